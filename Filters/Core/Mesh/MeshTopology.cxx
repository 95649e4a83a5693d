#include "MeshTopology.h"

#include "MeshEdges.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <sstream>
#include <unordered_map>

namespace mobius
{
namespace
{
double TriangleDoubleArea(const Points& points, Index a, Index b, Index c)
{
  const Eigen::Vector3d pa = points.row(a), pb = points.row(b), pc = points.row(c);
  return (pb - pa).cross(pc - pa).norm();
}

// Drops the points no triangle uses and renumbers; fills provenance.PointSource.
void CompactPoints(Points& points, Triangles& triangles, MeshProvenance& provenance)
{
  std::vector<Index> newIndex(static_cast<size_t>(points.rows()), -1);
  std::vector<Index> source;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      Index& v = triangles(t, k);
      if (newIndex[v] < 0)
      {
        newIndex[v] = static_cast<Index>(source.size());
        source.push_back(v);
      }
      v = newIndex[v];
    }
  }
  Points compacted(static_cast<Index>(source.size()), 3);
  for (size_t i = 0; i < source.size(); ++i)
  {
    compacted.row(static_cast<Index>(i)) = points.row(source[i]);
  }
  points.swap(compacted);
  std::vector<Index> composed(source.size());
  for (size_t i = 0; i < source.size(); ++i)
  {
    composed[i] = provenance.PointSource.empty() ? source[i] : provenance.PointSource[source[i]];
  }
  provenance.PointSource.swap(composed);
}

Triangles SelectRows(const Triangles& triangles, const std::vector<Index>& rows)
{
  Triangles selected(static_cast<Index>(rows.size()), 3);
  for (size_t i = 0; i < rows.size(); ++i)
  {
    selected.row(static_cast<Index>(i)) = triangles.row(rows[i]);
  }
  return selected;
}
}

bool MeshTopologyReport::IsClosedManifold() const
{
  return this->BoundaryEdges == 0 && this->NonManifoldEdges == 0 &&
    this->NonManifoldVertices == 0;
}

bool MeshTopologyReport::IsTopologicalSphere() const
{
  return this->NumberOfTriangles > 0 && this->NonFinitePoints == 0 &&
    this->InvalidTriangles == 0 && this->RepeatedVertexTriangles == 0 &&
    this->DuplicateTriangles == 0 && this->UnusedPoints == 0 &&
    this->IsClosedManifold() &&
    this->InconsistentlyOrientedEdges == 0 && this->ConnectedComponents == 1 &&
    this->Genus == 0;
}

namespace
{
Index CountNonFinitePoints(const Points& points)
{
  Index count = 0;
  for (Index i = 0; i < points.rows(); ++i)
  {
    count += points.row(i).allFinite() ? 0 : 1;
  }
  return count;
}

// Exact duplicates: sort the point indices by coordinates, compare neighbours.
Index CountDuplicatePoints(const Points& points)
{
  std::vector<Index> order(static_cast<size_t>(points.rows()));
  std::iota(order.begin(), order.end(), Index(0));
  auto lexicographic = [&](Index a, Index b) {
    for (int k = 0; k < 3; ++k)
    {
      if (points(a, k) != points(b, k))
      {
        return points(a, k) < points(b, k);
      }
    }
    return false;
  };
  std::sort(order.begin(), order.end(), lexicographic);
  Index count = 0;
  for (size_t i = 1; i < order.size(); ++i)
  {
    count += points.row(order[i]) == points.row(order[i - 1]) ? 1 : 0;
  }
  return count;
}

// Numerically zero: twice the area is at rounding level next to the longest edge squared
// (a needle of 0.01 degrees is still 1e-4 here; only collinear points get this low).
bool HasZeroArea(const Points& points, Index a, Index b, Index c)
{
  const double longest = std::max({ (points.row(a) - points.row(b)).squaredNorm(),
    (points.row(b) - points.row(c)).squaredNorm(),
    (points.row(c) - points.row(a)).squaredNorm() });
  const double doubleArea = TriangleDoubleArea(points, a, b, c);
  return std::isfinite(doubleArea) && doubleArea <= 1e-14 * longest;
}

// Counts the invalid, repeated-vertex and zero-area triangles into the report, marks the
// points the valid ones use and returns how many are valid.
Index ClassifyTriangles(const Points& points, const Triangles& triangles,
  const std::vector<char>& valid, std::vector<char>& used, MeshTopologyReport& report)
{
  const Index n = points.rows();
  used.assign(static_cast<size_t>(n), 0);
  Index validCount = 0;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    const Index a = triangles(t, 0), b = triangles(t, 1), c = triangles(t, 2);
    const bool inRange = a >= 0 && b >= 0 && c >= 0 && a < n && b < n && c < n;
    if (!inRange)
    {
      ++report.InvalidTriangles;
      continue;
    }
    if (!valid[t])
    {
      ++report.RepeatedVertexTriangles;
      continue;
    }
    ++validCount;
    used[a] = used[b] = used[c] = 1;
    report.ZeroAreaTriangles += HasZeroArea(points, a, b, c) ? 1 : 0;
  }
  return validCount;
}

