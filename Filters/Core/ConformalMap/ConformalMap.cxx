#include "ConformalMap.h"

#include "CotangentLaplacian.h"
#include "LinearSphericalMap.h"
#include "MapDistortion.h"
#include "MeshTopology.h"
#include "MobiusCentering.h"
#include "SparseCholesky.h"
#include "SphericalFlipRepair.h"
#include "SqueezedRegionRefinement.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <cmath>
#include <exception>
#include <sstream>
#include <utility>

namespace mobius
{
namespace
{
// Moves the area-weighted centroid (lumped mass = area/3 per corner gives exactly the
// surface centroid) to the origin and scales the surface to unit area. Returns false if the
// surface has no area or non-finite coordinates.
bool NormalizeShape(Points& x, const Triangles& triangles, Vector& mass)
{
  mass = LumpedMass(x, triangles);
  const double area = mass.sum();
  if (!(area > 0.0) || !std::isfinite(area))
  {
    return false;
  }
  const Eigen::RowVector3d centroid = (mass.transpose() * x) / area;
  x.rowwise() -= centroid;
  x *= 1.0 / std::sqrt(area);
  mass /= area;
  return x.allFinite();
}

// L x computed edge by edge as sum_j w_ij (x_i - x_j): differences of nearby points are
// exact in floating point, so tiny regions keep their relative precision (the plain product
// L_ii x_i - sum_j w_ij x_j cancels large terms and loses it).
Eigen::MatrixXd ApplyStiffnessToDifferences(const SparseMatrix& stiffness, const Points& x)
{
  Eigen::MatrixXd product = Eigen::MatrixXd::Zero(x.rows(), 3);
  for (Index col = 0; col < stiffness.outerSize(); ++col)
  {
    for (SparseMatrix::InnerIterator it(stiffness, col); it; ++it)
    {
      if (it.row() != col)
      {
        // Column col of L holds -w_{row,col}: the contribution of x_row to row col.
        product.row(col) -= it.value() * (x.row(col) - x.row(it.row()));
      }
    }
  }
  return product;
}

// Index of each diagonal entry in the value array of a compressed column-major matrix.
std::vector<Index> DiagonalPositions(const SparseMatrix& matrix)
{
  std::vector<Index> positions(static_cast<size_t>(matrix.cols()), -1);
  for (Index col = 0; col < matrix.outerSize(); ++col)
  {
    for (Index k = matrix.outerIndexPtr()[col]; k < matrix.outerIndexPtr()[col + 1]; ++k)
    {
      if (matrix.innerIndexPtr()[k] == col)
      {
        positions[col] = k;
      }
    }
  }
  return positions;
}

// Solves system * d = rhs (three columns) by conjugate gradients preconditioned with the
// factorization `solver` holds of a nearby matrix (an earlier step's M_s + delta L): near
// convergence the masses change by a fraction of a percent per step, so the preconditioned
// matrix is close to the identity and a few triangular solves replace a factorization.
// False if the relative residual of some column is still above `tolerance` after
// `maximumIterations` (the caller then factorizes).
bool SolveWithNearbyFactorization(const SparseMatrix& system, const SparseCholesky& solver,
  const Eigen::MatrixXd& rhs, double tolerance, int maximumIterations, Eigen::MatrixXd& d,
  int& iterations)
{
  d = solver.Solve(rhs);
  Eigen::MatrixXd r = rhs - system * d;
  const Eigen::RowVectorXd limit = tolerance * rhs.colwise().norm();
  iterations = 0;
  auto converged = [&] {
    return ((r.colwise().norm() - limit).array() <= 0.0).all();
  };
  if (converged())
  {
    return true;
  }
  Eigen::MatrixXd z = solver.Solve(r);
  Eigen::MatrixXd direction = z;
  Eigen::RowVectorXd rz = (r.array() * z.array()).colwise().sum();
  for (iterations = 1; iterations <= maximumIterations; ++iterations)
  {
    const Eigen::MatrixXd product = system * direction;
    const Eigen::RowVectorXd curvature = (direction.array() * product.array()).colwise().sum();
    for (Index c = 0; c < rhs.cols(); ++c)
    {
      if (curvature[c] > 0.0 && rz[c] > 0.0)
      {
        const double alpha = rz[c] / curvature[c];
        d.col(c) += alpha * direction.col(c);
        r.col(c) -= alpha * product.col(c);
      }
    }
    if (!d.allFinite())
    {
      return false;
    }
    if (converged())
    {
      return true;
    }
    z = solver.Solve(r);
    const Eigen::RowVectorXd rzNext = (r.array() * z.array()).colwise().sum();
    for (Index c = 0; c < rhs.cols(); ++c)
    {
      const double beta = rz[c] > 0.0 ? rzNext[c] / rz[c] : 0.0;
      direction.col(c) = z.col(c) + beta * direction.col(c);
    }
    rz = rzNext;
  }
  return false;
}

// Progress after `steps` flow steps. The number of steps is not known in advance (3-13 on
// every development mesh, at most the limit), so the fraction approaches 0.95 geometrically
// (9 steps: 0.77) instead of counting against the limit (9 of 100 would leave the bar
// at 9% for the whole map); the steps after the flow take the rest.
double FlowProgress(int steps, int limit)
{
  const double expected = 1.0 - std::pow(0.85, steps);
  return steps >= limit ? 0.95 : 0.05 + 0.9 * expected;
}

// The rotation R that best maps the points `from` onto `to` (weighted least squares of
// R from_i - to_i; Kabsch), a proper rotation.
Eigen::Matrix3d BestRotation(const Points& from, const Points& to, const Vector& weights)
{
  const Eigen::Matrix3d covariance = from.transpose() * weights.asDiagonal() * to;
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d sign = Eigen::Matrix3d::Identity();
  sign(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  return svd.matrixV() * sign * svd.matrixU().transpose();
}

ConformalMapResult Fail(ConformalMapResult& result, const std::string& message)
{
  result.Success = false;
  result.Message = message;
  result.SpherePoints.resize(0, 3);
  return result;
}

// The parameters and the surface the flow can start from, or why not.
std::string CheckFlowInput(
  const Points& points, const Triangles& triangles, const ConformalMapParameters& p)
{
  if (!(p.TimeStep > 0.0) || !std::isfinite(p.TimeStep))
  {
    return "TimeStep must be a positive number";
  }
  if (p.MaximumNumberOfIterations < 1)
  {
    return "MaximumNumberOfIterations must be at least 1";
  }
  if (!(p.ConvergenceTolerance >= 0.0))
  {
    return "ConvergenceTolerance must not be negative";
  }
  const MeshTopologyReport topology = AnalyzeMeshTopology(points, triangles);
  if (!topology.IsTopologicalSphere())
  {
    return "the input is not a closed, connected, consistently oriented genus-0 surface: " +
      DescribeTopologyProblems(topology);
  }
  // Collinear triangles are fine on the intrinsic Delaunay triangulation (their long edge
  // gets flipped away); a zero-length edge is caught when the weights are built.
  if (!p.IntrinsicDelaunay && topology.ZeroAreaTriangles > 0)
  {
    return "zero-area triangles (" + std::to_string(topology.ZeroAreaTriangles) +
      ", three points on a line), whose cotangent weights are not defined without the "
      "intrinsic Delaunay triangulation";
  }
  return {};
}

// The flow's matrices: the stiffness L, the system M_t + delta L (L's pattern, all diagonal
// entries stored, so that the fill-reducing ordering and the symbolic factorization are
// computed once) and the solver holding its analysis and its latest factorization.
struct FlowSystem
{
  SparseMatrix Stiffness;
  SparseMatrix System;
  std::vector<Index> Diagonal;
  Vector ScaledStiffness; // delta L's values
  SparseCholesky Solver;
  // The solver holds a factorization of an earlier flow step's matrix (not the linear
  // start's L + eps M, which is too far from M_t + delta L to precondition it well).
  bool HaveFlowFactorization = false;
};

std::string BuildFlowSystem(const Points& x, const Triangles& triangles,
  const ConformalMapParameters& p, FlowSystem& flow, ConformalMapResult& result)
{
  CotangentStiffnessInfo stiffnessInfo;
  if (!BuildCotangentStiffness(x, triangles, p.IntrinsicDelaunay, flow.Stiffness, stiffnessInfo))
  {
    return "cannot build the Laplacian: " + stiffnessInfo.Error;
  }
  result.IntrinsicDelaunayUsed = p.IntrinsicDelaunay;
  result.IntrinsicFlips = stiffnessInfo.IntrinsicFlips;
  flow.System = p.TimeStep * flow.Stiffness;
  flow.Diagonal = DiagonalPositions(flow.System);
  flow.ScaledStiffness = Eigen::Map<const Vector>(flow.System.valuePtr(), flow.System.nonZeros());
  if (!flow.Solver.Analyze(flow.System))
  {
    return "the sparse Cholesky analysis failed";
  }
  return {};
}

// Starts the flow from a conformal map instead of the surface: the flow then only polishes
// it. If the linear map cannot be computed, x and mass stay the surface's and the flow
// starts from it as it always could.
void StartFromLinearMap(Points& x, Vector& mass, const Triangles& triangles,
  const Vector& originalAreas, FlowSystem& flow, ConformalMapResult& result)
{
  const LinearSphericalMapResult start =
    ComputeLinearSphericalMap(x, triangles, flow.Stiffness, mass, flow.Solver);
  result.PoleTriangle = start.PoleTriangle;
  result.Factorizations += start.Factorized ? 1 : 0;
  Points startPoints = start.SpherePoints;
  MobiusCenteringResult centering;
  Vector startMass;
  if (start.Success &&
    CenterSphericalMap(startPoints, triangles, originalAreas, MobiusCenteringParameters(),
      centering) &&
    NormalizeShape(startPoints, triangles, startMass))
  {
    // The linear map is intrinsic (its pole triangle and frame are chosen from the
    // surface's shape), so a turned copy of the surface would get the same map. Turn it
    // to the surface's own orientation instead: the flow commutes with rotations, so the
    // map then turns with the input as the flow from the surface does (SO3Register of a
    // turned copy finds the turn), and ends close to that flow's orientation.
    startPoints = startPoints * BestRotation(startPoints, x, startMass).transpose();
    x.swap(startPoints);
    mass.swap(startMass);
    result.LinearStart = true;
  }
  else
  {
    result.LinearStartError = start.Success ? "its Möbius centering failed" : start.Error;
  }
}

// The displacement of one flow step from x, (M_t + delta L) d = -delta L x_t, solved for d
// rather than for x_{t+1} itself: the same step, but the solver's rounding error is then
// relative to the (small, near convergence) displacement instead of the sphere's radius,
// which matters for limbs the map shrinks to 1e-10. One solve for the three coordinates.
std::string SolveFlowStep(const Points& x, const Vector& mass, const ConformalMapParameters& p,
  int iteration, FlowSystem& flow, Eigen::MatrixXd& displacement, ConformalMapResult& result)
{
  Eigen::Map<Vector>(flow.System.valuePtr(), flow.System.nonZeros()) = flow.ScaledStiffness;
  for (Index i = 0; i < x.rows(); ++i)
  {
    flow.System.valuePtr()[flow.Diagonal[i]] += mass[i];
  }
  const Eigen::MatrixXd rhs = -p.TimeStep * ApplyStiffnessToDifferences(flow.Stiffness, x);
  // Measured: 3-4 iterations to 1e-10 on every development mesh once the flow
  // polishes; a step that needs more than 10 is far from the factorized one.
  int cgIterations = 0;
  const bool reused = p.ReuseFactorization && flow.HaveFlowFactorization &&
    x.rows() >= p.ReuseFactorizationMinimumSize &&
    SolveWithNearbyFactorization(
      flow.System, flow.Solver, rhs, 1e-10, 10, displacement, cgIterations);
  if (reused)
  {
    result.ConjugateGradientIterations += cgIterations;
    return {};
  }
  if (!flow.Solver.Factorize(flow.System))
  {
    std::ostringstream s;
    s << "the sparse Cholesky factorization failed at flow step " << iteration + 1;
    return s.str();
  }
  ++result.Factorizations;
  flow.HaveFlowFactorization = true;
  displacement = flow.Solver.Solve(rhs);
  return {};
}

// Projects the stepped points onto the unit sphere and undoes the step's drift by the
// canonical Möbius centering (paper §7.1): without it the flow slides toward a point
// (hand_cgal: 1227 flipped triangles after 100 steps) and never meets the convergence test.
std::string CenterBetweenFlowSteps(
  Points& next, Vector& nextMass, const Triangles& triangles, const Vector& originalAreas)
{
  for (Index i = 0; i < next.rows(); ++i)
  {
    const double r = next.row(i).norm();
    if (!(r > 0.0))
    {
      return "a vertex reached the center during the flow; cannot center";
    }
    next.row(i) /= r;
  }
  MobiusCenteringResult centering;
  if (!CenterSphericalMap(next, triangles, originalAreas, MobiusCenteringParameters(), centering))
  {
    return "Möbius centering between flow steps failed: " + centering.Error;
  }
  if (!NormalizeShape(next, triangles, nextMass))
  {
    return "Möbius centering produced degenerate positions";
  }
  return {};
}

// The positions after one flow step from x, normalized, centered and passed through the
// caller's step between iterations as the parameters ask.
std::string StepFlow(const Points& x, const Vector& mass, const Triangles& triangles,
  const Vector& originalAreas, const ConformalMapParameters& p, int iteration, FlowSystem& flow,
  Eigen::MatrixXd& displacement, Points& next, Vector& nextMass, ConformalMapResult& result)
{
  std::string error = SolveFlowStep(x, mass, p, iteration, flow, displacement, result);
  if (!error.empty())
  {
    return error;
  }
  next = x + displacement;
  if (!NormalizeShape(next, triangles, nextMass))
  {
    std::ostringstream s;
    s << "the flow produced non-finite or degenerate positions at step " << iteration + 1;
    return s.str();
  }
  if (p.MobiusCentering &&
    !(error = CenterBetweenFlowSteps(next, nextMass, triangles, originalAreas)).empty())
  {
    return error;
  }
  if (p.BetweenSteps)
  {
    if (!p.BetweenSteps(next, iteration + 1))
    {
      return "the step between flow iterations (BetweenSteps) failed";
    }
    if (!NormalizeShape(next, triangles, nextMass))
    {
      return "the step between flow iterations produced degenerate positions";
    }
  }
  return {};
}

// Runs the flow from x until its relative change is within the tolerance or the iteration
// limit; x and mass end as the last step's positions and masses.
std::string RunFlow(Points& x, Vector& mass, const Triangles& triangles,
  const Vector& originalAreas, const ConformalMapParameters& p, FlowSystem& flow,
  ConformalMapResult& result)
{
  Points next(x.rows(), 3);
  Vector nextMass;
  Eigen::MatrixXd displacement;
  for (int iteration = 0; iteration < p.MaximumNumberOfIterations; ++iteration)
  {
    const std::string error = StepFlow(x, mass, triangles, originalAreas, p, iteration, flow,
      displacement, next, nextMass, result);
    if (!error.empty())
    {
      return error;
    }
    // Measured after the step between iterations, so that a drift the centering undoes
    // does not count as change.
    const double change = std::sqrt((nextMass.transpose() *
      (next - x).rowwise().squaredNorm()).value());
    const double radius = std::sqrt((nextMass.transpose() * next.rowwise().squaredNorm()).value());
    result.RelativeChange = change / radius;
    x.swap(next);
    mass.swap(nextMass);
    result.Iterations = iteration + 1;

    if (p.Progress && !p.Progress(FlowProgress(result.Iterations, p.MaximumNumberOfIterations)))
    {
      return "aborted";
    }
    if (result.RelativeChange <= p.ConvergenceTolerance)
    {
      result.Converged = true;
      break;
    }
  }
  return {};
}

// The flow's last positions (centered at their area-weighted centroid) projected radially
// onto the sphere, facing outward, with squeezed regions refined and flips repaired.
std::string FinishSphericalMap(Points& x, const Points& points, const Triangles& triangles,
  const ConformalMapParameters& p, bool inputFacesInward, ConformalMapResult& result)
{
  for (Index i = 0; i < x.rows(); ++i)
  {
    const double r = x.row(i).norm();
    if (!(r > 0.0) || !std::isfinite(r))
    {
      return "a vertex reached the center of the sphere; cannot project it";
    }
    x.row(i) /= r;
  }
  // Face outward: if the triangles enclose negative volume (the flow from a surface whose
  // triangles face inward), mirror the map.
  if (EnclosedVolume(x, triangles) < 0.0)
  {
    x.col(0) *= -1.0;
  }
  result.Reflected = inputFacesInward;
  if (p.SqueezedRegionThreshold > 0.0)
  {
    // On failure the affected regions keep the flow's positions: still a valid map.
    result.Refinement = RefineSqueezedRegions(x, triangles, points, p.SqueezedRegionThreshold);
  }
  if (p.FlipRepairPasses > 0)
  {
    result.FlipRepair = RepairFlippedTriangles(x, triangles, p.FlipRepairPasses);
  }
  if (!x.allFinite())
  {
    return "the map has non-finite coordinates";
  }
  return {};
}

std::string DescribeFlow(const ConformalMapResult& result)
{
  std::ostringstream s;
  s << (result.Converged ? "converged" : "stopped at the iteration limit") << " after "
    << result.Iterations << " steps (relative change " << result.RelativeChange << "); "
    << result.Distortion.FlippedTriangles << " flipped triangles, mean quasi-conformal distortion "
    << result.Distortion.MeanQuasiConformal;
  return s.str();
}

ConformalMapResult MapToSphere(
  const Points& points, const Triangles& triangles, const ConformalMapParameters& p)
{
  ConformalMapResult result;
  std::string error = CheckFlowInput(points, triangles, p);
  if (!error.empty())
  {
    return Fail(result, error);
  }
  Points x = points;
  Vector mass;
  if (!NormalizeShape(x, triangles, mass))
  {
    return Fail(result, "the input surface has no area");
  }
  const Vector originalAreas = TriangleAreas(x, triangles); // centering weights
  // The flow from the surface keeps the input's orientation, the linear start's map faces
  // outward whatever the input's does: remember which way the input faced.
  const bool inputFacesInward = EnclosedVolume(x, triangles) < 0.0;
  FlowSystem flow;
  if (!(error = BuildFlowSystem(x, triangles, p, flow, result)).empty())
  {
    return Fail(result, error);
  }
  if (p.LinearStart && p.MobiusCentering)
  {
    StartFromLinearMap(x, mass, triangles, originalAreas, flow, result);
  }
  if (p.Progress && !p.Progress(0.05))
  {
    return Fail(result, "aborted");
  }
  if (!(error = RunFlow(x, mass, triangles, originalAreas, p, flow, result)).empty() ||
    !(error = FinishSphericalMap(x, points, triangles, p, inputFacesInward, result)).empty())
  {
    return Fail(result, error);
  }
  result.Distortion = MeasureMapDistortion(points, x, triangles);
  result.SpherePoints.swap(x);
  result.Success = true;
  result.Message = DescribeFlow(result);
  return result;
}
}

ConformalMapResult ComputeSphericalConformalMap(
  const Points& points, const Triangles& triangles, const ConformalMapParameters& parameters)
{
  try
  {
    ConformalMapResult result = MapToSphere(points, triangles, parameters);
    if (result.Success && !parameters.IntrinsicDelaunay && parameters.IntrinsicDelaunayWhenFolded &&
      result.Distortion.FlippedTriangles > 0)
    {
      ConformalMapParameters intrinsic = parameters;
      intrinsic.IntrinsicDelaunay = true;
      if (parameters.Progress)
      {
        // The bar stays where the first map left it (the second may still be aborted).
        intrinsic.Progress = [&parameters](double) { return parameters.Progress(0.95); };
      }
      ConformalMapResult again = MapToSphere(points, triangles, intrinsic);
      if (again.Success &&
        again.Distortion.FlippedTriangles <= result.Distortion.FlippedTriangles)
      {
        result = std::move(again);
      }
    }
    return result;
  }
  catch (const std::bad_alloc&)
  {
    ConformalMapResult result;
    return Fail(result, "out of memory");
  }
  catch (const std::exception& e)
  {
    ConformalMapResult result;
    return Fail(result, std::string("unexpected error: ") + e.what());
  }
}
}
