#include "SqueezedTipSpreading.h"

#include "MeshAdjacency.h"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace mobius
{
namespace
{
// Disks spread at most (each is one tip; real shapes have a few dozen at most).
constexpr int MaximumSpreadTips = 100;
// The exponents tried: 1, 0.9, 0.81, ... down to 1e-3 (quasi-conformal distortion 1000).
constexpr double ExponentStep = 0.9;
constexpr double SmallestExponentTried = 1e-3;
// The disks tried, smallest first: each reaches no vertex with an edge this long. Larger
// disks leave room for gentler spreadings (fewer folds) but distort more of the map.
constexpr double DiskEdgeLengths[] = { 1e-9, 1e-7, 1e-5, 1e-3 };

// A disk around a tip: the vertices inside it (which the spreading moves), the triangles
// touching them and those triangles' other corners, each vertex with its offset from the tip.
struct Disk
{
  Index Center = -1;
  double Radius = 0.0;
  Eigen::RowVector3d Normal; // the sphere's normal at the tip
  /// The vertices inside the disk, then the other corners of its triangles, which stay.
  std::vector<Index> Vertices;
  std::vector<Eigen::RowVector3d> Offsets; // each vertex's offset from the tip
  size_t Members = 0;                      // Vertices[0, Members) are inside
  std::vector<Index> Triangles;
  std::vector<Index> Corners; // 3 per triangle: positions in Vertices
};

// The disk around `tip` that reaches no vertex whose edges reach `resolved`.
Disk FindDisk(const NestedFrames& x, const Triangles& triangles, const VertexLists& around,
  const Vector& longest, Index tip, double resolved)
{
  Disk disk;
  disk.Center = tip;
  const Eigen::RowVector3d center = x.Absolute().High.row(tip);
  disk.Normal = center.normalized();
  disk.Radius = std::numeric_limits<double>::infinity();
  for (Index v = 0; v < longest.size(); ++v)
  {
    if (longest[v] >= resolved)
    {
      disk.Radius = std::min(disk.Radius, x.Difference(v, tip).norm());
    }
  }
  if (!std::isfinite(disk.Radius))
  {
    return disk;
  }
  // Each vertex's offset is computed once (and so is its spreading, for every exponent tried).
  std::vector<Index> position(static_cast<size_t>(longest.size()), -1);
  for (Index v = 0; v < longest.size(); ++v)
  {
    const Eigen::RowVector3d offset = x.Difference(v, tip);
    if (offset.norm() < disk.Radius)
    {
      position[v] = static_cast<Index>(disk.Vertices.size());
      disk.Vertices.push_back(v);
      disk.Offsets.push_back(offset);
    }
  }
  disk.Members = disk.Vertices.size();
  std::vector<char> listed(static_cast<size_t>(triangles.rows()), 0);
  for (size_t m = 0; m < disk.Members; ++m)
  {
    const Index v = disk.Vertices[m];
    for (Index k = around.Begin(v); k < around.End(v); ++k)
    {
      const Index t = around.Items[k];
      if (listed[t])
      {
        continue;
      }
      listed[t] = 1;
      disk.Triangles.push_back(t);
      for (int c = 0; c < 3; ++c)
      {
        const Index corner = triangles(t, c);
        if (position[corner] < 0)
        {
          position[corner] = static_cast<Index>(disk.Vertices.size());
          disk.Vertices.push_back(corner);
          disk.Offsets.push_back(x.Difference(corner, tip));
        }
        disk.Corners.push_back(position[corner]);
      }
    }
  }
  return disk;
}

// The radial power map of the disk: rho -> R (rho / R)^a. (A collar easing the slope from 1
// at the disk's edge to a inside left more folds on the generated branches, not fewer.)
Eigen::RowVector3d Spread(const Eigen::RowVector3d& offset, double radius, double exponent)
{
  const double rho = offset.norm();
  return rho > 0.0 ? Eigen::RowVector3d(offset * std::pow(rho / radius, exponent - 1.0)) : offset;
}

// The disk's triangles once spread with `exponent`: their shortest edge and how many fold.
struct SpreadQuality
{
  double Shortest = 0.0;
  Index Folded = 0;
};

SpreadQuality Evaluate(const Disk& disk, double exponent)
{
  std::vector<Eigen::RowVector3d> q(disk.Offsets);
  for (size_t m = 0; m < disk.Members; ++m)
  {
    q[m] = Spread(disk.Offsets[m], disk.Radius, exponent);
  }
  SpreadQuality quality;
  quality.Shortest = std::numeric_limits<double>::infinity();
  for (size_t t = 0; t < disk.Triangles.size(); ++t)
  {
    const Index* corner = &disk.Corners[3 * t];
    for (int k = 0; k < 3; ++k)
    {
      quality.Shortest = std::min(quality.Shortest, (q[corner[(k + 1) % 3]] - q[corner[k]]).norm());
    }
    const Eigen::RowVector3d& a = q[corner[0]];
    quality.Folded += disk.Normal.dot((q[corner[1]] - a).cross(q[corner[2]] - a)) <= 0.0 ? 1 : 0;
  }
  return quality;
}

// A spreading of one disk: the exponent and what it gives.
struct SpreadChoice
{
  double Exponent = 1.0;
  SpreadQuality Quality;
  /// Every edge resolved.
  bool Resolved() const { return this->Quality.Shortest >= ResolvableEdgeLength; }
  /// Better: resolved before not; then fewer folds; then (both unresolved) a longer
  /// shortest edge; then a larger exponent (less distortion).
  bool Better(const SpreadChoice& other) const
  {
    if (this->Resolved() != other.Resolved())
    {
      return this->Resolved();
    }
    if (this->Resolved() && this->Quality.Folded != other.Quality.Folded)
    {
      return this->Quality.Folded < other.Quality.Folded;
    }
    if (!this->Resolved() && this->Quality.Shortest != other.Quality.Shortest)
    {
      return this->Quality.Shortest > other.Quality.Shortest;
    }
    return this->Exponent > other.Exponent;
  }
};

// The best exponent for the disk (see SpreadChoice::Better). Folds the spreading leaves (a
// straight edge cutting inside the next ring when the rings come closer than the polygon's
// sagitta) are few and the flip repair's to undo.
SpreadChoice ChooseExponent(const Disk& disk)
{
  SpreadChoice best;
  best.Quality = Evaluate(disk, 1.0);
  for (double a = ExponentStep; a >= SmallestExponentTried; a *= ExponentStep)
  {
    SpreadChoice choice;
    choice.Exponent = a;
    choice.Quality = Evaluate(disk, a);
    if (choice.Better(best))
    {
      best = choice;
    }
  }
  return best;
}

// The vertex with the shortest longest edge below ResolvableEdgeLength, not given up on; -1
// if there is none.
Index DeepestVertex(const Vector& longest, const std::vector<char>& abandoned)
{
  Index deepest = -1;
  for (Index v = 0; v < longest.size(); ++v)
  {
    if (!abandoned[v] && longest[v] < ResolvableEdgeLength &&
      (deepest < 0 || longest[v] < longest[deepest]))
    {
      deepest = v;
    }
  }
  return deepest;
}

// The disk around `tip` with the best spreading (the smallest, of equal ones).
Disk BestDisk(const NestedFrames& x, const Triangles& triangles, const VertexLists& around,
  const Vector& longest, Index tip, SpreadChoice& choice)
{
  Disk disk;
  for (double resolved : DiskEdgeLengths)
  {
    Disk candidate = FindDisk(x, triangles, around, longest, tip, resolved);
    const SpreadChoice candidateChoice = ChooseExponent(candidate);
    if (disk.Center < 0 || candidateChoice.Better(choice))
    {
      disk = std::move(candidate);
      choice = candidateChoice;
    }
  }
  return disk;
}

Index CountUnresolvedEdges(const NestedFrames& x, const Triangles& triangles)
{
  Index count = 0;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index a = triangles(t, k), b = triangles(t, (k + 1) % 3);
      // Each edge once (from the triangle that has it going up).
      count += a < b && x.Difference(a, b).norm() < ResolvableEdgeLength ? 1 : 0;
    }
  }
  return count;
}
}