// A face listed twice (either way round) makes its edges non-manifold, and a single
// triangle closed by FillHoles becomes two triangles on the same points (a "pillow" with
// no inside): named as what they are rather than only through their edges.
Index CountDuplicateTriangles(const Triangles& triangles, const std::vector<char>& valid, Index n)
{
  using Corners = std::array<Index, 3>;
  auto produceCorners = [&](auto emit) {
    for (Index t = 0; t < triangles.rows(); ++t)
    {
      if (valid[t])
      {
        Corners sorted = { triangles(t, 0), triangles(t, 1), triangles(t, 2) };
        std::sort(sorted.begin(), sorted.end());
        emit(sorted);
      }
    }
  };
  const std::vector<Corners> corners = BucketSorted<Corners>(
    n, produceCorners, [](const Corners& c) { return c[0]; },
    [](const Corners& x, const Corners& y) { return x[1] != y[1] ? x[1] < y[1] : x[2] < y[2]; });
  Index count = 0;
  for (size_t i = 1; i < corners.size(); ++i)
  {
    count += corners[i] == corners[i - 1] ? 1 : 0;
  }
  return count;
}

// Edges, boundary, non-manifold and inconsistently oriented edges, and boundary loops.
void CountEdges(const std::vector<HalfEdge>& halfEdges, MeshTopologyReport& report)
{
  ForEachEdge(halfEdges, [&](size_t begin, size_t end) {
    ++report.Edges;
    const size_t sides = end - begin;
    if (sides == 1)
    {
      ++report.BoundaryEdges;
    }
    else if (sides > 2)
    {
      ++report.NonManifoldEdges;
    }
    else if (halfEdges[begin].From == halfEdges[begin + 1].From)
    {
      ++report.InconsistentlyOrientedEdges;
    }
  });
  std::vector<std::vector<Index>> loops;
  std::vector<char> closed;
  TraceBoundaryLoops(halfEdges, loops, closed);
  report.BoundaryLoops = static_cast<Index>(loops.size());
}

// Components of the used vertices joined by valid triangles.
Index CountComponents(
  const Triangles& triangles, const std::vector<char>& valid, const std::vector<char>& used)
{
  const Index n = static_cast<Index>(used.size());
  UnionFind components(n);
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    if (valid[t])
    {
      components.Union(triangles(t, 0), triangles(t, 1));
      components.Union(triangles(t, 0), triangles(t, 2));
    }
  }
  Index count = 0;
  for (Index i = 0; i < n; ++i)
  {
    count += (used[i] && components.Find(i) == i) ? 1 : 0;
  }
  return count;
}

