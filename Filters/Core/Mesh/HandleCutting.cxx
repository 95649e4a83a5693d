#include "HandleCutting.h"

#include "MeshAdjacency.h"
#include "MeshEdges.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

namespace mobius
{
namespace
{
/// Base points spread over the surface cover it until every point is within this share of
/// the best loop's length of one: a base point within d of the shortest loop finds a loop at
/// most 2 d longer (out to it, around, back), which then goes on to the loop phase. A fused
/// hand's tube (CGAL's man, 0.13 sqrt(area) around) was missed with 8 base points, which
/// found a loop around the upper arm (0.24) first.
constexpr double kCoverShare = 1.0 / 6.0;
/// ... at most this many (a handle much thinner than the surface is large, such as a
/// scan's noise tunnel, is then found through the loop phase from a longer loop across it).
constexpr int kMaximumSpreadBasePoints = 256;
/// The loop phase: points evenly spread along the best loop (at most this many) are tried as
/// base points, round after round until none finds a shorter loop. The searches are bounded
/// by the best loop's length.
constexpr size_t kLoopBasePoints = 32;
constexpr int kLoopRounds = 4;

struct SurfaceEdge
{
  Index A, B;                 ///< end points
  Index TriangleA, TriangleB; ///< its two triangles
  double Length;
};

// Every edge of a closed manifold surface with its two triangles.
std::vector<SurfaceEdge> ClosedSurfaceEdges(const Points& points, const Triangles& triangles)
{
  const std::vector<char> valid = ValidTriangles(triangles, points.rows());
  const std::vector<HalfEdge> halfEdges = SortedHalfEdges(triangles, valid, points.rows());
  std::vector<SurfaceEdge> edges;
  ForEachEdge(halfEdges, [&](size_t begin, size_t end) {
    if (end - begin == 2)
    {
      const HalfEdge& h = halfEdges[begin];
      edges.push_back({ h.Low, h.High, h.Triangle, halfEdges[begin + 1].Triangle,
        (points.row(h.Low) - points.row(h.High)).norm() });
    }
  });
  return edges;
}

struct ShortestPathTree
{
  std::vector<double> Distance;
  std::vector<Index> Parent; ///< -1 at the root
};

// Shortest paths along edges from `root`, to the points within `radius` (the others keep an
// infinite distance).
ShortestPathTree ShortestPaths(const Points& points, const VertexLists& neighbours, Index root, double radius)
{
  const Index n = points.rows();
  ShortestPathTree tree{ std::vector<double>(static_cast<size_t>(n), std::numeric_limits<double>::infinity()),
    std::vector<Index>(static_cast<size_t>(n), -1) };
  using Entry = std::pair<double, Index>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  tree.Distance[root] = 0;
  queue.emplace(0.0, root);
  while (!queue.empty())
  {
    const auto [distance, v] = queue.top();
    queue.pop();
    if (distance > tree.Distance[v])
    {
      continue;
    }
    for (Index k = neighbours.Begin(v); k < neighbours.End(v); ++k)
    {
      const Index w = neighbours.Items[k];
      const double through = distance + (points.row(v) - points.row(w)).norm();
      if (through < tree.Distance[w] && through <= radius)
      {
        tree.Distance[w] = through;
        tree.Parent[w] = v;
        queue.emplace(through, w);
      }
    }
  }
  return tree;
}

// The cycle of tree paths from the lowest common ancestor of a and b down to each, closed by
// the edge (a, b).
std::vector<Index> TreeLoop(const ShortestPathTree& tree, Index a, Index b)
{
  std::vector<char> aboveA(tree.Parent.size(), 0);
  for (Index v = a; v >= 0; v = tree.Parent[v])
  {
    aboveA[v] = 1;
  }
  std::vector<Index> fromB;
  Index ancestor = b;
  for (; !aboveA[ancestor]; ancestor = tree.Parent[ancestor])
  {
    fromB.push_back(ancestor);
  }
  std::vector<Index> loop;
  for (Index v = a; v != ancestor; v = tree.Parent[v])
  {
    loop.push_back(v);
  }
  loop.push_back(ancestor);
  std::reverse(loop.begin(), loop.end()); // ancestor ... a
  loop.insert(loop.end(), fromB.begin(), fromB.end()); // then b ... up to below the ancestor
  return loop;
}

// The shortest non-separating loop through `root` (see the header) if it is shorter than
// `bound`. Only the edges whose loops are shorter than the bound need their true lengths and
// order: both their ends are within the bound of the root, so the paths stop there, and the
// other edges go into the dual tree first, in any order.
SurfaceLoop LoopThrough(const Points& points, const Triangles& triangles,
  const VertexLists& neighbours, const std::vector<SurfaceEdge>& edges, Index root, double bound)
{
  const ShortestPathTree tree = ShortestPaths(points, neighbours, root, bound);
  UnionFind dual(triangles.rows());
  std::vector<std::pair<double, Index>> cotreeCandidates;
  for (size_t e = 0; e < edges.size(); ++e)
  {
    const SurfaceEdge& edge = edges[e];
    const double length = tree.Distance[edge.A] + edge.Length + tree.Distance[edge.B];
    if (tree.Parent[edge.A] == edge.B || tree.Parent[edge.B] == edge.A)
    {
      continue;
    }
    if (length < bound)
    {
      cotreeCandidates.emplace_back(length, static_cast<Index>(e));
    }
    else
    {
      dual.Union(edge.TriangleA, edge.TriangleB);
    }
  }
  // Longest loops first into the dual tree: what is left, in neither tree, closes the
  // non-separating loops, the shortest of which is the answer.
  std::sort(cotreeCandidates.begin(), cotreeCandidates.end(), std::greater<>());
  SurfaceLoop best;
  Index bestEdge = -1;
  for (const auto& candidate : cotreeCandidates)
  {
    const Index e = candidate.second;
    const Index a = dual.Find(edges[e].TriangleA), b = dual.Find(edges[e].TriangleB);
    if (a != b)
    {
      dual.Union(a, b);
    }
    else
    {
      bestEdge = e; // sorted longest first: the last one left is the shortest
    }
  }
  if (bestEdge >= 0)
  {
    best.Vertices = TreeLoop(tree, edges[bestEdge].A, edges[bestEdge].B);
    // The loop's own length (the tree paths from the ancestor, not from the root).
    best.Length = 0;
    for (size_t i = 0; i < best.Vertices.size(); ++i)
    {
      best.Length += (points.row(best.Vertices[i]) -
        points.row(best.Vertices[(i + 1) % best.Vertices.size()])).norm();
    }
  }
  return best;
}

}

SurfaceLoop ShortNonSeparatingLoop(const Points& points, const Triangles& triangles)
{
  const VertexLists neighbours = VertexNeighbors(points.rows(), triangles);
  const std::vector<SurfaceEdge> edges = ClosedSurfaceEdges(points, triangles);
  SurfaceLoop best;
  std::vector<char> tried(static_cast<size_t>(points.rows()), 0);
  auto tryRoot = [&](Index root) {
    if (tried[root])
    {
      return false;
    }
    tried[root] = 1;
    const double bound = best.Vertices.empty() ? std::numeric_limits<double>::infinity() : best.Length;
    SurfaceLoop loop = LoopThrough(points, triangles, neighbours, edges, root, bound);
    const bool shorter = !loop.Vertices.empty() && loop.Length < bound;
    if (shorter)
    {
      best = std::move(loop);
    }
    return shorter;
  };
  // Base points in farthest-point order (in space) from the point farthest from the
  // centroid, until they cover the surface (kCoverShare).
  const Eigen::RowVector3d centroid = points.colwise().mean();
  Eigen::VectorXd nearest = (points.rowwise() - centroid).rowwise().squaredNorm();
  for (int k = 0; k < kMaximumSpreadBasePoints && points.rows() > 0; ++k)
  {
    Index root = 0;
    const double farthest = std::sqrt(nearest.maxCoeff(&root));
    if (!best.Vertices.empty() && farthest < kCoverShare * best.Length)
    {
      break;
    }
    tryRoot(root);
    const Eigen::RowVector3d chosen = points.row(root);
    nearest = nearest.cwiseMin((points.rowwise() - chosen).rowwise().squaredNorm());
  }
  // Points of the best loop as base points: one of them may lie on a shorter loop.
  for (int round = 0; round < kLoopRounds && !best.Vertices.empty(); ++round)
  {
    const std::vector<Index> loop = best.Vertices;
    bool improved = false;
    const size_t step = std::max<size_t>(1, loop.size() / kLoopBasePoints);
    for (size_t k = 0; k < loop.size(); k += step)
    {
      improved = tryRoot(loop[k]) || improved;
    }
    if (!improved)
    {
      break;
    }
  }
  return best;
}
}
