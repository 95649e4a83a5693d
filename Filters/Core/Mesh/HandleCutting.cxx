#include "HandleCutting.h"

#include "MeshEdges.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
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
/// base points, round after round until none finds a shorter loop.
constexpr size_t kLoopBasePoints = 32;
constexpr int kLoopRounds = 4;

struct SurfaceEdge
{
  Index A, B;                 ///< end points
  Index TriangleA, TriangleB; ///< its two triangles
  double Length;
};

// A closed manifold surface's edges, each with its two triangles, and each vertex's edges.
struct EdgeGraph
{
  std::vector<SurfaceEdge> Edges;
  std::vector<Index> Offsets, Incident; ///< the edges of vertex v: Incident[Offsets[v] .. Offsets[v + 1])
  double LongestEdge = 0;

  EdgeGraph(const Points& points, const Triangles& triangles)
  {
    const std::vector<char> valid = ValidTriangles(triangles, points.rows());
    const std::vector<HalfEdge> halfEdges = SortedHalfEdges(triangles, valid, points.rows());
    ForEachEdge(halfEdges, [&](size_t begin, size_t end) {
      if (end - begin == 2)
      {
        const HalfEdge& h = halfEdges[begin];
        this->Edges.push_back({ h.Low, h.High, h.Triangle, halfEdges[begin + 1].Triangle,
          (points.row(h.Low) - points.row(h.High)).norm() });
      }
    });
    this->Offsets.assign(static_cast<size_t>(points.rows()) + 1, 0);
    for (const SurfaceEdge& e : this->Edges)
    {
      ++this->Offsets[e.A + 1];
      ++this->Offsets[e.B + 1];
      this->LongestEdge = std::max(this->LongestEdge, e.Length);
    }
    for (size_t v = 1; v < this->Offsets.size(); ++v)
    {
      this->Offsets[v] += this->Offsets[v - 1];
    }
    this->Incident.resize(static_cast<size_t>(this->Offsets.back()));
    std::vector<Index> fill(this->Offsets.begin(), this->Offsets.end() - 1);
    for (size_t e = 0; e < this->Edges.size(); ++e)
    {
      this->Incident[fill[this->Edges[e].A]++] = static_cast<Index>(e);
      this->Incident[fill[this->Edges[e].B]++] = static_cast<Index>(e);
    }
  }

  Index Other(Index e, Index v) const { return this->Edges[e].A == v ? this->Edges[e].B : this->Edges[e].A; }
};

// Up to 128 classes of cohomology, one bit each (kMaximumHandleCuts handles: genus 64).
struct Classes
{
  std::uint64_t Bits[2] = { 0, 0 };
  Classes operator^(const Classes& other) const
  {
    Classes sum;
    sum.Bits[0] = this->Bits[0] ^ other.Bits[0];
    sum.Bits[1] = this->Bits[1] ^ other.Bits[1];
    return sum;
  }
  bool Any() const { return this->Bits[0] != 0 || this->Bits[1] != 0; }
  void Flip(size_t k) { this->Bits[k / 64] ^= std::uint64_t(1) << (k % 64); }
};