// Vertex fans: the triangles around v, joined when they share an edge (v, w). A manifold
// vertex has one fan; two cones touching at their tips have two. The triangles' corners
// (3 t + k) are the elements; every edge joins the corners of its triangles at each of its
// two ends, so each fan of v ends up as one set of v's corners.
Index CountNonManifoldVertices(const Triangles& triangles, const std::vector<char>& valid,
  const std::vector<HalfEdge>& halfEdges, Index n)
{
  UnionFind fans(3 * triangles.rows());
  auto corner = [&](Index t, Index v) {
    return 3 * t + (triangles(t, 0) == v ? 0 : triangles(t, 1) == v ? 1 : 2);
  };
  ForEachEdge(halfEdges, [&](size_t begin, size_t end) {
    const HalfEdge& first = halfEdges[begin];
    for (size_t i = begin + 1; i < end; ++i)
    {
      fans.Union(corner(halfEdges[i].Triangle, first.Low), corner(first.Triangle, first.Low));
      fans.Union(corner(halfEdges[i].Triangle, first.High), corner(first.Triangle, first.High));
    }
  });
  std::vector<Index> fansAt(static_cast<size_t>(n), 0);
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; valid[t] && k < 3; ++k)
    {
      fansAt[triangles(t, k)] += fans.Find(3 * t + k) == 3 * t + k ? 1 : 0;
    }
  }
  return std::count_if(fansAt.begin(), fansAt.end(), [](Index f) { return f > 1; });
}
}

MeshTopologyReport AnalyzeMeshTopology(const Points& points, const Triangles& triangles)
{
  MeshTopologyReport report;
  const Index n = points.rows();
  report.NumberOfPoints = n;
  report.NumberOfTriangles = triangles.rows();
  report.NonFinitePoints = CountNonFinitePoints(points);
  report.DuplicatePoints = CountDuplicatePoints(points);

  const std::vector<char> valid = ValidTriangles(triangles, n);
  std::vector<char> used;
  const Index validCount = ClassifyTriangles(points, triangles, valid, used, report);
  report.DuplicateTriangles = CountDuplicateTriangles(triangles, valid, n);
  const Index usedCount = std::count(used.begin(), used.end(), 1);
  report.UnusedPoints = n - usedCount;

  const std::vector<HalfEdge> halfEdges = SortedHalfEdges(triangles, valid, n);
  CountEdges(halfEdges, report);
  report.ConnectedComponents = CountComponents(triangles, valid, used);
  report.NonManifoldVertices = CountNonManifoldVertices(triangles, valid, halfEdges, n);

  report.EulerCharacteristic = usedCount - report.Edges + validCount;
  if (validCount > 0 && report.IsClosedManifold() && report.InconsistentlyOrientedEdges == 0 &&
    report.ConnectedComponents == 1)
  {
    report.Genus = static_cast<int>((2 - report.EulerCharacteristic) / 2);
  }
  return report;
}

