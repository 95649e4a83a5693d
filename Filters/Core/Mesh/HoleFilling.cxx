#include "HoleFilling.h"

#include "MeshAdjacency.h"
#include "MeshEdges.h"
#include "PortableMath.h"

#include <Eigen/Geometry>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace mobius
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
/// Each ring's spacing is this times the next outer ring's: a hole of n rim edges gets
/// O(n log n) points instead of the O(n^2) of a uniform fill.
constexpr double kRingGrowth = 1.25;
/// A patch never gets more points than this many times its rim's: the growth is raised
/// until it fits (only for holes of thousands of edges).
constexpr double kMaximumPointsPerRimPoint = 16;

// A patch under construction: its points' places in the disc's planar layout (the rim on
// the unit circle) and its triangles in local numbers (0 .. n-1 the rim, then the new
// points), counter-clockwise in the layout.
struct DiscLayout
{
  std::vector<Eigen::Vector2d> Planar;
  std::vector<std::array<Index, 3>> Triangles;
};

struct Ring
{
  Index First; ///< local number of its first point
  Index Count;
  std::vector<double> Angles;
};

// Zips two concentric rings into triangles: always advancing along the ring whose next point
// comes first in angle, so each triangle spans the smallest angle it can.
void ZipRings(const Ring& outer, const Ring& inner, DiscLayout& disc)
{
  // The inner ring starts at its point nearest in angle to the outer ring's first point;
  // both are then followed once around, their angles unwrapped from there.
  Index j0 = 0;
  double best = 1e300;
  for (Index j = 0; j < inner.Count; ++j)
  {
    const double d = std::abs(std::remainder(inner.Angles[j] - outer.Angles[0], 2 * kPi));
    if (d < best)
    {
      best = d;
      j0 = j;
    }
  }
  const double turns = std::round((outer.Angles[0] - inner.Angles[j0]) / (2 * kPi));
  auto angle = [](const Ring& ring, Index m, double offset) {
    return ring.Angles[m % ring.Count] + 2 * kPi * (static_cast<double>(m / ring.Count) + offset);
  };
  Index i = 0, j = 0;
  while (i < outer.Count || j < inner.Count)
  {
    const Index o = outer.First + i % outer.Count, in = inner.First + (j0 + j) % inner.Count;
    const bool advanceOuter = j >= inner.Count ||
      (i < outer.Count && angle(outer, i + 1, 0.0) <= angle(inner, j0 + j + 1, turns));
    if (advanceOuter)
    {
      disc.Triangles.push_back({ o, outer.First + (i + 1) % outer.Count, in });
      ++i;
    }
    else
    {
      disc.Triangles.push_back({ o, inner.First + (j0 + j + 1) % inner.Count, in });
      ++j;
    }
  }
}

// Rings of a disc whose rim has the given angles: radii and point counts, ring spacing
// growing by `growth` inward. Returns the number of new points.
Index PlanRings(const std::vector<double>& rimAngles, double growth, std::vector<Ring>& rings,
  std::vector<double>& radii)
{
  const Index n = static_cast<Index>(rimAngles.size());
  rings.assign(1, Ring{ 0, n, rimAngles });
  radii.assign(1, 1.0);
  double spacing = 2 * kPi / static_cast<double>(n); // rim edge over the rim's radius
  double radius = 1.0;
  Index points = n;
  while (true)
  {
    radius -= spacing * std::sqrt(3.0) / 2;
    spacing *= growth;
    const Index count = std::min(rings.back().Count,
      static_cast<Index>(std::lround(2 * kPi * radius / spacing)));
    if (radius < 0.5 * spacing || count < 3)
    {
      return points + 1; // the middle point
    }
    Ring ring{ points, count, {} };
    const double phase = rings.size() % 2 == 0 ? 0.0 : 0.5;
    for (Index k = 0; k < count; ++k)
    {
      ring.Angles.push_back(2 * kPi * (static_cast<double>(k) + phase) / static_cast<double>(count));
    }
    rings.push_back(std::move(ring));
    radii.push_back(radius);
    points += count;
  }
}

// The disc of a rim whose points sit at `rimAngles` (increasing, from 0).
DiscLayout LayOutDisc(const std::vector<double>& rimAngles)
{
  const Index n = static_cast<Index>(rimAngles.size());
  std::vector<Ring> rings;
  std::vector<double> radii;
  double growth = kRingGrowth;
  while (PlanRings(rimAngles, growth, rings, radii) >
    n + static_cast<Index>(kMaximumPointsPerRimPoint * static_cast<double>(n)))
  {
    growth *= kRingGrowth;
  }
  DiscLayout disc;
  for (size_t r = 0; r < rings.size(); ++r)
  {
    for (double angle : rings[r].Angles)
    {
      double sine, cosine; // portable: the patch, and so the map, the same on every CPU
      PortableSinCos(angle, sine, cosine);
      disc.Planar.emplace_back(radii[r] * cosine, radii[r] * sine);
    }
  }
  for (size_t r = 0; r + 1 < rings.size(); ++r)
  {
    ZipRings(rings[r], rings[r + 1], disc);
  }
  const Index middle = static_cast<Index>(disc.Planar.size());
  disc.Planar.emplace_back(0.0, 0.0);
  const Ring& last = rings.back();
  for (Index k = 0; k < last.Count; ++k)
  {
    disc.Triangles.push_back({ last.First + k, last.First + (k + 1) % last.Count, middle });
  }
  return disc;
}

