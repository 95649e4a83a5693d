#include "SphericalFlipRepair.h"

#include "MapDistortion.h"
#include "MeshAdjacency.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <vector>

namespace mobius
{
namespace
{
// A star is projected only if every vertex is within 60 degrees of its center, where the
// gnomonic projection stretches lengths by at most 4.
constexpr double MinimumCosineToStarCenter = 0.5;
// Rounds of kernel placement (remedy 2); each either removes a fold or ends the remedy.
constexpr int MaximumKernelRounds = 50;

bool IsFlipped(const Points& x, const Triangles& triangles, Index t)
{
  const Eigen::Vector3d a = x.row(triangles(t, 0)), b = x.row(triangles(t, 1)),
                        c = x.row(triangles(t, 2));
  return SignedVolume(a, b, c) <= 0.0;
}

// Remedy 1: Gauss-Seidel sweeps over the vertices of folded triangles. Returns the sweeps
// made; `flips` is updated. The map with the fewest folds seen is the one kept: on a squeezed
// region the sweeps can spread a fold instead of removing it.
int SmoothFoldedVertices(
  Points& x, const Triangles& triangles, const VertexLists& neighbours, int maximumPasses, Index& flips)
{
  const Index n = x.rows();
  std::vector<char> marked(static_cast<size_t>(n), 0);
  std::vector<Index> active;
  Points best = x;
  Index bestFlips = flips;
  int pass = 0;
  for (; pass < maximumPasses && flips > 0; ++pass)
  {
    active.clear();
    for (Index t = 0; t < triangles.rows(); ++t)
    {
      if (IsFlipped(x, triangles, t))
      {
        for (int k = 0; k < 3; ++k)
        {
          const Index v = triangles(t, k);
          if (!marked[v])
          {
            marked[v] = 1;
            active.push_back(v);
          }
        }
      }
    }
    // A fold that survives sweeps of its own vertices needs room: widen to the k-ring.
    const int rings = std::min(1 + pass / 5, 6) - 1;
    for (int ring = 0; ring < rings; ++ring)
    {
      const size_t end = active.size();
      for (size_t i = 0; i < end; ++i)
      {
        for (Index k = neighbours.Begin(active[i]); k < neighbours.End(active[i]); ++k)
        {
          const Index w = neighbours.Items[k];
          if (!marked[w])
          {
            marked[w] = 1;
            active.push_back(w);
          }
        }
      }
    }
    for (Index v : active)
    {
      Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
      for (Index k = neighbours.Begin(v); k < neighbours.End(v); ++k)
      {
        sum += x.row(neighbours.Items[k]);
      }
      const double norm = sum.norm();
      if (norm > 0.0)
      {
        x.row(v) = sum / norm;
      }
      marked[v] = 0;
    }
    flips = CountFlippedTriangles(x, triangles);
    if (flips < bestFlips)
    {
      bestFlips = flips;
      best = x;
    }
  }
  if (flips > bestFlips)
  {
    x = best;
    flips = bestFlips;
  }
  return pass;
}

// Remedy 2 for one vertex: moves v to the point of its star's kernel farthest from the
// kernel's edges (the Chebyshev center of the half-planes "left of each link edge"), in the
// gnomonic plane at v, where the sphere's triangles around v are planar triangles with the
// same orientation. Only v's own triangles change, and all of them end up unfolded, so a move
// never creates a fold. Returns false (v unchanged) when the kernel is empty.
bool PlaceInStarKernel(
  Points& x, const Triangles& triangles, const VertexLists& vertexTriangles, Index v)
{
  const Eigen::Vector3d c = x.row(v).transpose();
  const Eigen::Vector3d e1 = c.unitOrthogonal(), e2 = c.cross(e1); // e1 x e2 = c: outward
  auto project = [&](Index w, Eigen::Vector2d& q) {
    const Eigen::Vector3d d = x.row(w).transpose() - c; // exact for nearby points
    const double cosine = x.row(w).dot(c);
    if (!(cosine > MinimumCosineToStarCenter))
    {
      return false;
    }
    const Eigen::Vector3d tangential = d - d.dot(c) * c;
    q = Eigen::Vector2d(tangential.dot(e1), tangential.dot(e2)) / cosine;
    return true;
  };
  // One half-plane n . p >= h per triangle (v, a, b): p left of the directed edge a -> b.
  std::vector<Eigen::Vector2d> normals;
  std::vector<Eigen::Vector2d> starts;
  double scale = 0.0;
  for (Index k = vertexTriangles.Begin(v); k < vertexTriangles.End(v); ++k)
  {
    const Index t = vertexTriangles.Items[k];
    const int corner = triangles(t, 0) == v ? 0 : (triangles(t, 1) == v ? 1 : 2);
    Eigen::Vector2d a, b;
    if (!project(triangles(t, (corner + 1) % 3), a) || !project(triangles(t, (corner + 2) % 3), b))
    {
      return false;
    }
    normals.emplace_back(-(b - a).y(), (b - a).x());
    starts.push_back(a);
    scale = std::max({ scale, a.norm(), b.norm() });
  }
  if (!(scale > 0.0) || normals.size() < 3)
  {
    return false;
  }
  // In units of the star's size, with unit normals: the constraint's value is a distance.
  const size_t count = normals.size();
  Eigen::VectorXd offsets(count);
  for (size_t i = 0; i < count; ++i)
  {
    const double length = normals[i].norm();
    if (!(length > 0.0))
    {
      return false;
    }
    normals[i] /= length;
    offsets[i] = normals[i].dot(starts[i] / scale);
  }
  // The Chebyshev center is a vertex of the linear program max t s.t. n_i . p - t >= h_i:
  // where three constraints are tight. Stars have a handful of triangles, so all triples are
  // tried.
  double bestDepth = 0.0;
  Eigen::Vector2d bestPoint;
  for (size_t i = 0; i < count; ++i)
  {
    for (size_t j = i + 1; j < count; ++j)
    {
      for (size_t k = j + 1; k < count; ++k)
      {
        Eigen::Matrix3d system;
        system << normals[i].transpose(), -1.0, normals[j].transpose(), -1.0,
          normals[k].transpose(), -1.0;
        const Eigen::Vector3d rhs(offsets[i], offsets[j], offsets[k]);
        const Eigen::FullPivLU<Eigen::Matrix3d> lu(system);
        if (!lu.isInvertible())
        {
          continue;
        }
        const Eigen::Vector3d solution = lu.solve(rhs);
        const Eigen::Vector2d point = solution.head<2>();
        double depth = solution[2];
        for (size_t l = 0; l < count && depth > bestDepth; ++l)
        {
          depth = std::min(depth, normals[l].dot(point) - offsets[l]);
        }
        if (depth > bestDepth)
        {
          bestDepth = depth;
          bestPoint = point;
        }
      }
    }
  }
  if (!(bestDepth > 0.0))
  {
    return false;
  }
  const Eigen::RowVector3d saved = x.row(v);
  x.row(v) = (c + scale * (bestPoint.x() * e1 + bestPoint.y() * e2)).normalized().transpose();
  for (Index k = vertexTriangles.Begin(v); k < vertexTriangles.End(v); ++k)
  {
    if (IsFlipped(x, triangles, vertexTriangles.Items[k]))
    {
      x.row(v) = saved; // rounding at the scale of a squeezed star: keep what was there
      return false;
    }
  }
  return true;
}

// Remedy 2: rounds of PlaceInStarKernel over the vertices of folded triangles, while some
// vertex moves. Each move only removes folds.
void MoveFoldedVerticesIntoKernels(
  Points& x, const Triangles& triangles, const VertexLists& vertexTriangles, Index& flips)
{
  std::vector<char> listed(static_cast<size_t>(x.rows()), 0);
  for (int round = 0; round < MaximumKernelRounds && flips > 0; ++round)
  {
    std::vector<Index> folded;
    for (Index t = 0; t < triangles.rows(); ++t)
    {
      if (IsFlipped(x, triangles, t))
      {
        for (int k = 0; k < 3; ++k)
        {
          if (!listed[triangles(t, k)])
          {
            listed[triangles(t, k)] = 1;
            folded.push_back(triangles(t, k));
          }
        }
      }
    }
    bool moved = false;
    for (Index v : folded)
    {
      moved = PlaceInStarKernel(x, triangles, vertexTriangles, v) || moved;
      listed[v] = 0;
    }
    flips = CountFlippedTriangles(x, triangles);
    if (!moved)
    {
      break;
    }
  }
}

}

Index CountFlippedTriangles(const Points& sphere, const Triangles& triangles)
{
  Index count = 0;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    count += IsFlipped(sphere, triangles, t) ? 1 : 0;
  }
  return count;
}

FlipRepairResult RepairFlippedTriangles(Points& x, const Triangles& triangles, int maximumPasses)
{
  FlipRepairResult result;
  result.InitialFlips = CountFlippedTriangles(x, triangles);
  result.RemainingFlips = result.InitialFlips;
  if (maximumPasses <= 0 || result.InitialFlips == 0)
  {
    return result;
  }
  const Points given = x;
  const VertexLists neighbours = VertexNeighbors(x.rows(), triangles);
  result.Passes =
    SmoothFoldedVertices(x, triangles, neighbours, maximumPasses, result.RemainingFlips);
  const VertexLists vertexTriangles = VertexTriangles(x.rows(), triangles);
  MoveFoldedVerticesIntoKernels(x, triangles, vertexTriangles, result.RemainingFlips);
  for (Index v = 0; v < x.rows(); ++v)
  {
    result.MovedVertices += (x.row(v) != given.row(v)) ? 1 : 0;
  }
  return result;
}
}