std::string DescribeTopologyProblems(const MeshTopologyReport& r)
{
  std::vector<std::string> problems;
  auto add = [&](Index count, const char* singular, const char* plural) {
    if (count > 0)
    {
      std::ostringstream s;
      s << count << " " << (count == 1 ? singular : plural);
      problems.push_back(s.str());
    }
  };
  if (r.NumberOfTriangles == 0)
  {
    problems.push_back("no triangles");
  }
  add(r.NonFinitePoints, "point with a NaN or infinite coordinate",
    "points with NaN or infinite coordinates");
  add(r.InvalidTriangles, "triangle with a point index out of range",
    "triangles with point indices out of range");
  add(r.RepeatedVertexTriangles, "triangle naming the same point twice",
    "triangles naming the same point twice");
  add(r.DuplicateTriangles, "duplicate triangle (the same three points as another triangle)",
    "duplicate triangles (the same three points as other triangles)");
  add(r.UnusedPoints, "point not used by any triangle", "points not used by any triangle");
  if (r.BoundaryEdges > 0)
  {
    std::ostringstream s;
    s << r.BoundaryLoops << " boundary loop" << (r.BoundaryLoops == 1 ? "" : "s")
      << " (holes) made of " << r.BoundaryEdges << " boundary edges";
    if (r.DuplicatePoints > 0)
    {
      s << " (" << r.DuplicatePoints << " points are exact duplicates: a triangle soup?)";
    }
    problems.push_back(s.str());
  }
  add(r.NonManifoldEdges, "non-manifold edge (more than two triangles)",
    "non-manifold edges (more than two triangles)");
  add(r.NonManifoldVertices, "non-manifold vertex (triangles around it form several fans)",
    "non-manifold vertices (triangles around them form several fans)");
  add(r.InconsistentlyOrientedEdges, "edge where the two triangles' orientations disagree",
    "edges where the two triangles' orientations disagree");
  if (r.ConnectedComponents > 1)
  {
    add(r.ConnectedComponents, "connected component", "connected components");
  }
  if (r.Genus > 0)
  {
    std::ostringstream s;
    s << "genus " << r.Genus << " (" << r.Genus << (r.Genus == 1 ? " handle" : " handles")
      << "; only genus 0 maps to the sphere)";
    problems.push_back(s.str());
  }
  std::string joined;
  for (const auto& p : problems)
  {
    joined += (joined.empty() ? "" : "; ") + p;
  }
  return joined;
}

MeshProvenance IdentityProvenance(Index points, Index triangles)
{
  MeshProvenance identity;
  identity.PointSource.resize(static_cast<size_t>(points));
  std::iota(identity.PointSource.begin(), identity.PointSource.end(), Index(0));
  identity.TriangleSource.resize(static_cast<size_t>(triangles));
  std::iota(identity.TriangleSource.begin(), identity.TriangleSource.end(), Index(0));
  return identity;
}

void ComposeProvenance(MeshProvenance& provenance, const MeshProvenance& step)
{
  auto compose = [](const std::vector<Index>& before, const std::vector<Index>& rows) {
    std::vector<Index> composed(rows.size());
    for (size_t i = 0; i < rows.size(); ++i)
    {
      composed[i] = rows[i] >= 0 ? before[rows[i]] : -1;
    }
    return composed;
  };
  provenance.PointSource = compose(provenance.PointSource, step.PointSource);
  provenance.TriangleSource = compose(provenance.TriangleSource, step.TriangleSource);
}

MeshProvenance MergeDuplicatePoints(Points& points, Triangles& triangles)
{
  const Index n = points.rows();
  std::vector<Index> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), Index(0));
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) {
    for (int k = 0; k < 3; ++k)
    {
      if (points(a, k) != points(b, k))
      {
        return points(a, k) < points(b, k);
      }
    }
    return false;
  });
  // Each point's representative is the lowest index with its coordinates (stable sort puts
  // it first in its run). NaN coordinates never compare equal, so such points stay apart.
  std::vector<Index> representative(static_cast<size_t>(n));
  for (size_t i = 0; i < order.size(); ++i)
  {
    const bool same = i > 0 && points.row(order[i]) == points.row(order[i - 1]);
    representative[order[i]] = same ? representative[order[i - 1]] : order[i];
  }
  MeshProvenance provenance;
  std::vector<Index> newIndex(static_cast<size_t>(n), -1);
  for (Index i = 0; i < n; ++i)
  {
    if (representative[i] == i)
    {
      newIndex[i] = static_cast<Index>(provenance.PointSource.size());
      provenance.PointSource.push_back(i);
    }
  }
  Points merged(static_cast<Index>(provenance.PointSource.size()), 3);
  for (size_t i = 0; i < provenance.PointSource.size(); ++i)
  {
    merged.row(static_cast<Index>(i)) = points.row(provenance.PointSource[i]);
  }
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    bool inRange = true;
    for (int k = 0; k < 3; ++k)
    {
      const Index v = triangles(t, k);
      inRange = inRange && v >= 0 && v < n;
      triangles(t, k) = (v >= 0 && v < n) ? newIndex[representative[v]] : v;
    }
    const Index a = triangles(t, 0), b = triangles(t, 1), c = triangles(t, 2);
    if (!inRange || (a != b && b != c && c != a))
    {
      provenance.TriangleSource.push_back(t); // out-of-range triangles are left for Analyze
    }
  }
  triangles = SelectRows(triangles, provenance.TriangleSource);
  points.swap(merged);
  return provenance;
}

