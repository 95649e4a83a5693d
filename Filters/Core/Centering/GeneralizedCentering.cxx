#include "GeneralizedCentering.h"

#include <Eigen/Dense>

#include <cmath>
#include <vector>

namespace mobius
{
namespace
{
int NumberOfFunctions(int degree)
{
  return (degree + 1) * (degree + 1) - 1;
}

// Normalized centroid directions of the triangles.
Points TriangleCenters(const Points& points, const Triangles& triangles)
{
  Points centers(triangles.rows(), 3);
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    const Eigen::Vector3d c = points.row(triangles(t, 0)) + points.row(triangles(t, 1)) +
      points.row(triangles(t, 2));
    centers.row(t) = c.norm() > 0 ? Eigen::Vector3d(c.normalized()) : Eigen::Vector3d::Zero();
  }
  return centers;
}

// Tangential gradients of the harmonics at x (k x 3), by central differences along two
// tangent directions: the harmonics are smooth and low-degree, so h = 1e-5 gives about ten
// correct digits, plenty for the Newton matrix (mu itself is evaluated exactly).
Eigen::MatrixXd HarmonicGradients(int degree, const Eigen::Vector3d& x)
{
  const int k = NumberOfFunctions(degree);
  const Eigen::Vector3d helper = std::abs(x.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d t1 = x.cross(helper).normalized();
  const Eigen::Vector3d t2 = x.cross(t1);
  const double h = 1e-5;
  Eigen::MatrixXd gradients = Eigen::MatrixXd::Zero(k, 3);
  std::vector<double> plus(k), minus(k);
  for (const Eigen::Vector3d& t : { t1, t2 })
  {
    EvaluateRealSphericalHarmonics(degree, (x + h * t).normalized(), plus.data());
    EvaluateRealSphericalHarmonics(degree, (x - h * t).normalized(), minus.data());
    for (int i = 0; i < k; ++i)
    {
      gradients.row(i) += (plus[i] - minus[i]) / (2 * h) * t.transpose();
    }
  }
  return gradients;
}

Index CountInvertedTriangles(const Points& points, const Triangles& triangles, const Vector& signs)
{
  Index inverted = 0;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    const Eigen::Vector3d a = points.row(triangles(t, 0)), b = points.row(triangles(t, 1)),
                          c = points.row(triangles(t, 2));
    inverted += a.dot((b - a).cross(c - a)) * signs[t] <= 0 ? 1 : 0;
  }
  return inverted;
}
}

void EvaluateRealSphericalHarmonics(int degree, const Eigen::Vector3d& x, double* values)
{
  const double z = std::max(-1.0, std::min(1.0, x.z()));
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = std::atan2(x.y(), x.x());
  // Associated Legendre P_l^m(z) (without the Condon-Shortley phase) by the standard
  // recurrences; degrees are small, so factorial normalizations are exact enough.
  std::vector<std::vector<double>> P(degree + 1, std::vector<double>(degree + 1, 0.0));
  P[0][0] = 1.0;
  for (int m = 1; m <= degree; ++m)
  {
    P[m][m] = P[m - 1][m - 1] * (2 * m - 1) * s;
  }
  for (int m = 0; m < degree; ++m)
  {
    P[m + 1][m] = z * (2 * m + 1) * P[m][m];
  }
  for (int m = 0; m <= degree; ++m)
  {
    for (int l = m + 2; l <= degree; ++l)
    {
      P[l][m] = ((2 * l - 1) * z * P[l - 1][m] - (l + m - 1) * P[l - 2][m]) / (l - m);
    }
  }
  int index = 0;
  for (int l = 1; l <= degree; ++l)
  {
    for (int m = -l; m <= l; ++m)
    {
      const int a = std::abs(m);
      double ratio = 1.0; // (l - |m|)! / (l + |m|)!
      for (int f = l - a + 1; f <= l + a; ++f)
      {
        ratio /= f;
      }
      const double norm = std::sqrt((2 * l + 1) / (4 * M_PI) * ratio);
      const double value = norm * P[l][a];
      values[index++] = m == 0 ? value
        : m > 0 ? std::sqrt(2.0) * value * std::cos(a * phi)
                : std::sqrt(2.0) * value * std::sin(a * phi);
    }
  }
}

