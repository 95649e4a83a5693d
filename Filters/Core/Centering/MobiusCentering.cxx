#include "MobiusCentering.h"

#include <Eigen/Dense>

#include <cmath>
#include <sstream>

namespace mobius
{
namespace
{
// Per-step weights and centroid directions: C(t) normalized, A(t) normalized to sum 1.
struct WeightedDirections
{
  Points Directions;
  Vector Weights;
};

WeightedDirections ComputeWeightedDirections(
  const Points& points, const Triangles& triangles, const Vector& normalizedWeights)
{
  WeightedDirections wd;
  wd.Weights = normalizedWeights;
  if (triangles.rows() == 0)
  {
    wd.Directions = points;
    return wd;
  }
  wd.Directions.resize(triangles.rows(), 3);
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    const Eigen::Vector3d centroid = points.row(triangles(t, 0)) + points.row(triangles(t, 1)) +
      points.row(triangles(t, 2));
    const double norm = centroid.norm();
    // A centroid at the origin only happens for a triangle spanning a great circle; it then
    // has no direction and contributes nothing.
    wd.Directions.row(t) = norm > 0 ? Eigen::Vector3d(centroid / norm) : Eigen::Vector3d::Zero();
  }
  return wd;
}

Eigen::Vector3d CenterOfMass(const WeightedDirections& wd)
{
  return (wd.Directions.transpose() * wd.Weights);
}

Eigen::Matrix3d CenteringJacobian(const WeightedDirections& wd)
{
  Eigen::Matrix3d outer = wd.Directions.transpose() * wd.Weights.asDiagonal() * wd.Directions;
  return 2.0 * (wd.Weights.sum() * Eigen::Matrix3d::Identity() - outer);
}

std::string CheckInput(const Points& points, const Triangles& triangles, const Vector& areas)
{
  std::ostringstream error;
  if (points.rows() == 0)
  {
    return "the spherical map has no points";
  }
  for (Eigen::Index i = 0; i < points.rows(); ++i)
  {
    if (!points.row(i).allFinite())
    {
      error << "point " << i << " has a NaN or infinite coordinate";
      return error.str();
    }
    const double radius = points.row(i).norm();
    if (std::abs(radius - 1.0) > 1e-6)
    {
      error << "point " << i << " is not on the unit sphere (|p| = " << radius
            << ", tolerance 1e-6)";
      return error.str();
    }
  }
  if (triangles.rows() == 0)
  {
    return {};
  }
  if (areas.size() != triangles.rows())
  {
    error << "expected one area per triangle (" << triangles.rows() << "), got " << areas.size();
    return error.str();
  }
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (triangles(t, k) < 0 || triangles(t, k) >= points.rows())
      {
        error << "triangle " << t << " refers to point " << triangles(t, k) << ", out of range";
        return error.str();
      }
    }
    // Zero is a triangle of three points on a line (it weighs nothing).
    if (!std::isfinite(areas[t]) || areas[t] < 0)
    {
      error << "triangle " << t << " has an invalid area (" << areas[t]
            << "); areas must be finite and not negative";
      return error.str();
    }
  }
  if (!(areas.sum() > 0))
  {
    return "the triangles have no area";
  }
  return {};
}
}

Eigen::Matrix4d InversionLorentzMatrix(const Eigen::Vector3d& c)
{
  const double s = c.squaredNorm();
  Eigen::Matrix4d lorentz;
  lorentz.topLeftCorner<3, 3>() = (1.0 - s) * Eigen::Matrix3d::Identity() + 2.0 * c * c.transpose();
  lorentz.topRightCorner<3, 1>() = 2.0 * c;
  lorentz.bottomLeftCorner<1, 3>() = 2.0 * c.transpose();
  lorentz(3, 3) = 1.0 + s;
  // Dividing by 1 - |c|^2 makes it a proper Lorentz boost (determinant 1), so products of
  // many steps stay well scaled.
  return lorentz / (1.0 - s);
}

Eigen::Vector3d ApplyLorentzTransform(const Eigen::Matrix4d& lorentz, const Eigen::Vector3d& x)
{
  const Eigen::Vector4d image = lorentz * Eigen::Vector4d(x.x(), x.y(), x.z(), 1.0);
  return (image.head<3>() / image.w()).normalized();
}