MeshProvenance CollapseZeroLengthEdges(Points& points, Triangles& triangles, Index* collapsed)
{
  const std::vector<char> valid = ValidTriangles(triangles, points.rows());
  UnionFind ends(points.rows());
  Index count = 0;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; valid[t] && k < 3; ++k)
    {
      const Index a = triangles(t, k), b = triangles(t, (k + 1) % 3);
      if (points.row(a) == points.row(b) && ends.Find(a) != ends.Find(b))
      {
        ends.Union(std::max(a, b), std::min(a, b)); // the lower number stays
        ++count;
      }
    }
  }
  MeshProvenance provenance;
  for (Index i = 0; i < points.rows(); ++i)
  {
    provenance.PointSource.push_back(i); // the merged-away points are left unused
  }
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; valid[t] && k < 3; ++k)
    {
      triangles(t, k) = ends.Find(triangles(t, k));
    }
    const Index a = triangles(t, 0), b = triangles(t, 1), c = triangles(t, 2);
    if (!valid[t] || (a != b && b != c && c != a))
    {
      provenance.TriangleSource.push_back(t); // invalid triangles are left for Analyze
    }
  }
  triangles = SelectRows(triangles, provenance.TriangleSource);
  if (collapsed)
  {
    *collapsed = count;
  }
  return provenance;
}

MeshProvenance ExtractLargestComponent(Points& points, Triangles& triangles)
{
  const std::vector<char> valid = ValidTriangles(triangles, points.rows());
  UnionFind components(points.rows());
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    if (valid[t])
    {
      components.Union(triangles(t, 0), triangles(t, 1));
      components.Union(triangles(t, 0), triangles(t, 2));
    }
  }
  std::unordered_map<Index, Index> trianglesPerComponent;
  Index largest = -1, largestCount = 0;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    if (valid[t])
    {
      const Index root = components.Find(triangles(t, 0));
      const Index count = ++trianglesPerComponent[root];
      if (count > largestCount)
      {
        largestCount = count;
        largest = root;
      }
    }
  }
  MeshProvenance provenance;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    if (valid[t] && components.Find(triangles(t, 0)) == largest)
    {
      provenance.TriangleSource.push_back(t);
    }
  }
  triangles = SelectRows(triangles, provenance.TriangleSource);
  CompactPoints(points, triangles, provenance);
  return provenance;
}

namespace
{
// A triangle across a two-triangle edge, and whether the pair currently agrees.
struct OrientationNeighbour
{
  Index Triangle;
  bool SameDirection; // both traverse the shared edge the same way: orientations disagree
  Index Low, High;    // the shared edge
};

// Triangle adjacency across two-triangle edges. On manifold edges a triangle has at most
// three neighbours: fixed slots, no list per triangle.
struct OrientationAdjacency
{
  std::vector<std::array<OrientationNeighbour, 3>> Neighbours;
  std::vector<unsigned char> Count;
};

// The largest point index used, plus one.
Index UsedPointCount(const Triangles& triangles)
{
  Index numberOfPoints = 0;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    numberOfPoints = std::max(numberOfPoints, triangles.row(t).maxCoeff() + 1);
  }
  return numberOfPoints;
}

