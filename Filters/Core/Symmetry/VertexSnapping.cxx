#include "VertexSnapping.h"

#include "SphericalPointLocator.h"

#include <algorithm>
#include <limits>

namespace mobius
{
Index SnapToCoincidentVertices(const Points& reflectedSphere, const Points& sphere,
  const Triangles& triangles, double relativeTolerance, std::vector<Index>& triangle,
  std::vector<Eigen::Vector3d>& barycentric, std::string& error)
{
  SphericalPointLocator locator;
  if (!locator.Build(sphere, triangles, error))
  {
    return -1;
  }
  // The local vertex spacing: the shortest edge at each vertex (conformal maps squeeze
  // limbs, so spacings differ by orders of magnitude over the sphere).
  Vector spacing = Vector::Constant(sphere.rows(), std::numeric_limits<double>::max());
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index a = triangles(t, k), b = triangles(t, (k + 1) % 3);
      const double length = (sphere.row(a) - sphere.row(b)).norm();
      spacing(a) = std::min(spacing(a), length);
      spacing(b) = std::min(spacing(b), length);
    }
  }
  Index snapped = 0;
  for (Index v = 0; v < reflectedSphere.rows(); ++v)
  {
    const Eigen::Vector3d point = reflectedSphere.row(v).transpose();
    const SphericalLocation location = locator.Locate(point);
    if (location.Triangle < 0)
    {
      continue;
    }
    Eigen::Index corner = 0;
    location.Barycentric.maxCoeff(&corner);
    const Index w = triangles(location.Triangle, corner);
    if ((point - sphere.row(w).transpose()).norm() <= relativeTolerance * spacing(w))
    {
      triangle[v] = location.Triangle;
      barycentric[v] = Eigen::Vector3d::Unit(corner);
      ++snapped;
    }
  }
  return snapped;
}
}
