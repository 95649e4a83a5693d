#include "SymmetryMeasures.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace mobius
{
double SymmetryDistance(double correlationCoefficient)
{
  const double rho = std::max(-1.0, std::min(1.0, correlationCoefficient));
  return std::sqrt((1.0 - rho) / 2.0);
}

MirrorPlane MirrorPlaneOf(const Eigen::Matrix3d& reflection)
{
  // T = R_n(θ) (I - 2nnᵀ) has eigenvalue -1 along n and a rotation by θ in the plane, so
  // its symmetric part has eigenvalues -1 (along n) and cos θ (twice): the smallest one's
  // eigenvector is n even when θ is large.
  const Eigen::Matrix3d symmetric = 0.5 * (reflection + reflection.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(symmetric);
  MirrorPlane plane;
  plane.Normal = solver.eigenvectors().col(0).normalized();
  Eigen::Index largest = 0;
  plane.Normal.cwiseAbs().maxCoeff(&largest);
  if (plane.Normal(largest) < 0)
  {
    plane.Normal = -plane.Normal;
  }
  // The rotation left after undoing the reflection: trace = 1 + 2 cos θ.
  const Eigen::Matrix3d pure =
    Eigen::Matrix3d::Identity() - 2.0 * plane.Normal * plane.Normal.transpose();
  const double cosine = ((reflection * pure).trace() - 1.0) / 2.0;
  plane.Twist = std::acos(std::max(-1.0, std::min(1.0, cosine)));
  return plane;
}

Vector MirrorAsymmetry(const Points& surface, const Triangles& triangles,
  const std::vector<Index>& mirrorTriangle, const std::vector<Eigen::Vector3d>& barycentric,
  const Points& mirrorPoints)
{
  Vector asymmetry(surface.rows());
  for (Index v = 0; v < surface.rows(); ++v)
  {
    Eigen::Vector3d twice = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
    {
      twice += barycentric[v][k] * mirrorPoints.row(triangles(mirrorTriangle[v], k)).transpose();
    }
    asymmetry(v) = (surface.row(v).transpose() - twice).norm();
  }
  return asymmetry;
}

Vector RelativeMirrorAsymmetry(const Points& surface, const Triangles& triangles,
  const Vector& areas, const std::vector<Index>& mirrorTriangle,
  const std::vector<Eigen::Vector3d>& barycentric, const Points& mirrorPoints)
{
  const double scale = std::sqrt(areas.sum());
  return MirrorAsymmetry(surface, triangles, mirrorTriangle, barycentric, mirrorPoints) / scale;
}

std::string DescribeMirrorCandidates(const std::vector<Eigen::Matrix3d>& reflections,
  const std::vector<double>& correlationCoefficients, MirrorCandidates& candidates)
{
  if (reflections.empty() || reflections.size() != correlationCoefficients.size())
  {
    return "the registration reported no candidates";
  }
  candidates.Distances.clear();
  candidates.Normals.clear();
  for (size_t c = 0; c < reflections.size(); ++c)
  {
    candidates.Distances.push_back(SymmetryDistance(correlationCoefficients[c]));
    const MirrorPlane plane = MirrorPlaneOf(reflections[c]);
    candidates.Normals.insert(
      candidates.Normals.end(), plane.Normal.data(), plane.Normal.data() + 3);
  }
  candidates.Best = reflections[0];
  candidates.BestPlane = MirrorPlaneOf(reflections[0]);
  return std::string();
}
}
