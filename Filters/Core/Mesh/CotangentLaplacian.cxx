#include "CotangentLaplacian.h"

#include "IntrinsicDelaunay.h"
#include "StableSortRun.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
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

Points AreaWeightedVertexNormals(const Points& points, const Triangles& triangles)
{
  Points normals = Points::Zero(points.rows(), 3);
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    const Eigen::RowVector3d a = points.row(triangles(t, 0)), b = points.row(triangles(t, 1)),
                             c = points.row(triangles(t, 2));
    const Eigen::RowVector3d normal = (b - a).cross(c - a); // |normal| = 2 x area
    for (int k = 0; k < 3; ++k)
    {
      normals.row(triangles(t, k)) += normal;
    }
  }
  normals.rowwise().normalize();
  return normals;
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

namespace
{
// One half-edge's weight as seen from one of its two ends.
struct WeightTerm
{
  Index Other; // the half-edge's other end
  double Weight;
};

// The stiffness matrix L (L_ii = sum of the weights w of i's edges, L_ij = -w summed over
// the edges i-j) from the half-edges' weights (0.5 times their opposite cotangents), column
// by column from each vertex's half-edges. Every entry's terms are summed in half-edge order
// starting as Eigen's setFromTriplets did (diagonals from 0, off-diagonals from their first
// term), so the values are the same to the last bit; without the triplet list (4 entries
// per half-edge) and its transposed copy this takes a fraction of the time and memory.
// Loop edges of an intrinsic triangulation (i = i) contribute nothing.
void AssembleStiffness(const Triangles& corners, const std::vector<double>& cotangents,
  Index n, SparseMatrix& stiffness)
{
  auto ends = [&](size_t h, Index& i, Index& j) {
    const Index t = static_cast<Index>(h / 3), k = static_cast<Index>(h % 3);
    i = corners(t, k);
    j = corners(t, (k + 1) % 3);
  };
  std::vector<Index> start(static_cast<size_t>(n) + 1, 0);
  for (size_t h = 0; h < cotangents.size(); ++h)
  {
    Index i, j;
    ends(h, i, j);
    if (i != j)
    {
      ++start[i + 1];
      ++start[j + 1];
    }
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<WeightTerm> terms(static_cast<size_t>(start[n]));
  {
    std::vector<Index> fill(start.begin(), start.end() - 1);
    for (size_t h = 0; h < cotangents.size(); ++h)
    {
      Index i, j;
      ends(h, i, j);
      if (i != j)
      {
        const double w = 0.5 * cotangents[h];
        terms[fill[i]++] = { j, w };
        terms[fill[j]++] = { i, w };
      }
    }
  }
  std::vector<int> rows;
  std::vector<double> values;
  rows.reserve(terms.size() + static_cast<size_t>(n));
  values.reserve(terms.size() + static_cast<size_t>(n));
  std::vector<int> columnStart(static_cast<size_t>(n) + 1, 0);
  for (Index v = 0; v < n; ++v)
  {
    const auto begin = terms.begin() + start[v], end = terms.begin() + start[v + 1];
    double diagonal = 0.0;
    for (auto term = begin; term != end; ++term)
    {
      diagonal += term->Weight;
    }
    // Stable: the terms of one edge stay in half-edge order.
    StableSortRun(
      begin, end, [](const WeightTerm& x, const WeightTerm& y) { return x.Other < y.Other; });
    bool diagonalPlaced = false;
    for (auto term = begin; term != end;)
    {
      if (!diagonalPlaced && term->Other > v)
      {
        rows.push_back(static_cast<int>(v));
        values.push_back(diagonal);
        diagonalPlaced = true;
      }
      double value = -term->Weight;
      auto next = term + 1;
      for (; next != end && next->Other == term->Other; ++next)
      {
        value += -next->Weight;
      }
      rows.push_back(static_cast<int>(term->Other));
      values.push_back(value);
      term = next;
    }
    if (!diagonalPlaced)
    {
      rows.push_back(static_cast<int>(v));
      values.push_back(diagonal);
    }
    columnStart[v + 1] = static_cast<int>(rows.size());
  }
  stiffness.resize(n, n);
  stiffness.resizeNonZeros(static_cast<Index>(rows.size()));
  std::copy(columnStart.begin(), columnStart.end(), stiffness.outerIndexPtr());
  std::copy(rows.begin(), rows.end(), stiffness.innerIndexPtr());
  std::copy(values.begin(), values.end(), stiffness.valuePtr());
}
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

  for (const double cotangent : cotangents)
  {
    if (!std::isfinite(0.5 * cotangent))
    {
      info.Error = "a cotangent weight is not finite (a triangle has a zero-length edge or "
                   "no area)";
      return false;
    }
  }
  AssembleStiffness(intrinsic.Corners, cotangents, points.rows(), stiffness);
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
