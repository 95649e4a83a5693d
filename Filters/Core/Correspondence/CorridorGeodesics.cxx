#include "CorridorGeodesics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mobius
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();

struct HeapEntry
{
  double Key;      // distance + straight line to the goal
  double Distance; // the distance it was pushed with, to recognize stale entries
  std::int32_t Node;
};
}

//------------------------------------------------------------------------------
void CorridorGeodesics::Build(const EdgePathGeodesics& geodesics, int steinerPoints)
{
  this->Geodesics = &geodesics;
  this->SteinerPoints = std::max(0, steinerPoints);
  const Triangles& triangles = geodesics.GetTriangles();
  const Index n = geodesics.GetNumberOfPoints();
  this->FirstVertexTriangle.assign(n + 1, 0);
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++this->FirstVertexTriangle[triangles(t, k) + 1];
    }
  }
  for (Index v = 0; v < n; ++v)
  {
    this->FirstVertexTriangle[v + 1] += this->FirstVertexTriangle[v];
  }
  this->VertexTriangle.resize(this->FirstVertexTriangle[n]);
  std::vector<std::int32_t> next(this->FirstVertexTriangle.begin(), this->FirstVertexTriangle.end() - 1);
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->VertexTriangle[next[triangles(t, k)]++] = static_cast<std::int32_t>(t);
    }
  }
}

//------------------------------------------------------------------------------
double CorridorGeodesics::Distance(Index fromVertex, Index toVertex, Workspace& workspace) const
{
  const double edgePath = this->Geodesics->Distance(fromVertex, toVertex, workspace.Edges);
  // Two vertices of one edge: the edge is the straight segment, nothing is shorter.
  if (!std::isfinite(edgePath) || this->SteinerPoints == 0 ||
    !this->Geodesics->LastPath(toVertex, workspace.Edges, workspace.Path) ||
    workspace.Path.size() < 3 || workspace.Path.front() != fromVertex)
  {
    return edgePath;
  }
  // The shortest path through the corridor's Steiner points may run along its border; the
  // corridor around that path is then searched again, while the length drops by more than
  // RoundGain.
  double best = edgePath;
  for (int round = 0; round < MaximumRounds; ++round)
  {
    this->BuildCorridor(workspace);
    const double shortened = this->Shortest(
      workspace.LocalVertex[fromVertex], workspace.LocalVertex[toVertex], workspace);
    this->ClearCorridor(workspace);
    if (!(shortened < best * (1 - RoundGain)))
    {
      break;
    }
    best = shortened;
  }
  return best;
}

//------------------------------------------------------------------------------
void CorridorGeodesics::ClearCorridor(Workspace& workspace) const
{
  const Triangles& triangles = this->Geodesics->GetTriangles();
  for (std::int32_t t : workspace.CorridorTriangles)
  {
    workspace.InCorridor[t] = 0;
    for (int k = 0; k < 3; ++k)
    {
      workspace.LocalVertex[triangles(t, k)] = -1;
    }
  }
}

