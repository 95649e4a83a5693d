// Cholesky factorization of a sparse symmetric positive definite matrix whose sparsity
// pattern stays fixed while its values change (the conformal flow's M_t + delta L):
// the ordering and symbolic analysis are computed once, each factorization reuses them.
//
// With CHOLMOD (SuiteSparse; MOBIUS_HAVE_CHOLMOD) the factorization is supernodal (dense
// BLAS kernels on blocks of columns) after a nested-dissection ordering by METIS, which
// suits surface meshes: their graphs have small separators (O(sqrt N)), so the factor's
// fill grows as N log N. Smaller matrices (below 50,000 rows) are factored by Eigen's
// simplicial LDL^T with AMD, which is as fast there, as is every matrix when CHOLMOD is not
// available (same interface, same results to rounding). On large meshes the supernodal
// factorization makes the whole map several times cheaper than the simplicial one (README,
// Performance). Debian's CHOLMOD calls the reference BLAS unless an optimized one
// (OpenBLAS) is installed as the libblas.so.3 alternative; the dense kernels are then a
// large part of the time.
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

  SparseCholesky();
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
  /// from 50,000 rows on (when built with it), Eigen's simplicial LDL^T below.
  static const char* Backend(Eigen::Index size);

private:
  struct Implementation;
  std::unique_ptr<Implementation> Impl;
};
}

#endif