// Mean-value weights of each new point's neighbours in the planar layout: sum over the
// triangles at i of tan(angle at i / 2) / |x_j - x_i| for each other corner j. They
// reproduce the layout exactly, so fairing keeps its spacing. tan(angle / 2) is
// sin / (1 + cos), from the cross and dot products without the C library's (CPU-dependent)
// trigonometry.
std::vector<std::vector<std::pair<Index, double>>> MeanValueWeights(const DiscLayout& disc, Index rim)
{
  std::vector<std::vector<std::pair<Index, double>>> weights(disc.Planar.size());
  for (const auto& triangle : disc.Triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index i = triangle[k], j = triangle[(k + 1) % 3], l = triangle[(k + 2) % 3];
      if (i < rim)
      {
        continue;
      }
      const Eigen::Vector2d a = disc.Planar[j] - disc.Planar[i], b = disc.Planar[l] - disc.Planar[i];
      const double half =
        std::abs(a.x() * b.y() - a.y() * b.x()) / (a.norm() * b.norm() + a.dot(b));
      weights[i].emplace_back(j, half / a.norm());
      weights[i].emplace_back(l, half / b.norm());
    }
  }
  return weights;
}


using SparseMatrix = Eigen::SparseMatrix<double>;

// The rows of the least squares that place a patch's new points, as coefficients of the
// unknowns (the new points, numbered from 0) and a right-hand side from the known points:
// each new point's mean-value Laplacian in the layout, and each rim point's uniform
// Laplacian over all its neighbours, old ones (`meshNeighbours`, the rim's two neighbours on
// the loop among them) and new ones.
void LaplacianRows(const DiscLayout& disc, const std::vector<Index>& loop, const Points& points,
  const VertexLists& meshNeighbours, std::vector<Eigen::Triplet<double>>& entries,
  std::vector<Eigen::RowVector3d>& rhs)
{
  const Index n = static_cast<Index>(loop.size());
  const auto weights = MeanValueWeights(disc, n);
  for (Index i = n; i < static_cast<Index>(disc.Planar.size()); ++i)
  {
    const Index row = static_cast<Index>(rhs.size());
    double total = 0;
    for (const auto& other : weights[i])
    {
      total += other.second;
    }
    Eigen::RowVector3d known = Eigen::RowVector3d::Zero();
    entries.emplace_back(row, i - n, 1.0);
    for (const auto& other : weights[i])
    {
      if (other.first >= n)
      {
        entries.emplace_back(row, other.first - n, -other.second / total);
      }
      else
      {
        known += other.second / total * points.row(loop[other.first]);
      }
    }
    rhs.push_back(known);
  }
  std::vector<std::vector<Index>> newNeighbours(static_cast<size_t>(n));
  for (const auto& triangle : disc.Triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      for (int l = 1; l < 3; ++l)
      {
        const Index i = triangle[k], j = triangle[(k + l) % 3];
        if (i < n && j >= n &&
          std::find(newNeighbours[i].begin(), newNeighbours[i].end(), j) == newNeighbours[i].end())
        {
          newNeighbours[i].push_back(j);
        }
      }
    }
  }
  for (Index i = 0; i < n; ++i)
  {
    const Index v = loop[i];
    const double degree = static_cast<double>(
      meshNeighbours.End(v) - meshNeighbours.Begin(v) + static_cast<Index>(newNeighbours[i].size()));
    const Index row = static_cast<Index>(rhs.size());
    Eigen::RowVector3d known = -points.row(v);
    for (Index k = meshNeighbours.Begin(v); k < meshNeighbours.End(v); ++k)
    {
      known += points.row(meshNeighbours.Items[k]) / degree;
    }
    for (Index j : newNeighbours[i])
    {
      entries.emplace_back(row, j - n, -1.0 / degree);
    }
    rhs.push_back(known);
  }
}

// Places the disc's new points by least squares on LaplacianRows; false if the solve fails.
bool PlaceNewPoints(const DiscLayout& disc, const std::vector<Index>& loop, const Points& points,
  const VertexLists& meshNeighbours, Points& placed)
{
  const Index unknowns = static_cast<Index>(disc.Planar.size() - loop.size());
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<Eigen::RowVector3d> rhs;
  LaplacianRows(disc, loop, points, meshNeighbours, entries, rhs);
  SparseMatrix a(static_cast<Index>(rhs.size()), unknowns);
  a.setFromTriplets(entries.begin(), entries.end());
  Eigen::MatrixXd b(static_cast<Index>(rhs.size()), 3);
  for (size_t r = 0; r < rhs.size(); ++r)
  {
    b.row(static_cast<Index>(r)) = rhs[r];
  }
  const SparseMatrix normal = (a.transpose() * a).pruned();
  Eigen::SimplicialLDLT<SparseMatrix> solver(normal);
  if (solver.info() != Eigen::Success)
  {
    return false;
  }
  const Eigen::MatrixXd x = solver.solve(a.transpose() * b);
  if (solver.info() != Eigen::Success || !x.allFinite())
  {
    return false;
  }
  placed = x;
  return true;
}

