// Cholesky factorization of a sparse symmetric positive definite matrix whose sparsity
// pattern stays fixed while its values change (the conformal flow's M_t + delta L):
// the ordering and symbolic analysis are computed once, each factorization reuses them.
//
// With CHOLMOD (SuiteSparse; MOBIUS_HAVE_CHOLMOD) the factorization is supernodal (dense
// BLAS kernels on blocks of columns) after a nested-dissection ordering by METIS, which
// suits surface meshes: their graphs have small separators (O(sqrt N)), so the factor's
// fill grows as N log N. Smaller matrices (below 50,000 rows) are factored by Eigen's
// simplicial LDL^T with AMD, which is as fast there, as is every matrix when CHOLMOD is not
// available (same interface, same results to rounding). A factorization made for many
// solves (SparseCholesky::Use::ManySolves) is CHOLMOD's simplicial LDL^T with AMD there
// instead: its solve takes up to four right-hand sides in one pass over the factor, where
// Eigen's makes a pass per column (20,000-vertex Laplacian: three columns 2.2 times, one
// column 1.5 times as fast), and its analysis and factorization take about a third longer.
// On large meshes the supernodal factorization makes the whole map several times cheaper
// than the simplicial one (README, Performance). Debian's CHOLMOD calls the reference BLAS
// unless an optimized one (OpenBLAS) is installed as the libblas.so.3 alternative; the
// dense kernels are then a large part of the time.
#ifndef mobius_SparseCholesky_h
#define mobius_SparseCholesky_h

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <string>

namespace mobius
{
class SparseCholesky
{
public:
  using Matrix = Eigen::SparseMatrix<double>; // column-major, int indices

  /// What the factorization is for: a few solves each (the conformal flow factorizes a new
  /// matrix at every step) or many (the polish solves for three columns at each of its
  /// iterations with one factorization).
  enum class Use
  {
    FewSolves,
    ManySolves
  };

  explicit SparseCholesky(Use use = Use::FewSolves);
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  /// Ordering and symbolic factorization of a symmetric matrix (both triangles stored, or
  /// at least the lower one: only the lower triangle is read). False on failure.
  bool Analyze(const Matrix& matrix);
  /// Numeric factorization of a matrix with the analyzed pattern. False if it is not
  /// positive definite (or on failure).
  bool Factorize(const Matrix& matrix);
  /// Solution of A X = B for the last factorization, one column per right-hand side.
  Eigen::MatrixXd Solve(const Eigen::MatrixXd& rightHandSides) const;

  /// The factorization this build uses for a matrix of `size` rows: CHOLMOD supernodal
  /// from 50,000 rows on (when built with it), below that Eigen's simplicial LDL^T, or
  /// CHOLMOD's for many solves.
  static const char* Backend(Eigen::Index size, Use use = Use::FewSolves);

private:
  struct Implementation;
  std::unique_ptr<Implementation> Impl;
};
}

#endif