// The adjacency of the valid triangles; false if an edge has more than two of them.
bool BuildOrientationAdjacency(const Triangles& triangles, const std::vector<char>& valid,
  Index numberOfPoints, OrientationAdjacency& adjacency)
{
  const std::vector<HalfEdge> halfEdges = SortedHalfEdges(triangles, valid, numberOfPoints);
  adjacency.Neighbours.resize(static_cast<size_t>(triangles.rows()));
  adjacency.Count.assign(static_cast<size_t>(triangles.rows()), 0);
  bool manifold = true;
  ForEachEdge(halfEdges, [&](size_t begin, size_t end) {
    if (end - begin > 2)
    {
      manifold = false;
    }
    else if (end - begin == 2 && manifold)
    {
      const HalfEdge &x = halfEdges[begin], &y = halfEdges[begin + 1];
      const bool same = x.From == y.From;
      adjacency.Neighbours[x.Triangle][adjacency.Count[x.Triangle]++] = { y.Triangle, same,
        x.Low, x.High };
      adjacency.Neighbours[y.Triangle][adjacency.Count[y.Triangle]++] = { x.Triangle, same,
        x.Low, x.High };
    }
  });
  return manifold;
}

// Breadth-first from each component's first triangle: whether to reverse each triangle (1)
// or not (0; -1 for invalid ones). A contradiction means the surface is not orientable (a
// Moebius strip, a Klein bottle): without `contradictions` that ends the search (false);
// with it, its edge is recorded and the search goes on.
bool ChooseReversals(const std::vector<char>& valid, const OrientationAdjacency& adjacency,
  std::vector<signed char>& reverse, std::vector<EdgeKey>* contradictions)
{
  reverse.assign(valid.size(), -1);
  std::vector<Index> queue;
  for (Index seed = 0; seed < static_cast<Index>(valid.size()); ++seed)
  {
    if (!valid[seed] || reverse[seed] >= 0)
    {
      continue;
    }
    reverse[seed] = 0;
    queue.assign(1, seed);
    for (size_t q = 0; q < queue.size(); ++q)
    {
      const Index t = queue[q];
      for (int i = 0; i < adjacency.Count[t]; ++i)
      {
        const OrientationNeighbour& nb = adjacency.Neighbours[t][i];
        const signed char wanted =
          static_cast<signed char>(nb.SameDirection ? 1 - reverse[t] : reverse[t]);
        if (reverse[nb.Triangle] < 0)
        {
          reverse[nb.Triangle] = wanted;
          queue.push_back(nb.Triangle);
        }
        else if (reverse[nb.Triangle] != wanted)
        {
          if (!contradictions)
          {
            return false;
          }
          contradictions->emplace_back(nb.Low, nb.High);
        }
      }
    }
  }
  return true;
}

// Reverses the triangles marked 1; returns how many.
Index ReverseMarked(const std::vector<signed char>& reverse, Triangles& triangles)
{
  Index count = 0;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    if (reverse[t] == 1)
    {
      std::swap(triangles(t, 1), triangles(t, 2));
      ++count;
    }
  }
  return count;
}
}

bool OrientConsistently(
  Triangles& triangles, Index* reversedTriangles, std::vector<EdgeKey>* disagreeing)
{
  if (reversedTriangles)
  {
    *reversedTriangles = 0;
  }
  const Index numberOfPoints = UsedPointCount(triangles);
  const std::vector<char> valid = ValidTriangles(triangles, numberOfPoints);
  OrientationAdjacency adjacency;
  std::vector<EdgeKey> contradictions;
  std::vector<signed char> reverse;
  if (!BuildOrientationAdjacency(triangles, valid, numberOfPoints, adjacency) ||
    !ChooseReversals(valid, adjacency, reverse, disagreeing ? &contradictions : nullptr))
  {
    return false;
  }
  if (disagreeing)
  {
    std::sort(contradictions.begin(), contradictions.end());
    contradictions.erase(std::unique(contradictions.begin(), contradictions.end()), contradictions.end());
    *disagreeing = std::move(contradictions);
  }
  const Index count = ReverseMarked(reverse, triangles);
  if (reversedTriangles)
  {
    *reversedTriangles = count;
  }
  return !disagreeing || disagreeing->empty();
}
}
