#include "LaplaceBeltramiBasis.h"

#include "CotangentLaplacian.h"

#include <Eigen/SparseCholesky>
#include <Spectra/SymEigsShiftSolver.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mobius
{
namespace
{
// Spectra's shift-and-invert operator for the symmetric standard problem
// A = D L D, D = M^(-1/2) (M is diagonal, so the generalized problem L phi = lambda M phi
// becomes a standard one with psi = M^(1/2) phi):
// (A - sigma I)^-1 x = M^(1/2) (L - sigma M)^-1 M^(1/2) x. One sparse Cholesky of
// L - sigma M serves every Lanczos step.
class ShiftInvertOperator
{
public:
  using Scalar = double;

  ShiftInvertOperator(const SparseMatrix& stiffness, const Vector& mass)
    : Stiffness(stiffness)
    , SqrtMass(mass.cwiseSqrt())
  {
  }

  Eigen::Index rows() const { return this->SqrtMass.size(); }
  Eigen::Index cols() const { return this->SqrtMass.size(); }

  void set_shift(double sigma)
  {
    SparseMatrix shifted = this->Stiffness;
    for (Eigen::Index i = 0; i < shifted.rows(); ++i)
    {
      shifted.coeffRef(i, i) -= sigma * this->SqrtMass[i] * this->SqrtMass[i];
    }
    this->Factorization.compute(shifted);
  }

  bool Ok() const { return this->Factorization.info() == Eigen::Success; }

  void perform_op(const double* in, double* out) const
  {
    const Eigen::Map<const Vector> x(in, this->rows());
    Eigen::Map<Vector> y(out, this->rows());
    y = this->SqrtMass.cwiseProduct(this->Factorization.solve(this->SqrtMass.cwiseProduct(x)));
  }

private:
  const SparseMatrix& Stiffness;
  Vector SqrtMass;
  Eigen::SimplicialLDLT<SparseMatrix> Factorization;
};
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

  // The spectrum of a unit-area surface starts at 0 and grows like 4 pi k; a shift just
  // below 0 makes L - sigma M positive definite and puts the wanted end of the spectrum
  // first.
  const double sigma = -1e-3;
  ShiftInvertOperator op(stiffness, basis.Mass);
  const Eigen::Index subspace = std::min<Eigen::Index>(n, std::max(2 * count + 1, count + 20));
  Spectra::SymEigsShiftSolver<ShiftInvertOperator> solver(op, count, subspace, sigma);
  if (!op.Ok())
  {
    error = "the Laplacian could not be factorized";
    return false;
  }
  solver.init();
  solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-10);
  if (solver.info() != Spectra::CompInfo::Successful)
  {
    error = "the Laplace-Beltrami eigensolver did not converge";
    return false;
  }
  const Vector values = solver.eigenvalues();
  const Eigen::MatrixXd vectors = solver.eigenvectors();
  std::vector<int> order(static_cast<size_t>(values.size()));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return values[a] < values[b]; });
  basis.Eigenvalues.resize(count);
  basis.Functions.resize(n, count);
  const Vector inverseSqrtMass = basis.Mass.cwiseSqrt().cwiseInverse();
  for (int j = 0; j < count; ++j)
  {
    basis.Eigenvalues[j] = values[order[j]];
    basis.Functions.col(j) = inverseSqrtMass.cwiseProduct(vectors.col(order[j]));
  }
  if (!basis.Functions.allFinite())
  {
    error = "the Laplace-Beltrami eigenfunctions are not finite";
    return false;
  }
  return true;
}
}
