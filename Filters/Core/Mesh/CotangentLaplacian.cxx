#include "CotangentLaplacian.h"

#include "IntrinsicDelaunay.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
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

bool BuildMassMatrix(const Points& points, const Triangles& triangles, bool intrinsicDelaunay,
  double consistentShare, SparseMatrix& mass)
{
  IntrinsicTriangulation intrinsic;
  if (!MakeIntrinsicTriangulation(points, triangles, intrinsic))
  {
    return false;
  }
  if (intrinsicDelaunay)
  {
    FlipToDelaunay(intrinsic);
  }
  const Index n = points.rows();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(9 * static_cast<size_t>(intrinsic.Corners.rows()));
  // Per triangle of area A: lumped A/3 on the diagonal; consistent A/6 on the diagonal and
  // A/12 off it. Blended: diagonal A (1/3 - s/6), off-diagonal s A / 12.
  const double diagonal = 1.0 / 3.0 - consistentShare / 6.0, offDiagonal = consistentShare / 12.0;
  for (Index t = 0; t < intrinsic.Corners.rows(); ++t)
  {
    const double a = intrinsic.Length[3 * t], b = intrinsic.Length[3 * t + 1],
                 c = intrinsic.Length[3 * t + 2];
    // Heron's formula in the numerically stable ordering (Kahan).
    double s[3] = { a, b, c };
    std::sort(s, s + 3, std::greater<double>());
    const double product = (s[0] + (s[1] + s[2])) * (s[2] - (s[0] - s[1])) *
      (s[2] + (s[0] - s[1])) * (s[0] + (s[1] - s[2]));
    const double area = 0.25 * std::sqrt(std::max(0.0, product));
    for (int k = 0; k < 3; ++k)
    {
      const Index i = intrinsic.Corners(t, k);
      entries.emplace_back(i, i, diagonal * area);
      for (int l = 0; l < 3 && offDiagonal != 0; ++l) // lumped: a diagonal pattern
      {
        if (l != k)
        {
          entries.emplace_back(i, intrinsic.Corners(t, l), offDiagonal * area);
        }
      }
    }
  }
  mass.resize(n, n);
  mass.setFromTriplets(entries.begin(), entries.end());
  mass.makeCompressed();
  return true;
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
