#include "MeshAdjacency.h"

#include <algorithm>

namespace mobius
{
namespace
{
// Counting sort of (vertex, item) pairs into compressed lists.
VertexLists Compress(Index numberOfPoints, const std::vector<std::pair<Index, Index>>& pairs)
{
  VertexLists lists;
  lists.Offsets.assign(static_cast<size_t>(numberOfPoints) + 1, 0);
  for (const auto& pair : pairs)
  {
    ++lists.Offsets[pair.first + 1];
  }
  for (Index v = 0; v < numberOfPoints; ++v)
  {
    lists.Offsets[v + 1] += lists.Offsets[v];
  }
  lists.Items.resize(pairs.size());
  std::vector<Index> next(lists.Offsets.begin(), lists.Offsets.end() - 1);
  for (const auto& pair : pairs)
  {
    lists.Items[next[pair.first]++] = pair.second;
  }
  return lists;
}
}

VertexLists VertexNeighbors(Index numberOfPoints, const Triangles& triangles)
{
  std::vector<std::pair<Index, Index>> pairs;
  pairs.reserve(static_cast<size_t>(6 * triangles.rows()));
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index a = triangles(t, k), b = triangles(t, (k + 1) % 3);
      pairs.emplace_back(a, b);
      pairs.emplace_back(b, a);
    }
  }
  VertexLists lists = Compress(numberOfPoints, pairs);
  // Each interior edge was listed by both of its triangles: keep one copy.
  std::vector<Index> offsets(lists.Offsets.size(), 0);
  Index write = 0;
  for (Index v = 0; v < numberOfPoints; ++v)
  {
    const auto begin = lists.Items.begin() + lists.Begin(v), end = lists.Items.begin() + lists.End(v);
    std::sort(begin, end);
    const auto unique = std::unique(begin, end);
    for (auto it = begin; it != unique; ++it)
    {
      lists.Items[write++] = *it;
    }
    offsets[v + 1] = write;
  }
  lists.Items.resize(static_cast<size_t>(write));
  lists.Offsets = offsets;
  return lists;
}

VertexLists VertexTriangles(Index numberOfPoints, const Triangles& triangles)
{
  std::vector<std::pair<Index, Index>> pairs;
  pairs.reserve(static_cast<size_t>(3 * triangles.rows()));
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      pairs.emplace_back(triangles(t, k), t);
    }
  }
  return Compress(numberOfPoints, pairs);
}

void PlaceAtVertex(const Triangles& triangles, const VertexLists& vertexTriangles, Index vertex,
  Index& triangle, Eigen::Vector3d& barycentric)
{
  triangle = vertexTriangles.Items[vertexTriangles.Begin(vertex)];
  for (int corner = 0; corner < 3; ++corner)
  {
    barycentric[corner] = triangles(triangle, corner) == vertex ? 1.0 : 0.0;
  }
}
}
