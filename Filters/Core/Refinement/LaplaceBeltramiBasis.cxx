#include "LaplaceBeltramiBasis.h"

#include "CotangentLaplacian.h"

#include <Eigen/SparseCholesky>
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Spectra/SymEigsShiftSolver.h>

#include <algorithm>
#include <cmath>

namespace mobius
{
namespace
{
// The shift-and-invert operator of the symmetric standard problem A = D L D,
// D = M^(-1/2) (M is diagonal, so the generalized problem L phi = lambda M phi becomes a
// standard one with psi = M^(1/2) phi): (A - sigma I)^-1 x = M^(1/2) (L - sigma M)^-1 M^(1/2) x.
// One sparse Cholesky factorization of L - sigma M, in double precision, serves every
// Lanczos step, whichever precision the Lanczos vectors are kept in.
struct ShiftedFactorization
{
  ShiftedFactorization(const SparseMatrix& stiffness, const Vector& mass, double sigma)
    : Sigma(sigma)
    , SqrtMass(mass.cwiseSqrt())
  {
    SparseMatrix shifted = stiffness;
    for (Eigen::Index i = 0; i < shifted.rows(); ++i)
    {
      shifted.coeffRef(i, i) -= sigma * mass[i];
    }
    this->Factorization.compute(shifted);
  }

  bool Ok() const { return this->Factorization.info() == Eigen::Success; }

  // Factorizes L - sigma M for another shift, reusing the fill-reducing ordering and the
  // symbolic analysis (the same sparsity pattern).
  void Shift(const SparseMatrix& stiffness, const Vector& mass, double sigma)
  {
    SparseMatrix shifted = stiffness;
    for (Eigen::Index i = 0; i < shifted.rows(); ++i)
    {
      shifted.coeffRef(i, i) -= sigma * mass[i];
    }
    this->Sigma = sigma;
    this->Factorization.factorize(shifted);
  }

  double Sigma;
  Vector SqrtMass;
  Eigen::SimplicialLDLT<SparseMatrix> Factorization;
};

// Spectra's operator on vectors of `ScalarType` (float or double).
template <typename ScalarType>
class ShiftInvertOperator
{
public:
  using Scalar = ScalarType;
  using ScalarVector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;

  explicit ShiftInvertOperator(const ShiftedFactorization& factorization)
    : Shifted(factorization)
  {
  }

  Eigen::Index rows() const { return this->Shifted.SqrtMass.size(); }
  Eigen::Index cols() const { return this->Shifted.SqrtMass.size(); }

  // The factorization is made for one shift beforehand; Spectra announces the same one.
  void set_shift(Scalar) {}