double TriangleArea(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  return 0.5 * (b - a).cross(c - a).norm();
}

// Closes one loop (its vertices in its triangles' direction): appends the patch's points and
// triangles, reversed so that they run against the loop. Returns the patch's area, or -1 if
// it could not be placed.
double FillLoop(const std::vector<Index>& loop, const VertexLists& meshNeighbours,
  const Points& points, std::vector<Eigen::Vector3d>& newPoints,
  std::vector<std::array<Index, 3>>& newTriangles, Index firstNewPoint)
{
  const Index n = static_cast<Index>(loop.size());
  if (n == 3)
  {
    newTriangles.push_back({ loop[0], loop[2], loop[1] });
    return TriangleArea(points.row(loop[0]), points.row(loop[1]), points.row(loop[2]));
  }
  std::vector<double> angles(static_cast<size_t>(n), 0.0);
  double perimeter = 0;
  for (Index i = 0; i < n; ++i)
  {
    angles[i] = perimeter;
    perimeter += (points.row(loop[(i + 1) % n]) - points.row(loop[i])).norm();
  }
  for (Index i = 0; i < n; ++i)
  {
    angles[i] = 2 * kPi * (perimeter > 0 ? angles[i] / perimeter : static_cast<double>(i) / static_cast<double>(n));
  }
  const DiscLayout disc = LayOutDisc(angles);
  Points placed;
  if (!PlaceNewPoints(disc, loop, points, meshNeighbours, placed))
  {
    return -1;
  }
  const Index base = firstNewPoint + static_cast<Index>(newPoints.size());
  auto global = [&](Index local) { return local < n ? loop[local] : base + local - n; };
  auto position = [&](Index local) -> Eigen::Vector3d {
    return local < n ? Eigen::Vector3d(points.row(loop[local])) : Eigen::Vector3d(placed.row(local - n));
  };
  double area = 0;
  for (const auto& t : disc.Triangles)
  {
    newTriangles.push_back({ global(t[0]), global(t[2]), global(t[1]) });
    area += TriangleArea(position(t[0]), position(t[1]), position(t[2]));
  }
  for (Index i = 0; i < placed.rows(); ++i)
  {
    newPoints.emplace_back(placed.row(i));
  }
  return area;
}
}

HoleFillResult FillHoles(Points& points, Triangles& triangles, MeshProvenance* provenance)
{
  HoleFillResult result;
  const std::vector<char> valid = ValidTriangles(triangles, points.rows());
  const std::vector<HalfEdge> halfEdges = SortedHalfEdges(triangles, valid, points.rows());
  std::vector<std::vector<Index>> loops;
  std::vector<char> closed;
  TraceBoundaryLoops(halfEdges, loops, closed);
  const VertexLists neighbours = VertexNeighbors(points.rows(), triangles);
  std::vector<Eigen::Vector3d> newPoints;
  std::vector<std::array<Index, 3>> newTriangles;
  for (size_t l = 0; l < loops.size(); ++l)
  {
    std::vector<Index> sorted = loops[l];
    std::sort(sorted.begin(), sorted.end());
    const bool simple = std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
    const double area = closed[l] && simple && loops[l].size() >= 3
      ? FillLoop(loops[l], neighbours, points, newPoints, newTriangles, points.rows())
      : -1;
    if (area < 0)
    {
      ++result.Skipped;
      continue;
    }
    ++result.Holes;
    result.BoundaryEdges += static_cast<Index>(loops[l].size());
    result.Area += area;
  }
  const Index oldPoints = points.rows(), oldTriangles = triangles.rows();
  if (provenance)
  {
    provenance->PointSource.resize(static_cast<size_t>(oldPoints));
    std::iota(provenance->PointSource.begin(), provenance->PointSource.end(), Index(0));
    provenance->PointSource.resize(provenance->PointSource.size() + newPoints.size(), -1);
    provenance->TriangleSource.resize(static_cast<size_t>(oldTriangles));
    std::iota(provenance->TriangleSource.begin(), provenance->TriangleSource.end(), Index(0));
    provenance->TriangleSource.resize(provenance->TriangleSource.size() + newTriangles.size(), -1);
  }
  points.conservativeResize(oldPoints + static_cast<Index>(newPoints.size()), 3);
  for (size_t i = 0; i < newPoints.size(); ++i)
  {
    points.row(oldPoints + static_cast<Index>(i)) = newPoints[i].transpose();
  }
  triangles.conservativeResize(oldTriangles + static_cast<Index>(newTriangles.size()), 3);
  for (size_t i = 0; i < newTriangles.size(); ++i)
  {
    triangles.row(oldTriangles + static_cast<Index>(i)) << newTriangles[i][0], newTriangles[i][1], newTriangles[i][2];
  }
  return result;
}
}
