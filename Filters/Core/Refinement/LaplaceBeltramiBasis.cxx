#include "LaplaceBeltramiBasis.h"

#include "CotangentLaplacian.h"

#include <Eigen/SparseCholesky>
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Spectra/SymEigsShiftSolver.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace mobius
{
namespace
{
// R with M = R^T R: the square root of a diagonal (lumped) mass, or the sparse Cholesky
// factor of a non-diagonal (consistent) one. The generalized problem L phi = lambda M phi is
// the standard symmetric one A psi = lambda psi with A = R^-T L R^-1 and psi = R phi.
struct MassRoot
{
  explicit MassRoot(const SparseMatrix& mass)
  {
    Diagonal = true;
    for (Eigen::Index col = 0; col < mass.outerSize() && Diagonal; ++col)
    {
      for (SparseMatrix::InnerIterator it(mass, col); it; ++it)
      {
        if (it.row() != col && it.value() != 0)
        {
          Diagonal = false;
          break;
        }
      }
    }
    if (Diagonal)
    {
      Sqrt = mass.diagonal().cwiseSqrt();
    }
    else
    {
      Factor.compute(mass); // P M P^T = L L^T, so R = L^T P
    }
  }
  bool Ok() const { return Diagonal || Factor.info() == Eigen::Success; }
  Vector Apply(const Vector& x) const // R x
  {
    if (Diagonal)
    {
      return Sqrt.cwiseProduct(x);
    }
    const Vector permuted = Factor.permutationP() * x;
    return Factor.matrixU() * permuted;
  }
  Vector ApplyTransposed(const Vector& x) const // R^T x
  {
    if (Diagonal)
    {
      return Sqrt.cwiseProduct(x);
    }
    const Vector lower = Factor.matrixL() * x;
    return Factor.permutationP().transpose() * lower;
  }
  Eigen::MatrixXd Solve(const Eigen::MatrixXd& v) const // R^-1 v
  {
    if (Diagonal)
    {
      return Sqrt.cwiseInverse().asDiagonal() * v;
    }
    const Eigen::MatrixXd solved = Factor.matrixU().solve(v);
    return Factor.permutationP().transpose() * solved;
  }
  bool Diagonal = true;
  Vector Sqrt;
  Eigen::SimplicialLLT<SparseMatrix> Factor;
};

// The shift-and-invert operator of the symmetric standard problem A = R^-T L R^-1:
// (A - sigma I)^-1 x = R (L - sigma M)^-1 R^T x. One sparse Cholesky factorization of
// L - sigma M, in double precision, serves every Lanczos step, whichever precision the
// Lanczos vectors are kept in.
struct ShiftedFactorization
{
  ShiftedFactorization(const SparseMatrix& stiffness, const SparseMatrix& mass,
    const MassRoot& root, double sigma)
    : Sigma(sigma)
    , Root(root)
  {
    this->Factorization.compute(SparseMatrix(stiffness - sigma * mass));
  }

  bool Ok() const { return this->Factorization.info() == Eigen::Success; }

  // Factorizes L - sigma M for another shift, reusing the fill-reducing ordering and the
  // symbolic analysis (the same sparsity pattern).
  void Shift(const SparseMatrix& stiffness, const SparseMatrix& mass, double sigma)
  {
    this->Sigma = sigma;
    this->Factorization.factorize(SparseMatrix(stiffness - sigma * mass));
  }

  double Sigma;
  const MassRoot& Root;
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

  Eigen::Index rows() const { return this->Shifted.Factorization.rows(); }
  Eigen::Index cols() const { return this->Shifted.Factorization.cols(); }

  // The factorization is made for one shift beforehand; Spectra announces the same one.
  void set_shift(Scalar) {}

  void perform_op(const Scalar* in, Scalar* out) const
  {
    const Eigen::Map<const ScalarVector> x(in, this->rows());
    Eigen::Map<ScalarVector> y(out, this->rows());
    const MassRoot& root = this->Shifted.Root;
    const Vector rightHandSide = root.ApplyTransposed(x.template cast<double>());
    y = root.Apply(this->Shifted.Factorization.solve(rightHandSide)).template cast<Scalar>();
  }

private:
  const ShiftedFactorization& Shifted;
};

// The `count` eigenvectors of A whose eigenvalues lie nearest the factorization's shift
// (columns of an n x count matrix, in no particular order) by shift-invert Lanczos with
// Lanczos vectors of type Scalar, and, when asked, their eigenvalues (Ritz values); false if
// Spectra does not converge.
template <typename Scalar>
bool ShiftInvertLanczos(const ShiftedFactorization& factorization, int count, double tolerance,
  Eigen::MatrixXd& vectors, Vector* values = nullptr)
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
  if (values)
  {
    *values = solver.eigenvalues().template cast<double>();
  }
  return vectors.allFinite();
}

// How many eigenvalues of L phi = lambda M phi lie below `value` (Sylvester's law of inertia:
// the negative pivots of the LDL^T factorization of L - value M); -1 if it fails. Refactorizes
// `factorization` (whose ordering it reuses) at that shift.
Eigen::Index EigenvaluesBelow(
  const SparseMatrix& stiffness, const SparseMatrix& mass, double value, ShiftedFactorization& factorization)
{
  factorization.Shift(stiffness, mass, value);
  if (!factorization.Ok())
  {
    return -1;
  }
  return (factorization.Factorization.vectorD().array() < 0).count();
}

// Rayleigh-Ritz in double precision on the span of the columns of `vectors`: orthonormalizes
// them through the eigen-decomposition of their Gram matrix and rotates them within their
// span into the eigenvectors of A restricted to it, with the Rayleigh quotients as
// eigenvalues; keeps the `count` of smallest value, ascending. Turns single-precision
// Lanczos vectors into a basis orthonormal to double precision. The columns may be nearly
// dependent (the windows of SlicedLanczos overlap, so an eigenvector can be found twice):
// the directions a duplicate adds are dropped. False if fewer than `count` independent
// directions remain.
bool RayleighRitz(const SparseMatrix& stiffness, const MassRoot& root, int count,
  Eigen::MatrixXd& vectors, Vector& values)
{
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(vectors.cols(), vectors.cols());
  gram.selfadjointView<Eigen::Lower>().rankUpdate(vectors.transpose());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> overlaps(gram);
  if (overlaps.info() != Eigen::Success)
  {
    return false;
  }
  // Ascending: the independent directions are the last ones.
  const double largest = overlaps.eigenvalues().maxCoeff();
  const Eigen::Index independent = (overlaps.eigenvalues().array() > 1e-6 * largest).count();
  if (independent < count)
  {
    return false;
  }
  const Eigen::MatrixXd orthonormalize = overlaps.eigenvectors().rightCols(independent) *
    overlaps.eigenvalues().tail(independent).cwiseSqrt().cwiseInverse().asDiagonal();
  const Eigen::MatrixXd scaled = root.Solve(vectors);
  const Eigen::MatrixXd stiffnessOnSpan = scaled.transpose() * (stiffness * scaled);
  Eigen::MatrixXd projected = orthonormalize.transpose() * stiffnessOnSpan * orthonormalize;
  projected = 0.5 * (projected + projected.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> restricted(projected);
  if (restricted.info() != Eigen::Success)
  {
    return false;
  }
  vectors = (vectors * (orthonormalize * restricted.eigenvectors().leftCols(count))).eval();
  values = restricted.eigenvalues().head(count);
  return vectors.allFinite();
}

// Eigenpairs per window of SlicedLanczos. Lanczos with full reorthogonalization costs about
// vertices x (2k)^2 for k eigenpairs, so k in windows of w costs about w / k of that, plus
// one factorization per window and the overlaps: 120 eigenpairs of a 5,000-vertex body take
// 0.17 s instead of 0.31 s (docs/DEVELOPMENT.md, "Refinement cost").
constexpr int kEigenpairsPerWindow = 40;

// The `count` eigenpairs of smallest eigenvalue by spectrum slicing: the lowest window at
// the factorization's shift, then windows at shifts placed above it, each finding the
// eigenvalues nearest its shift, until `count` are found below the top of the covered
// range; Rayleigh-Ritz on all of them together. A window whose lower end does not reach the
// range already covered is repeated nearer (the spectrum was denser than estimated there);
// the caller checks completeness. Refactorizes `factorization` at each shift. False if a
// window fails or the windows do not close up.
bool SlicedLanczos(const SparseMatrix& stiffness, const SparseMatrix& mass, const MassRoot& root,
  ShiftedFactorization& factorization, int count, Eigen::MatrixXd& vectors, Vector& values)
{
  const int windows = (count + kEigenpairsPerWindow - 1) / kEigenpairsPerWindow;
  const int perWindow = (count + windows - 1) / windows;
  std::vector<Eigen::MatrixXd> parts(1);
  Vector found;
  if (!ShiftInvertLanczos<float>(factorization, perWindow, 1e-5, parts[0], &found))
  {
    return false;
  }
  // Eigenvalues at the edge of a window may have unfound siblings of the same value: only
  // those clearly inside count as found, and the next window starts there.
  constexpr double edge = 1e-4;
  double covered = found.maxCoeff() * (1 - edge);
  Index below = (found.array() < covered).count();
  double density = below / covered; // eigenvalues per unit: Weyl's law makes it ~constant
  for (int attempt = 0; below < count && attempt < 2 * windows + 2; ++attempt)
  {
    const int wanted = std::min(perWindow, static_cast<int>(count - below));
    const int size = wanted + wanted / 4 + 4; // a margin on both sides of the shift
    const double sigma = covered + 0.5 * wanted / density;
    factorization.Shift(stiffness, mass, sigma);
    Eigen::MatrixXd part;
    if (!factorization.Ok() ||
      !ShiftInvertLanczos<float>(factorization, size, 1e-5, part, &found))
    {
      return false;
    }
    parts.push_back(std::move(part));
    // Every eigenvalue within `radius` of the shift is among those found.
    const double radius = (found.array() - sigma).abs().maxCoeff() * (1 - edge);
    density = size / (2 * radius);
    if (sigma - radius > covered)
    {
      continue; // a gap below this window: the next one, with the new density, is nearer
    }
    below += (found.array() >= covered && found.array() < sigma + radius).count();
    covered = sigma + radius;
  }
  if (below < count)
  {
    return false;
  }
  Eigen::Index columns = 0;
  for (const Eigen::MatrixXd& part : parts)
  {
    columns += part.cols();
  }
  vectors.resize(stiffness.rows(), columns);
  columns = 0;
  for (const Eigen::MatrixXd& part : parts)
  {
    vectors.middleCols(columns, part.cols()) = part;
    columns += part.cols();
  }
  return RayleighRitz(stiffness, root, count, vectors, values);
}
}

bool BuildUnitAreaMassMatrix(const Points& points, const Triangles& triangles,
  double consistentMassShare, SparseMatrix& mass, std::string& error)
{
  const Index n = points.rows();
  // Lumped by default. A consistent share uses the intrinsic Delaunay triangulation, the
  // one the stiffness is built on (the same function space): the lumped mass alone puts the
  // high eigenvalues of a coarse mesh too low (the 80th of CGAL's cow 5.4% below that of
  // its midpoint subdivision), the consistent one too high (5.8% above), a half-half blend
  // leaves them 0.3% apart. With the consistent mass on the original triangles instead, the
  // cow mapped onto its rotated copy came out as its mirror image (measured).
  if (!BuildMassMatrix(points, triangles, consistentMassShare > 0, consistentMassShare, mass))
  {
    error = "the mesh has non-manifold or inconsistently oriented edges";
    return false;
  }
  // Unit total area: eigenvalues and coefficients of two surfaces are then comparable.
  const Vector lumped = mass * Vector::Ones(n); // row sums: each vertex's area
  const double area = lumped.sum();
  if (!(area > 0) || !std::isfinite(area))
  {
    error = "the surface has no area";
    return false;
  }
  mass /= area;
  if (lumped.minCoeff() <= 0)
  {
    error = "a vertex has no area (it belongs only to degenerate triangles)";
    return false;
  }
  return true;
}

bool ComputeLaplaceBeltramiBasis(const Points& points, const Triangles& triangles, int count,
  LaplaceBeltramiBasis& basis, std::string& error, double consistentMassShare)
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
  if (!BuildUnitAreaMassMatrix(points, triangles, consistentMassShare, basis.Mass, error))
  {
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
  const MassRoot root(basis.Mass);
  if (!root.Ok())
  {
    error = "the mass matrix could not be factorized";
    return false;
  }
  ShiftedFactorization factorization(stiffness, basis.Mass, root, -10.0);
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
  auto complete = [&](const Vector& values) {
    const double below = values[count - 1] - 1e-4 * std::abs(values[count - 1]);
    return EigenvaluesBelow(stiffness, basis.Mass, below, factorization) ==
      (values.array() < below).count();
  };
  Eigen::MatrixXd vectors;
  // More than one window's worth: spectrum slicing; should it fail or miss an eigenvalue,
  // one window from the lowest end.
  const bool sliced = count > kEigenpairsPerWindow;
  bool solved = sliced &&
    SlicedLanczos(stiffness, basis.Mass, root, factorization, count, vectors, basis.Eigenvalues) &&
    complete(basis.Eigenvalues);
  if (!solved && sliced)
  {
    factorization.Shift(stiffness, basis.Mass, -10.0);
  }
  solved = solved ||
    (factorization.Ok() && ShiftInvertLanczos<float>(factorization, count, 1e-5, vectors) &&
      RayleighRitz(stiffness, root, count, vectors, basis.Eigenvalues) &&
      complete(basis.Eigenvalues));
  if (!solved)
  {
    // The solver as it was before single precision (4x slower on the man): double
    // precision, tol 1e-10 and the shift just below 0, whose rounding noise in the huge
    // inverted constant function let it find every member of a sphere's repeated eigenvalues,
    // where the shift of -10 in double precision missed one too (measured).
    // With the blended mass matrix it can miss one as well (a sphere's l = 2, measured):
    // then a few more eigenpairs than wanted are computed and the first `count` kept.
    const ShiftedFactorization nearZero(stiffness, basis.Mass, root, -1e-3);
    for (const int extra : { 0, 4 + count / 4 })
    {
      const int wanted = static_cast<int>(std::min<Index>(count + extra, n - 1));
      solved = nearZero.Ok() && ShiftInvertLanczos<double>(nearZero, wanted, 1e-10, vectors) &&
        RayleighRitz(stiffness, root, wanted, vectors, basis.Eigenvalues);
      if (solved && wanted > count)
      {
        vectors.conservativeResize(Eigen::NoChange, count);
        basis.Eigenvalues.conservativeResize(count);
      }
      if (!solved || complete(basis.Eigenvalues))
      {
        break;
      }
    }
  }
  if (!solved)
  {
    error = "the Laplace-Beltrami eigensolver did not converge";
    return false;
  }
  basis.Functions = root.Solve(vectors);
  if (!basis.Functions.allFinite())
  {
    error = "the Laplace-Beltrami eigenfunctions are not finite";
    return false;
  }
  return true;
}
}
