#include "LinearSphericalMap.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

namespace mobius
{
namespace
{
// Share of the mass by which L is shifted: large enough that L + eps M stays numerically
// positive definite on million-vertex meshes (its smallest eigenvalue, eps / N for the
// constant vector, must dwarf rounding), small enough that the solution's non-constant part
// moves by eps / lambda_1 (lambda_1 is about 25 for a unit-area round surface), which the
// refinement step squares.
constexpr double MassShift = 1e-3;

Eigen::Vector3d Corner(const Points& points, const Triangles& triangles, Index t, int k)
{
  return points.row(triangles(t, k)).transpose();
}
}

Index ChoosePoleTriangle(const Points& points, const Triangles& triangles)
{
  const Index count = triangles.rows();
  if (count == 0)
  {
    return -1;
  }
  // Area-weighted vertex normals: a corner's normal far from its triangle's says the
  // surface bends around that corner.
  Points vertexNormals = Points::Zero(points.rows(), 3);
  Points normals(count, 3); // twice the area times the unit normal
  Vector areas(count);
  for (Index t = 0; t < count; ++t)
  {
    const Eigen::Vector3d a = Corner(points, triangles, t, 0), b = Corner(points, triangles, t, 1),
                          c = Corner(points, triangles, t, 2);
    const Eigen::Vector3d n = (b - a).cross(c - a);
    normals.row(t) = n.transpose();
    areas[t] = 0.5 * n.norm();
    for (int k = 0; k < 3; ++k)
    {
      vertexNormals.row(triangles(t, k)) += n.transpose();
    }
  }
  std::vector<double> sortedAreas(areas.data(), areas.data() + count);
  const auto median = sortedAreas.begin() + count / 2;
  std::nth_element(sortedAreas.begin(), median, sortedAreas.end());
  const double medianArea = *median;

  // The choice must not depend on the vertices' or triangles' numbering (a mesh split over
  // MPI ranks and merged again maps to the same map): scores are compared after rounding
  // away the last bits their summation order changes, and ties go to the triangle whose
  // centroid comes first in (x, y, z), also rounded.
  auto rounded = [](double value) { return std::round(value * 1e9); };
  Index best = -1;
  std::array<double, 4> bestKey = { -1.0, 0.0, 0.0, 0.0 };
  for (Index t = 0; t < count; ++t)
  {
    if (!(areas[t] > 0.0) || !std::isfinite(areas[t]) || areas[t] < medianArea)
    {
      continue;
    }
    double squaredLengths = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      squaredLengths +=
        (points.row(triangles(t, (k + 1) % 3)) - points.row(triangles(t, k))).squaredNorm();
    }
    const double quality = 4.0 * std::sqrt(3.0) * areas[t] / squaredLengths;
    const Eigen::Vector3d n = normals.row(t).transpose().normalized();
    double flatness = 1.0;
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d m = vertexNormals.row(triangles(t, k)).transpose();
      const double length = m.norm();
      flatness = std::min(flatness, length > 0.0 ? n.dot(m) / length : -1.0);
    }
    const double score = quality * std::max(flatness, 0.0);
    if (!std::isfinite(score))
    {
      continue;
    }
    const Eigen::RowVector3d centroid = (points.row(triangles(t, 0)) +
      points.row(triangles(t, 1)) + points.row(triangles(t, 2))) / 3.0;
    // Larger score first, then smaller centroid coordinates.
    const std::array<double, 4> key = { rounded(score), -rounded(centroid[0]),
      -rounded(centroid[1]), -rounded(centroid[2]) };
    if (best < 0 || key > bestKey)
    {
      bestKey = key;
      best = t;
    }
  }
  return best;
}

LinearSphericalMapResult ComputeLinearSphericalMap(const Points& points,
  const Triangles& triangles, const SparseMatrix& stiffness, const Vector& mass,
  SparseCholesky& solver)
{
  LinearSphericalMapResult result;
  const Index n = points.rows();
  result.PoleTriangle = ChoosePoleTriangle(points, triangles);
  if (result.PoleTriangle < 0)
  {
    result.Error = "no triangle with positive area to place the pole in";
    return result;
  }

  // b_j = (d/du + i d/dv) phi_j in the pole triangle, (u, v, normal) right-handed. (The
  // conjugate of the form in the file comment: z then follows 1/conj(w), and the inverse
  // stereographic projection, which reverses orientation, makes the map face the same way
  // as the surface, as the flow's does.)
  const Index t = result.PoleTriangle;
  const Eigen::Vector3d a = Corner(points, triangles, t, 0), b = Corner(points, triangles, t, 1),
                        c = Corner(points, triangles, t, 2);
  const Eigen::Vector3d doubleAreaNormal = (b - a).cross(c - a);
  const double doubleArea = doubleAreaNormal.norm();
  const Eigen::Vector3d normal = doubleAreaNormal / doubleArea;
  const Eigen::Vector3d u = (b - a).normalized();
  const Eigen::Vector3d v = normal.cross(u);
  const Eigen::Vector3d opposite[3] = { c - b, a - c, b - a };
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 2);
  for (int k = 0; k < 3; ++k)
  {
    const Eigen::Vector3d gradient = normal.cross(opposite[k]) / doubleArea;
    rhs(triangles(t, k), 0) += gradient.dot(u);
    rhs(triangles(t, k), 1) += gradient.dot(v);
  }

  SparseMatrix shifted = stiffness;
  for (Index i = 0; i < n; ++i)
  {
    shifted.coeffRef(i, i) += MassShift * mass[i];
  }
  result.Factorized = true;
  if (!solver.Factorize(shifted))
  {
    result.Error = "the factorization of the shifted Laplacian failed";
    return result;
  }
  Eigen::MatrixXd z = solver.Solve(rhs);
  // One step of iterative refinement against the unshifted L: the residual is eps M z (plus
  // rounding), so the correction removes the shift's first-order effect.
  const Eigen::MatrixXd residual = rhs - stiffness * z;
  z += solver.Solve(residual);
  if (!z.allFinite())
  {
    result.Error = "the linear solve gave non-finite values";
    return result;
  }

  // Remove the constant (any constant is a solution) and scale so that the vertices of half
  // the area fall inside the unit circle: the southern hemisphere after projection.
  const double totalMass = mass.sum();
  const Eigen::RowVector2d mean = (mass.transpose() * z) / totalMass;
  z.rowwise() -= mean;
  std::vector<std::pair<double, double>> radii(static_cast<size_t>(n));
  for (Index i = 0; i < n; ++i)
  {
    radii[i] = { z.row(i).norm(), mass[i] };
  }
  std::sort(radii.begin(), radii.end());
  double cumulative = 0.0, scale = 0.0;
  for (const auto& radius : radii)
  {
    cumulative += radius.second;
    if (cumulative >= 0.5 * totalMass)
    {
      scale = radius.first;
      break;
    }
  }
  if (!(scale > 0.0) || !std::isfinite(scale))
  {
    result.Error = "the linear map collapsed the surface onto a point";
    return result;
  }

  result.SpherePoints.resize(n, 3);
  for (Index i = 0; i < n; ++i)
  {
    const double x = z(i, 0) / scale, y = z(i, 1) / scale;
    const double r2 = x * x + y * y;
    result.SpherePoints.row(i) << 2.0 * x / (1.0 + r2), 2.0 * y / (1.0 + r2),
      (r2 - 1.0) / (r2 + 1.0);
  }
  if (!result.SpherePoints.allFinite())
  {
    result.Error = "the stereographic projection gave non-finite values";
    return result;
  }
  result.Success = true;
  return result;
}
}