// Per edge, which of a basis of the surface's cocycles it crosses. A cycle of edges separates
// the surface if and only if it crosses every cocycle of the basis an even number of times
// (its homology class is zero), so the XOR of its edges' classes tells, with no search of
// the rest of the surface. The basis: a spanning tree of the edges (by breadth), a spanning
// tree of the dual graph of the other edges, and for each of the 2 g edges left in neither,
// the dual cycle it closes (Erickson & Whittlesey's tree-cotree decomposition).
std::vector<Classes> CocycleClasses(const EdgeGraph& graph, Index points, Index triangles)
{
  std::vector<char> inTree(graph.Edges.size(), 0), reached(static_cast<size_t>(points), 0);
  std::vector<Index> queue{ 0 };
  reached[0] = 1;
  for (size_t q = 0; q < queue.size(); ++q)
  {
    for (Index k = graph.Offsets[queue[q]]; k < graph.Offsets[queue[q] + 1]; ++k)
    {
      const Index e = graph.Incident[k], w = graph.Other(e, queue[q]);
      if (!reached[w])
      {
        reached[w] = 1;
        inTree[e] = 1;
        queue.push_back(w);
      }
    }
  }
  // The dual tree, rooted at triangle 0: each triangle's parent triangle and the edge between.
  std::vector<std::vector<std::pair<Index, Index>>> dualNeighbours(static_cast<size_t>(triangles));
  for (size_t e = 0; e < graph.Edges.size(); ++e)
  {
    if (!inTree[e])
    {
      dualNeighbours[graph.Edges[e].TriangleA].emplace_back(graph.Edges[e].TriangleB, static_cast<Index>(e));
      dualNeighbours[graph.Edges[e].TriangleB].emplace_back(graph.Edges[e].TriangleA, static_cast<Index>(e));
    }
  }
  std::vector<Index> parentEdge(static_cast<size_t>(triangles), -1), depth(static_cast<size_t>(triangles), -1);
  std::vector<char> inCotree(graph.Edges.size(), 0);
  queue.assign(1, 0);
  depth[0] = 0;
  for (size_t q = 0; q < queue.size(); ++q)
  {
    for (const auto& [t, e] : dualNeighbours[queue[q]])
    {
      if (depth[t] < 0)
      {
        depth[t] = depth[queue[q]] + 1;
        parentEdge[t] = e;
        inCotree[e] = 1;
        queue.push_back(t);
      }
    }
  }
  auto parentOf = [&](Index t) {
    const SurfaceEdge& e = graph.Edges[parentEdge[t]];
    return e.TriangleA == t ? e.TriangleB : e.TriangleA;
  };
  std::vector<Classes> classes(graph.Edges.size());
  size_t generator = 0;
  for (size_t e = 0; e < graph.Edges.size() && generator < 128; ++e)
  {
    if (inTree[e] || inCotree[e])
    {
      continue;
    }
    // The dual cycle: this edge and the dual tree path between its two triangles.
    classes[e].Flip(generator);
    Index a = graph.Edges[e].TriangleA, b = graph.Edges[e].TriangleB;
    while (a != b)
    {
      Index& deeper = depth[a] >= depth[b] ? a : b;
      classes[parentEdge[deeper]].Flip(generator);
      deeper = parentOf(deeper);
    }
    ++generator;
  }
  return classes;
}

// Shortest paths from a base point within a bound, with each reached point's cohomology
// classes along its path; buffers kept between searches, reset only where they were used.
class BoundedSearch
{
public:
  BoundedSearch(const Points& points, const EdgeGraph& graph, const std::vector<Classes>& classes)
    : Positions(points)
    , Graph(graph)
    , EdgeClasses(classes)
    , Distance(static_cast<size_t>(points.rows()), std::numeric_limits<double>::infinity())
    , ParentEdge(static_cast<size_t>(points.rows()), -1)
    , PathClasses(static_cast<size_t>(points.rows()))
  {
  }

  // The shortest non-separating loop through `root` shorter than `bound`: a tree path out, a
  // non-tree edge whose loop has a class other than zero, a tree path back (see the header).
  SurfaceLoop LoopThrough(Index root, double bound)
  {
    this->Reset();
    // A loop root -> u -> v -> root of length L has d(u) <= d(v) + |uv| and the other way
    // round, so neither end is farther than (L + |uv|) / 2: the search stops there.
    this->Grow(root, 0.5 * (bound + this->Graph.LongestEdge));
    double best = bound;
    Index bestEdge = -1;
    for (Index v : this->Reached)
    {
      for (Index k = this->Graph.Offsets[v]; k < this->Graph.Offsets[v + 1]; ++k)
      {
        const Index e = this->Graph.Incident[k], w = this->Graph.Other(e, v);
        if (w < v || this->ParentEdge[v] == e || this->ParentEdge[w] == e)
        {
          continue; // each edge once; tree edges close no loop
        }
        const double length = this->Distance[v] + this->Graph.Edges[e].Length + this->Distance[w];
        if (length < best && (this->PathClasses[v] ^ this->PathClasses[w] ^ this->EdgeClasses[e]).Any())
        {
          best = length;
          bestEdge = e;
        }
      }
    }
    SurfaceLoop loop;
    if (bestEdge >= 0)
    {
      loop.Vertices = this->TreeLoop(this->Graph.Edges[bestEdge].A, this->Graph.Edges[bestEdge].B);
      for (size_t i = 0; i < loop.Vertices.size(); ++i)
      {
        loop.Length += (this->Positions.row(loop.Vertices[i]) -
          this->Positions.row(loop.Vertices[(i + 1) % loop.Vertices.size()])).norm();
      }
    }
    return loop;
  }

private:
  void Reset()
  {
    for (Index v : this->Reached)
    {
      this->Distance[v] = std::numeric_limits<double>::infinity();
      this->ParentEdge[v] = -1;
      this->PathClasses[v] = Classes();
    }
    this->Reached.clear();
  }

