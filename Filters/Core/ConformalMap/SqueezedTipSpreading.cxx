#include "SqueezedTipSpreading.h"

#include "MeshAdjacency.h"

#include <cmath>
#include <limits>
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

struct Disk
{
  ExtendedPoint Center;
  double Radius = 0.0;
  std::vector<Index> Members;                // vertices inside
  std::vector<Eigen::RowVector3d> Offsets;   // their offsets from the center
};

// The disk around `tip` that reaches no well-resolved vertex, and the vertices in it.
Disk FindDisk(const ExtendedPoints& x, const Vector& longest, Index tip)
{
  Disk disk;
  disk.Center = x.Point(tip);
  disk.Radius = std::numeric_limits<double>::infinity();
  for (Index v = 0; v < longest.size(); ++v)
  {
    if (longest[v] >= ResolvedEdgeLength)
    {
      disk.Radius = std::min(disk.Radius, x.Difference(v, disk.Center).norm());
    }
  }
  for (Index v = 0; v < longest.size() && std::isfinite(disk.Radius); ++v)
  {
    const Eigen::RowVector3d offset = x.Difference(v, disk.Center);
    if (offset.norm() < disk.Radius)
    {
      disk.Members.push_back(v);
      disk.Offsets.push_back(offset);
    }
  }
  return disk;
}

// The radial power map of the disk: rho -> R (rho / R)^a.
Eigen::RowVector3d Spread(const Eigen::RowVector3d& offset, double radius, double exponent)
{
  const double rho = offset.norm();
  return rho > 0.0 ? Eigen::RowVector3d(offset * std::pow(rho / radius, exponent - 1.0)) : offset;
}

// The shortest edge at the disk's members once spread with `exponent`; `local` numbers the
// members (-1 outside the disk, whose vertices stay).
double ShortestSpreadEdge(const ExtendedPoints& x, const Disk& disk, const std::vector<Index>& local,
  const VertexLists& neighbours, double exponent)
{
  double shortest = std::numeric_limits<double>::infinity();
  for (size_t r = 0; r < disk.Members.size(); ++r)
  {
    const Index v = disk.Members[r];
    const Eigen::RowVector3d p = Spread(disk.Offsets[r], disk.Radius, exponent);
    for (Index k = neighbours.Begin(v); k < neighbours.End(v); ++k)
    {
      const Index w = neighbours.Items[k];
      const Eigen::RowVector3d q = local[w] >= 0
        ? Spread(disk.Offsets[local[w]], disk.Radius, exponent)
        : Eigen::RowVector3d(x.Difference(w, disk.Center));
      shortest = std::min(shortest, (p - q).norm());
    }
  }
  return shortest;
}

// The largest exponent that resolves every edge at the disk, or else the one that makes its
// shortest edge longest.
double ChooseExponent(const ExtendedPoints& x, const Disk& disk, const std::vector<Index>& local,
  const VertexLists& neighbours, double& shortest)
{
  double best = 1.0;
  shortest = ShortestSpreadEdge(x, disk, local, neighbours, 1.0);
  for (double a = ExponentStep; a >= SmallestExponentTried && shortest < ResolvableEdgeLength;
       a *= ExponentStep)
  {
    const double length = ShortestSpreadEdge(x, disk, local, neighbours, a);
    if (length > shortest)
    {
      shortest = length;
      best = a;
    }
  }
  return best;
}
}

TipSpreadingResult SpreadUnresolvedTips(ExtendedPoints& x, const Triangles& triangles)
{
  TipSpreadingResult result;
  const Index n = x.High.rows();
  const VertexLists neighbours = VertexNeighbors(n, triangles);
  std::vector<char> moved(static_cast<size_t>(n), 0), abandoned(static_cast<size_t>(n), 0);
  std::vector<Index> local(static_cast<size_t>(n), -1);
  Vector longest = LongestEdges(x, triangles);
  for (int tip = 0; tip < MaximumSpreadTips; ++tip)
  {
    // The deepest vertex not given up on.
    Index deepest = -1;
    for (Index v = 0; v < n; ++v)
    {
      if (!abandoned[v] && longest[v] < ResolvableEdgeLength &&
        (deepest < 0 || longest[v] < longest[deepest]))
      {
        deepest = v;
      }
    }
    if (deepest < 0)
    {
      break;
    }
    const Disk disk = FindDisk(x, longest, deepest);
    for (size_t r = 0; r < disk.Members.size(); ++r)
    {
      local[disk.Members[r]] = static_cast<Index>(r);
    }
    double shortest = 0.0;
    const double exponent = ChooseExponent(x, disk, local, neighbours, shortest);
    for (size_t r = 0; r < disk.Members.size(); ++r)
    {
      local[disk.Members[r]] = -1;
    }
    if (exponent < 1.0)
    {
      for (size_t r = 0; r < disk.Members.size(); ++r)
      {
        x.Set(disk.Members[r], disk.Center, Spread(disk.Offsets[r], disk.Radius, exponent));
        moved[disk.Members[r]] = 1;
      }
      ++result.SpreadTips;
      result.SmallestExponent = std::min(result.SmallestExponent, exponent);
      longest = LongestEdges(x, triangles);
    }
    // A tip the disk could not resolve is not tried again (its disk would be the same).
    abandoned[deepest] = 1;
    if (!(shortest >= ResolvableEdgeLength))
    {
      for (Index v : disk.Members)
      {
        abandoned[v] = abandoned[v] || longest[v] < ResolvableEdgeLength;
      }
    }
  }
  for (Index v = 0; v < n; ++v)
  {
    result.SpreadVertices += moved[v];
  }
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index a = triangles(t, k), b = triangles(t, (k + 1) % 3);
      // Each edge once (from the triangle that has it going up).
      result.UnresolvedEdges += a < b && x.Difference(a, b).norm() < ResolvableEdgeLength ? 1 : 0;
    }
  }
  return result;
}
}
