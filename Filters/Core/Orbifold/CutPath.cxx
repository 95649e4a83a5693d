#include "CutPath.h"

#include "MeshAdjacency.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>

namespace mobius
{
Vector EdgePathDistances(
  const Points& points, const Triangles& triangles, Index source, std::vector<Index>* previous)
{
  const Index n = points.rows();
  const VertexLists neighbors = VertexNeighbors(n, triangles);
  Vector distance = Vector::Constant(n, std::numeric_limits<double>::infinity());
  if (previous)
  {
    previous->assign(static_cast<size_t>(n), -1);
  }
  if (source < 0 || source >= n)
  {
    return distance;
  }
  using Entry = std::pair<double, Index>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  distance[source] = 0.0;
  queue.push({ 0.0, source });
  while (!queue.empty())
  {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[v])
    {
      continue; // a stale entry
    }
    for (Index k = neighbors.Begin(v); k < neighbors.End(v); ++k)
    {
      const Index w = neighbors.Items[k];
      const double candidate = d + (points.row(w) - points.row(v)).norm();
      if (candidate < distance[w])
      {
        distance[w] = candidate;
        if (previous)
        {
          (*previous)[w] = v;
        }
        queue.push({ candidate, w });
      }
    }
  }
  return distance;
}

std::vector<Index> ShortestEdgePath(
  const Points& points, const Triangles& triangles, Index from, Index to)
{
  std::vector<Index> previous;
  const Vector distance = EdgePathDistances(points, triangles, from, &previous);
  std::vector<Index> path;
  if (to < 0 || to >= points.rows() || !std::isfinite(distance[to]))
  {
    return path;
  }
  for (Index v = to; v != -1; v = previous[v])
  {
    path.push_back(v);
  }
  std::reverse(path.begin(), path.end());
  return path;
}

namespace
{
Index FarthestVertex(const Vector& distance)
{
  Index best = -1;
  for (Index v = 0; v < distance.size(); ++v)
  {
    if (std::isfinite(distance[v]) && (best < 0 || distance[v] > distance[best]))
    {
      best = v;
    }
  }
  return best;
}
}

std::pair<Index, Index> FarApartVertices(const Points& points, const Triangles& triangles)
{
  if (points.rows() < 2)
  {
    return { -1, -1 };
  }
  Index start = 0;
  points.col(0).minCoeff(&start);
  const Index a = FarthestVertex(EdgePathDistances(points, triangles, start));
  const Index b = FarthestVertex(EdgePathDistances(points, triangles, a));
  return { a, b };
}
}
