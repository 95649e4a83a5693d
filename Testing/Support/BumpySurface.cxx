#include "BumpySurface.h"

#include <Eigen/Geometry>

#include <cmath>

namespace mobius
{
Eigen::Vector3d BumpySurfacePoint(const Eigen::Vector3d& x)
{
  const double bulge =
    1.0 + 0.8 * std::exp(-4.0 * (x - Eigen::Vector3d(0.6, 0.6, 0.5)).squaredNorm());
  return Eigen::Vector3d(1.7 * x.x(), x.y(), 0.6 * x.z()) * bulge;
}

Vector EmbeddedTriangleAreas(const Points& sphere, const Triangles& triangles,
  const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& embed)
{
  Vector areas(triangles.rows());
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    const Eigen::Vector3d a = embed(sphere.row(triangles(t, 0)).transpose());
    const Eigen::Vector3d b = embed(sphere.row(triangles(t, 1)).transpose());
    const Eigen::Vector3d c = embed(sphere.row(triangles(t, 2)).transpose());
    areas[t] = 0.5 * (b - a).cross(c - a).norm();
  }
  return areas;
}

Vector BumpySurfaceAreas(const Points& sphere, const Triangles& triangles)
{
  return EmbeddedTriangleAreas(sphere, triangles, BumpySurfacePoint);
}
}
