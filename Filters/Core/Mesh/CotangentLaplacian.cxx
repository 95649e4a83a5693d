#include "CotangentLaplacian.h"

#include "IntrinsicDelaunay.h"

#include <Eigen/Geometry>

#include <cmath>
#include <vector>

namespace mobius
{
Vector TriangleAreas(const Points& points, const Triangles& triangles)
{
  Vector areas(triangles.rows());
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    const Eigen::Vector3d a = points.row(triangles(t, 0)), b = points.row(triangles(t, 1)),
                          c = points.row(triangles(t, 2));
    areas[t] = 0.5 * (b - a).cross(c - a).norm();
  }
  return areas;
}

Vector LumpedMass(const Points& points, const Triangles& triangles)
{
  const Vector areas = TriangleAreas(points, triangles);
  Vector mass = Vector::Zero(points.rows());
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      mass[triangles(t, k)] += areas[t] / 3.0;
    }
  }
  return mass;
}

bool BuildCotangentStiffness(const Points& points, const Triangles& triangles,
  bool intrinsicDelaunay, SparseMatrix& stiffness, CotangentStiffnessInfo& info)
{
  info = CotangentStiffnessInfo();
  IntrinsicTriangulation intrinsic;
  if (!MakeIntrinsicTriangulation(points, triangles, intrinsic))
  {
    info.Error = "the mesh has non-manifold or inconsistently oriented edges";
    return false;
  }
  if (intrinsicDelaunay)
  {
    info.IntrinsicFlips = FlipToDelaunay(intrinsic);
  }
  const std::vector<double> cotangents = OppositeCotangents(intrinsic);

  const Index n = points.rows();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(4 * cotangents.size() + static_cast<size_t>(n));
  for (Index i = 0; i < n; ++i)
  {
    entries.emplace_back(i, i, 0.0); // keep every diagonal entry in the pattern
  }
  for (size_t h = 0; h < cotangents.size(); ++h)
  {
    const double w = 0.5 * cotangents[h];
    if (!std::isfinite(w))
    {
      info.Error = "a cotangent weight is not finite (a triangle has a zero-length edge or "
                   "no area)";
      return false;
    }
    const Index t = static_cast<Index>(h / 3), k = static_cast<Index>(h % 3);
    const Index i = intrinsic.Corners(t, k), j = intrinsic.Corners(t, (k + 1) % 3);
    if (i == j)
    {
      continue; // a loop edge of an intrinsic triangulation: x_i - x_i contributes nothing
    }
    entries.emplace_back(i, j, -w);
    entries.emplace_back(j, i, -w);
    entries.emplace_back(i, i, w);
    entries.emplace_back(j, j, w);
  }
  stiffness.resize(n, n);
  stiffness.setFromTriplets(entries.begin(), entries.end());
  stiffness.makeCompressed();
  // Count negative edge weights (each off-diagonal entry is -weight).
  for (Index col = 0; col < stiffness.outerSize(); ++col)
  {
    for (SparseMatrix::InnerIterator it(stiffness, col); it; ++it)
    {
      if (it.row() > col && it.value() > 0.0)
      {
        ++info.NegativeWeights;
      }
    }
  }
  return true;
}
}