Vector SphericalHarmonicMoments(
  const Points& points, const Triangles& triangles, const Vector& areas, int degree)
{
  const Points centers = TriangleCenters(points, triangles);
  const double total = areas.sum();
  Vector mu = Vector::Zero(NumberOfFunctions(degree));
  std::vector<double> values(mu.size());
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    EvaluateRealSphericalHarmonics(degree, centers.row(t).transpose(), values.data());
    mu += areas[t] / total * Eigen::Map<const Vector>(values.data(), mu.size());
  }
  return mu;
}

bool CenterWithSphericalHarmonics(Points& points, const Triangles& triangles, const Vector& areas,
  const GeneralizedCenteringParameters& parameters, GeneralizedCenteringResult& result,
  const ProgressCallback& progress)
{
  result = GeneralizedCenteringResult();
  if (parameters.Degree < 1)
  {
    result.Error = "the degree must be at least 1";
    return false;
  }
  if (triangles.rows() == 0 || areas.size() != triangles.rows() || !(areas.minCoeff() > 0))
  {
    result.Error = "generalized centering needs triangles with positive areas";
    return false;
  }
  const int degree = parameters.Degree;
  const double total = areas.sum();
  // The orientation each triangle has now: a step may not flip any of them.
  Vector signs(triangles.rows());
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    const Eigen::Vector3d a = points.row(triangles(t, 0)), b = points.row(triangles(t, 1)),
                          c = points.row(triangles(t, 2));
    signs[t] = a.dot((b - a).cross(c - a)) >= 0 ? 1.0 : -1.0;
  }
  const Index initiallyInverted = CountInvertedTriangles(points, triangles, signs);

  Points current = points;
  Vector mu = SphericalHarmonicMoments(current, triangles, areas, degree);
  result.InitialCenterOfMassNorm = mu.norm();
  while (mu.norm() > parameters.Tolerance &&
    result.NumberOfIterations < parameters.MaximumNumberOfIterations)
  {
    if (progress &&
      !progress(static_cast<double>(result.NumberOfIterations) / parameters.MaximumNumberOfIterations))
    {
      result.Error = "aborted";
      return false;
    }
    // Newton matrix J = sum_t A grad e_i . grad e_j at the triangle centers.
    const Points centers = TriangleCenters(current, triangles);
    const int k = static_cast<int>(mu.size());
    Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(k, k);
    for (Eigen::Index t = 0; t < triangles.rows(); ++t)
    {
      const Eigen::MatrixXd g = HarmonicGradients(degree, centers.row(t).transpose());
      jacobian.noalias() += areas[t] / total * g * g.transpose();
    }
    const Vector c = -jacobian.ldlt().solve(mu);
    if (!c.allFinite())
    {
      result.Error = "the centering matrix is singular";
      return false;
    }
    // Vertex velocities grad phi, scaled so that no vertex moves more than the cap.
    Points velocity(current.rows(), 3);
    double fastest = 0;
    for (Eigen::Index i = 0; i < current.rows(); ++i)
    {
      velocity.row(i) = (HarmonicGradients(degree, current.row(i).transpose()).transpose() * c).transpose();
      fastest = std::max(fastest, velocity.row(i).norm());
    }
    double step = fastest > parameters.MaximumStepAngle ? parameters.MaximumStepAngle / fastest : 1.0;
    bool improved = false;
    for (int halving = 0; halving < 40 && !improved; ++halving, step *= 0.5)
    {
      Points trial = current + step * velocity;
      trial.rowwise().normalize();
      if (CountInvertedTriangles(trial, triangles, signs) > initiallyInverted)
      {
        continue;
      }
      const Vector trialMu = SphericalHarmonicMoments(trial, triangles, areas, degree);
      if (trialMu.norm() < mu.norm())
      {
        current.swap(trial);
        mu = trialMu;
        improved = true;
      }
    }
    if (!improved)
    {
      break; // no admissible step lowers |mu| further
    }
    ++result.NumberOfIterations;
  }
  result.CenterOfMassNorm = mu.norm();
  result.Converged = result.CenterOfMassNorm <= parameters.Tolerance;
  points.swap(current);
  return true;
}
}
