#include "ManifoldSplit.h"

#include "MeshEdges.h"

#include <algorithm>
#include <array>
#include <numeric>

namespace mobius
{
namespace
{
Triangles KeptRows(const Triangles& triangles, const std::vector<Index>& rows)
{
  Triangles kept(static_cast<Index>(rows.size()), 3);
  for (size_t i = 0; i < rows.size(); ++i)
  {
    kept.row(static_cast<Index>(i)) = triangles.row(rows[i]);
  }
  return kept;
}

// The corner of triangle t at vertex v, as 3 t + k.
Index CornerAt(const Triangles& triangles, Index t, Index v)
{
  return 3 * t + (triangles(t, 0) == v ? 0 : triangles(t, 1) == v ? 1 : 2);
}
}

MeshProvenance RemoveDuplicateTriangles(Index numberOfPoints, Triangles& triangles, Index* removed)
{
  using Corners = std::array<Index, 3>;
  std::vector<Corners> sorted(static_cast<size_t>(triangles.rows()));
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    sorted[t] = { triangles(t, 0), triangles(t, 1), triangles(t, 2) };
    std::sort(sorted[t].begin(), sorted[t].end());
  }
  std::vector<Index> order(sorted.size());
  std::iota(order.begin(), order.end(), Index(0));
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return sorted[a] < sorted[b]; });
  std::vector<char> keep(sorted.size(), 1);
  for (size_t i = 1; i < order.size(); ++i)
  {
    keep[order[i]] = sorted[order[i]] == sorted[order[i - 1]] ? 0 : 1;
  }
  MeshProvenance provenance = IdentityProvenance(numberOfPoints, 0);
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    if (keep[t])
    {
      provenance.TriangleSource.push_back(t);
    }
  }
  if (removed)
  {
    *removed = triangles.rows() - static_cast<Index>(provenance.TriangleSource.size());
  }
  triangles = KeptRows(triangles, provenance.TriangleSource);
  return provenance;
}

FanSplit SplitVertexFans(Points& points, Triangles& triangles, const std::vector<EdgeKey>& cuts)
{
  const Index n = points.rows();
  const std::vector<char> valid = ValidTriangles(triangles, n);
  const std::vector<HalfEdge> halfEdges = SortedHalfEdges(triangles, valid, n);
  // Corners (3 t + k) joined across every two-triangle edge that is not a cut, at both ends:
  // each fan of a vertex ends up as one set of its corners.
  UnionFind fans(3 * triangles.rows());
  ForEachEdge(halfEdges, [&](size_t begin, size_t end) {
    const HalfEdge& first = halfEdges[begin];
    if (end - begin != 2 || std::binary_search(cuts.begin(), cuts.end(), EdgeKey(first.Low, first.High)))
    {
      return;
    }
    const Index other = halfEdges[begin + 1].Triangle;
    fans.Union(CornerAt(triangles, other, first.Low), CornerAt(triangles, first.Triangle, first.Low));
    fans.Union(CornerAt(triangles, other, first.High), CornerAt(triangles, first.Triangle, first.High));
  });
  FanSplit split;
  split.Provenance.PointSource.resize(static_cast<size_t>(n));
  std::iota(split.Provenance.PointSource.begin(), split.Provenance.PointSource.end(), Index(0));
  split.Provenance.TriangleSource.resize(static_cast<size_t>(triangles.rows()));
  std::iota(split.Provenance.TriangleSource.begin(), split.Provenance.TriangleSource.end(), Index(0));
  // The point each fan (by its root corner) is given; the first fan met keeps the vertex.
  std::vector<Index> pointOfFan(static_cast<size_t>(3 * triangles.rows()), -1);
  std::vector<char> vertexTaken(static_cast<size_t>(n), 0), vertexSplit(static_cast<size_t>(n), 0);
  std::vector<Index> copies;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; valid[t] && k < 3; ++k)
    {
      const Index v = triangles(t, k);
      const Index root = fans.Find(3 * t + k);
      if (pointOfFan[root] < 0)
      {
        if (!vertexTaken[v])
        {
          vertexTaken[v] = 1;
          pointOfFan[root] = v;
        }
        else
        {
          vertexSplit[v] = 1;
          pointOfFan[root] = n + static_cast<Index>(copies.size());
          copies.push_back(v);
        }
      }
      triangles(t, k) = pointOfFan[root];
    }
  }
  split.SplitVertices = std::count(vertexSplit.begin(), vertexSplit.end(), 1);
  points.conservativeResize(n + static_cast<Index>(copies.size()), 3);
  for (size_t i = 0; i < copies.size(); ++i)
  {
    points.row(n + static_cast<Index>(i)) = points.row(copies[i]);
    split.Provenance.PointSource.push_back(copies[i]);
  }
  return split;
}
}