  // Dijkstra from `root`, to the points within `reach`.
  void Grow(Index root, double reach)
  {
    using Entry = std::pair<double, Index>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    this->Distance[root] = 0;
    this->Reached.push_back(root);
    queue.emplace(0.0, root);
    while (!queue.empty())
    {
      const auto [distance, v] = queue.top();
      queue.pop();
      if (distance > this->Distance[v])
      {
        continue;
      }
      for (Index k = this->Graph.Offsets[v]; k < this->Graph.Offsets[v + 1]; ++k)
      {
        const Index e = this->Graph.Incident[k], w = this->Graph.Other(e, v);
        const double through = distance + this->Graph.Edges[e].Length;
        if (through < this->Distance[w] && through <= reach)
        {
          if (!std::isfinite(this->Distance[w]))
          {
            this->Reached.push_back(w);
          }
          this->Distance[w] = through;
          this->ParentEdge[w] = e;
          this->PathClasses[w] = this->PathClasses[v] ^ this->EdgeClasses[e];
          queue.emplace(through, w);
        }
      }
    }
  }

  // The cycle of tree paths from the lowest common ancestor of a and b down to each, closed
  // by the edge (a, b).
  std::vector<Index> TreeLoop(Index a, Index b) const
  {
    auto parent = [&](Index v) {
      return this->ParentEdge[v] < 0 ? Index(-1) : this->Graph.Other(this->ParentEdge[v], v);
    };
    std::vector<Index> fromA, fromB;
    for (Index v = a; v >= 0; v = parent(v))
    {
      fromA.push_back(v);
    }
    for (Index v = b; v >= 0; v = parent(v))
    {
      fromB.push_back(v);
    }
    // Both end at the root: drop their shared part but the ancestor itself.
    while (fromA.size() > 1 && fromB.size() > 1 && fromA[fromA.size() - 2] == fromB[fromB.size() - 2])
    {
      fromA.pop_back();
      fromB.pop_back();
    }
    fromB.pop_back(); // the ancestor, kept in fromA
    std::vector<Index> loop(fromA.rbegin(), fromA.rend()); // ancestor ... a
    loop.insert(loop.end(), fromB.begin(), fromB.end());   // b ... below the ancestor
    return loop;
  }

  const Points& Positions;
  const EdgeGraph& Graph;
  const std::vector<Classes>& EdgeClasses;
  std::vector<double> Distance;
  std::vector<Index> ParentEdge;
  std::vector<Classes> PathClasses;
  std::vector<Index> Reached;
};
}

SurfaceLoop ShortNonSeparatingLoop(const Points& points, const Triangles& triangles)
{
  SurfaceLoop best;
  if (points.rows() == 0)
  {
    return best;
  }
  const EdgeGraph graph(points, triangles);
  const std::vector<Classes> classes = CocycleClasses(graph, points.rows(), triangles.rows());
  BoundedSearch search(points, graph, classes);
  std::vector<char> tried(static_cast<size_t>(points.rows()), 0);
  auto tryRoot = [&](Index root) {
    if (tried[root])
    {
      return false;
    }
    tried[root] = 1;
    const double bound = best.Vertices.empty() ? std::numeric_limits<double>::infinity() : best.Length;
    SurfaceLoop loop = search.LoopThrough(root, bound);
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
  for (int k = 0; k < kMaximumSpreadBasePoints; ++k)
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