  void perform_op(const Scalar* in, Scalar* out) const
  {
    const Eigen::Map<const ScalarVector> x(in, this->rows());
    Eigen::Map<ScalarVector> y(out, this->rows());
    const Vector& sqrtMass = this->Shifted.SqrtMass;
    const Vector rightHandSide = sqrtMass.cwiseProduct(x.template cast<double>());
    y = sqrtMass.cwiseProduct(this->Shifted.Factorization.solve(rightHandSide)).template cast<Scalar>();
  }

private:
  const ShiftedFactorization& Shifted;
};

// The `count` eigenvectors of smallest eigenvalue of A (columns of an n x count matrix, in
// no particular order) by shift-invert Lanczos with Lanczos vectors of type Scalar; false if
// Spectra does not converge.
template <typename Scalar>
bool ShiftInvertLanczos(const ShiftedFactorization& factorization, int count, double tolerance,
  Eigen::MatrixXd& vectors)
{
  ShiftInvertOperator<Scalar> op(factorization);
  const Eigen::Index n = op.rows();
  const Eigen::Index subspace = std::min<Eigen::Index>(n, std::max(2 * count + 1, count + 20));
  Spectra::SymEigsShiftSolver<ShiftInvertOperator<Scalar>> solver(
    op, count, subspace, static_cast<Scalar>(factorization.Sigma));
  solver.init();
  solver.compute(Spectra::SortRule::LargestMagn, 1000, static_cast<Scalar>(tolerance));
  if (solver.info() != Spectra::CompInfo::Successful)
  {
    return false;
  }
  vectors = solver.eigenvectors().template cast<double>();
  return vectors.allFinite();
}

// How many eigenvalues of L phi = lambda M phi lie below `value` (Sylvester's law of inertia:
// the negative pivots of the LDL^T factorization of L - value M); -1 if it fails. Refactorizes
// `factorization` (whose ordering it reuses) at that shift.
Eigen::Index EigenvaluesBelow(
  const SparseMatrix& stiffness, const Vector& mass, double value, ShiftedFactorization& factorization)
{
  factorization.Shift(stiffness, mass, value);
  if (!factorization.Ok())
  {
    return -1;
  }
  return (factorization.Factorization.vectorD().array() < 0).count();
}

// Rayleigh-Ritz in double precision on the span of `vectors` (n x k, nearly orthonormal):
// orthonormalizes them (Cholesky QR) and rotates them within their span into the
// eigenvectors of A restricted to it, with the Rayleigh quotients as eigenvalues, ascending.
// Turns the single-precision Lanczos vectors into a basis orthonormal to double precision.
bool RayleighRitz(const SparseMatrix& stiffness, const Vector& inverseSqrtMass,
  Eigen::MatrixXd& vectors, Vector& values)
{
  const Eigen::LLT<Eigen::MatrixXd> gram(vectors.transpose() * vectors);
  if (gram.info() != Eigen::Success)
  {
    return false;
  }
  vectors = gram.matrixU().solve<Eigen::OnTheRight>(vectors); // V R^-1: orthonormal
  const Eigen::MatrixXd scaled = inverseSqrtMass.asDiagonal() * vectors;
  Eigen::MatrixXd projected = scaled.transpose() * (stiffness * scaled);
  projected = 0.5 * (projected + projected.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> restricted(projected);
  if (restricted.info() != Eigen::Success)
  {
    return false;
  }
  vectors = vectors * restricted.eigenvectors();
  values = restricted.eigenvalues();
  return vectors.allFinite();
}
}

bool ComputeLaplaceBeltramiBasis(const Points& points, const Triangles& triangles, int count,
  LaplaceBeltramiBasis& basis, std::string& error)
{
  const Index n = points.rows();
  if (count < 1 || count >= n)
  {
    error = "the basis size must be at least 1 and below the number of vertices (" +
      std::to_string(n) + ")";
    return false;
  }
  SparseMatrix stiffness;
  CotangentStiffnessInfo info;
  if (!BuildCotangentStiffness(points, triangles, true, stiffness, info))
  {
    error = info.Error;
    return false;
  }
  // Unit total area: eigenvalues and coefficients of two surfaces are then comparable.
  basis.Mass = LumpedMass(points, triangles);
  const double area = basis.Mass.sum();
  if (!(area > 0) || !std::isfinite(area))
  {
    error = "the surface has no area";
    return false;
  }
  basis.Mass /= area;
  if (basis.Mass.minCoeff() <= 0)
  {
    error = "a vertex has no area (it belongs only to degenerate triangles)";
    return false;
  }

  // The spectrum of a unit-area surface starts at 0 and grows like 4 pi k (the 80th
  // eigenvalue: 931 on CGAL's man); a shift below 0 makes L - sigma M positive definite and
  // puts the wanted end of the spectrum first. -10 rather than just below 0: the inverted
  // constant function then weighs (lambda_80 - sigma) / -sigma ~ 100 times the 80th, not
  // 10^6 times, which single-precision Lanczos vectors need (measured on the man: their span
  // agrees with the double-precision one to 1 - 1e-6 with sigma = -10, to 1 - 4e-5 with
  // sigma = -1e-3); the convergence of the wanted end, set by the gaps between
  // 1 / (lambda_j - sigma), hardly changes.
  ShiftedFactorization factorization(stiffness, basis.Mass, -10.0);
  if (!factorization.Ok())
  {
    error = "the Laplacian could not be factorized";
    return false;
  }
  // Lanczos with single-precision vectors: its full reorthogonalization (products with up
  // to 2k + 1 Lanczos vectors, repeated until orthogonal to working precision, at each of
  // ~200 steps) is memory-bound and was ~90% of the eigenbasis time; in single precision it
  // moves half the bytes and needs fewer repetitions. Measured on the man (17,495 vertices,
  // k = 80, CPU seconds): double, tol 1e-10: 3.6 (244 solves); double, tol 1e-6: 2.3;
  // single, tol 1e-5: 0.85 (203 solves). Spectra's tolerance is relative to each Ritz
  // value; 1e-5 is near what single precision can certify. The solves and the final
  // Rayleigh-Ritz step stay in double. Should single precision not converge, double does.
  // Single-precision Lanczos can also miss a member of an exactly repeated eigenvalue (a
  // sphere's, measured) and find the next eigenvalue up instead: then more eigenvalues lie
  // below the largest one found than were found, which one more factorization counts.
  const Vector inverseSqrtMass = basis.Mass.cwiseSqrt().cwiseInverse();
  auto complete = [&](const Vector& values) {
    const double below = values[count - 1] - 1e-4 * std::abs(values[count - 1]);
    return EigenvaluesBelow(stiffness, basis.Mass, below, factorization) ==
      (values.array() < below).count();
  };
  Eigen::MatrixXd vectors;
  bool solved = ShiftInvertLanczos<float>(factorization, count, 1e-5, vectors) &&
    RayleighRitz(stiffness, inverseSqrtMass, vectors, basis.Eigenvalues) &&
    complete(basis.Eigenvalues);
  if (!solved)
  {
    // The solver as it was before single precision (4x slower on the man): double
    // precision, tol 1e-10 and the shift just below 0, whose rounding noise in the huge
    // inverted constant function let it find every member of a sphere's repeated eigenvalues,
    // where the shift of -10 in double precision missed one too (measured).
    const ShiftedFactorization nearZero(stiffness, basis.Mass, -1e-3);
    solved = nearZero.Ok() && ShiftInvertLanczos<double>(nearZero, count, 1e-10, vectors) &&
      RayleighRitz(stiffness, inverseSqrtMass, vectors, basis.Eigenvalues);
  }
  if (!solved)
  {
    error = "the Laplace-Beltrami eigensolver did not converge";
    return false;
  }
  basis.Functions = inverseSqrtMass.asDiagonal() * vectors;
  if (!basis.Functions.allFinite())
  {
    error = "the Laplace-Beltrami eigenfunctions are not finite";
    return false;
  }
  return true;
}
}