TipSpreadingResult SpreadUnresolvedTips(NestedFrames& x, const Triangles& triangles)
{
  TipSpreadingResult result;
  const Index n = x.Absolute().High.rows();
  const VertexLists around = VertexTriangles(n, triangles);
  std::vector<char> moved(static_cast<size_t>(n), 0), abandoned(static_cast<size_t>(n), 0);
  Vector longest = x.LongestEdges(triangles);
  for (int tip = 0; tip < MaximumSpreadTips; ++tip)
  {
    const Index deepest = DeepestVertex(longest, abandoned);
    if (deepest < 0)
    {
      break;
    }
    SpreadChoice choice;
    const Disk disk = BestDisk(x, triangles, around, longest, deepest, choice);
    if (choice.Exponent < 1.0)
    {
      const ExtendedPoint center = x.Absolute().Point(disk.Center);
      for (size_t m = 0; m < disk.Members; ++m)
      {
        x.MoveAbsolute(
          disk.Vertices[m], center, Spread(disk.Offsets[m], disk.Radius, choice.Exponent));
        moved[disk.Vertices[m]] = 1;
      }
      ++result.SpreadTips;
      result.SmallestExponent = std::min(result.SmallestExponent, choice.Exponent);
      longest = x.LongestEdges(triangles);
    }
    // A tip is tried once; the disk's vertices left unresolved are given up on too (their
    // disks would be the same).
    abandoned[deepest] = 1;
    for (size_t m = 0; m < disk.Members; ++m)
    {
      const Index v = disk.Vertices[m];
      abandoned[v] = abandoned[v] || (!choice.Resolved() && longest[v] < ResolvableEdgeLength);
    }
  }
  for (Index v = 0; v < n; ++v)
  {
    result.SpreadVertices += moved[v];
  }
  result.UnresolvedEdges = CountUnresolvedEdges(x, triangles);
  return result;
}
}