//------------------------------------------------------------------------------
void CorridorGeodesics::BuildCorridor(Workspace& workspace) const
{
  const Points& points = this->Geodesics->GetPoints();
  const Triangles& triangles = this->Geodesics->GetTriangles();
  if (workspace.InCorridor.size() != static_cast<size_t>(triangles.rows()))
  {
    workspace.InCorridor.assign(triangles.rows(), 0);
    workspace.LocalVertex.assign(points.rows(), -1);
  }
  workspace.CorridorTriangles.clear();
  for (Index v : workspace.Path)
  {
    for (std::int32_t i = this->FirstVertexTriangle[v]; i < this->FirstVertexTriangle[v + 1]; ++i)
    {
      const std::int32_t t = this->VertexTriangle[i];
      if (!workspace.InCorridor[t])
      {
        workspace.InCorridor[t] = 1;
        workspace.CorridorTriangles.push_back(t);
      }
    }
  }
  // Nodes: the corridor's vertices, and SteinerPoints points on each of its edges (shared
  // by the edge's two triangles), numbered in the order met.
  const int k = this->SteinerPoints;
  const int perTriangle = 3 + 3 * k;
  workspace.Position.clear();
  workspace.LocalEdge.clear();
  workspace.TriangleNodes.clear();
  for (std::int32_t t : workspace.CorridorTriangles)
  {
    for (int c = 0; c < 3; ++c)
    {
      std::int32_t& node = workspace.LocalVertex[triangles(t, c)];
      if (node < 0)
      {
        node = static_cast<std::int32_t>(workspace.Position.size());
        workspace.Position.push_back(points.row(triangles(t, c)).transpose());
      }
      workspace.TriangleNodes.push_back(node);
    }
    for (int c = 0; c < 3; ++c)
    {
      const Index a = std::min(triangles(t, c), triangles(t, (c + 1) % 3));
      const Index b = std::max(triangles(t, c), triangles(t, (c + 1) % 3));
      const std::uint64_t key = (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b);
      const auto inserted =
        workspace.LocalEdge.emplace(key, static_cast<std::int32_t>(workspace.Position.size()));
      if (inserted.second)
      {
        for (int j = 1; j <= k; ++j)
        {
          const double s = static_cast<double>(j) / (k + 1);
          workspace.Position.push_back(
            ((1 - s) * points.row(a) + s * points.row(b)).transpose());
        }
      }
      for (int j = 0; j < k; ++j)
      {
        workspace.TriangleNodes.push_back(inserted.first->second + j);
      }
    }
  }
  // Each node's corridor triangles (compressed rows).
  const size_t nodes = workspace.Position.size();
  workspace.FirstNodeTriangle.assign(nodes + 1, 0);
  for (std::int32_t node : workspace.TriangleNodes)
  {
    ++workspace.FirstNodeTriangle[node + 1];
  }
  for (size_t u = 0; u < nodes; ++u)
  {
    workspace.FirstNodeTriangle[u + 1] += workspace.FirstNodeTriangle[u];
  }
  workspace.NodeTriangle.resize(workspace.TriangleNodes.size());
  std::vector<std::int32_t> next(
    workspace.FirstNodeTriangle.begin(), workspace.FirstNodeTriangle.end() - 1);
  for (size_t i = 0; i < workspace.TriangleNodes.size(); ++i)
  {
    workspace.NodeTriangle[next[workspace.TriangleNodes[i]]++] =
      static_cast<std::int32_t>(i / perTriangle);
  }
}

//------------------------------------------------------------------------------
double CorridorGeodesics::Shortest(std::int32_t from, std::int32_t to, Workspace& workspace) const
{
  const int perTriangle = 3 + 3 * this->SteinerPoints;
  const std::vector<Eigen::Vector3d>& position = workspace.Position;
  std::vector<double>& distance = workspace.Distance;
  distance.assign(position.size(), Infinity);
  workspace.ParentNode.assign(position.size(), -1);
  workspace.ParentTriangle.assign(position.size(), -1);
  std::vector<HeapEntry> heap;
  const auto greater = [](const HeapEntry& a, const HeapEntry& b) { return a.Key > b.Key; };
  const Eigen::Vector3d goal = position[to];
  distance[from] = 0.0;
  heap.push_back({ (position[from] - goal).norm(), 0.0, from });
  while (!heap.empty())
  {
    std::pop_heap(heap.begin(), heap.end(), greater);
    const HeapEntry entry = heap.back();
    heap.pop_back();
    if (entry.Distance > distance[entry.Node])
    {
      continue;
    }
    const std::int32_t u = entry.Node;
    if (u == to)
    {
      // The next corridor: around the corners of every triangle the path crosses.
      const Triangles& triangles = this->Geodesics->GetTriangles();
      workspace.Path.clear();
      for (std::int32_t w = to; workspace.ParentTriangle[w] >= 0; w = workspace.ParentNode[w])
      {
        const std::int32_t t = workspace.CorridorTriangles[workspace.ParentTriangle[w]];
        for (int c = 0; c < 3; ++c)
        {
          workspace.Path.push_back(triangles(t, c));
        }
      }
      return distance[u];
    }
    for (std::int32_t i = workspace.FirstNodeTriangle[u]; i < workspace.FirstNodeTriangle[u + 1]; ++i)
    {
      const std::int32_t* nodes = workspace.TriangleNodes.data() +
        static_cast<size_t>(workspace.NodeTriangle[i]) * perTriangle;
      for (int j = 0; j < perTriangle; ++j)
      {
        const std::int32_t w = nodes[j];
        const double candidate = entry.Distance + (position[u] - position[w]).norm();
        if (candidate < distance[w])
        {
          distance[w] = candidate;
          workspace.ParentNode[w] = u;
          workspace.ParentTriangle[w] = workspace.NodeTriangle[i];
          heap.push_back({ candidate + (position[w] - goal).norm(), candidate, w });
          std::push_heap(heap.begin(), heap.end(), greater);
        }
      }
    }
  }
  return Infinity;
}
}