void ApplyInversion(const Eigen::Vector3d& c, Points& points)
{
  const double scale = 1.0 - c.squaredNorm();
  for (Eigen::Index i = 0; i < points.rows(); ++i)
  {
    const Eigen::Vector3d shifted = points.row(i).transpose() + c;
    const Eigen::Vector3d image = scale * shifted / shifted.squaredNorm() + c;
    // The formula maps the sphere to itself exactly; renormalizing removes the round-off
    // that would otherwise accumulate over many steps.
    points.row(i) = image.normalized().transpose();
  }
}

Eigen::Vector3d SphericalCenterOfMass(
  const Points& points, const Triangles& triangles, const Vector& triangleAreas)
{
  const Eigen::Index n = triangles.rows() > 0 ? triangles.rows() : points.rows();
  Vector weights = triangles.rows() > 0 ? triangleAreas : Vector::Ones(n);
  weights /= weights.sum();
  return CenterOfMass(ComputeWeightedDirections(points, triangles, weights));
}

bool CenterSphericalMap(Points& points, const Triangles& triangles, const Vector& triangleAreas,
  const MobiusCenteringParameters& parameters, MobiusCenteringResult& result,
  const ProgressCallback& progress)
{
  result = MobiusCenteringResult();
  result.Error = CheckInput(points, triangles, triangleAreas);
  if (!result.Error.empty())
  {
    return false;
  }

  const Eigen::Index n = triangles.rows() > 0 ? triangles.rows() : points.rows();
  Vector weights = triangles.rows() > 0 ? triangleAreas : Vector::Ones(n);
  weights /= weights.sum();

  Points current = points;
  WeightedDirections wd = ComputeWeightedDirections(current, triangles, weights);
  Eigen::Vector3d mu = CenterOfMass(wd);
  result.InitialCenterOfMassNorm = mu.norm();

  while (mu.norm() > parameters.Tolerance &&
    result.NumberOfIterations < parameters.MaximumNumberOfIterations)
  {
    if (progress &&
      !progress(static_cast<double>(result.NumberOfIterations) /
        parameters.MaximumNumberOfIterations))
    {
      result.Error = "aborted";
      return false;
    }
    // Gauss-Newton direction; J is symmetric positive definite unless all mass sits on one
    // great circle's two antipodal points, which the solver reports as failure below.
    const Eigen::Matrix3d jacobian = CenteringJacobian(wd);
    Eigen::Vector3d c = -jacobian.ldlt().solve(mu);
    if (!c.allFinite())
    {
      result.Error = "the centering Jacobian is singular (all mass on a line through the origin)";
      return false;
    }
    if (c.norm() > parameters.MaximumStepRadius)
    {
      c *= parameters.MaximumStepRadius / c.norm();
    }

    // Backtracking line search on |mu|: halve the step until the centre of mass moves
    // closer to the origin. Gauss-Newton is a descent direction for |mu|^2 because J is
    // positive definite, so a small enough step always succeeds.
    bool improved = false;
    for (int halving = 0; halving < 60; ++halving, c *= 0.5)
    {
      Points trial = current;
      ApplyInversion(c, trial);
      WeightedDirections trialWd = ComputeWeightedDirections(trial, triangles, weights);
      const Eigen::Vector3d trialMu = CenterOfMass(trialWd);
      if (trialMu.norm() < mu.norm())
      {
        current.swap(trial);
        wd = std::move(trialWd);
        mu = trialMu;
        improved = true;
        break;
      }
    }
    if (!improved)
    {
      // Round-off floor reached: no inversion reduces |mu| any further.
      break;
    }
    result.InversionCenters.push_back(c);
    result.LorentzTransform = InversionLorentzMatrix(c) * result.LorentzTransform;
    ++result.NumberOfIterations;
  }

  result.CenterOfMassNorm = mu.norm();
  result.Converged = result.CenterOfMassNorm <= parameters.Tolerance;
  points.swap(current);
  return true;
}
}
