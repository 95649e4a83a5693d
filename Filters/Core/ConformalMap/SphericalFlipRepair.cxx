#include "SphericalFlipRepair.h"

#include "MapDistortion.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <vector>

namespace mobius
{
namespace
{
bool IsFlipped(const Points& x, const Triangles& triangles, Index t)
{
  const Eigen::Vector3d a = x.row(triangles(t, 0)), b = x.row(triangles(t, 1)),
                        c = x.row(triangles(t, 2));
  return SignedVolume(a, b, c) <= 0.0;
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
  const Index n = x.rows();
  // Vertex neighbours (compressed rows, duplicates removed).
  std::vector<std::vector<Index>> neighbours(static_cast<size_t>(n));
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      neighbours[triangles(t, k)].push_back(triangles(t, (k + 1) % 3));
      neighbours[triangles(t, k)].push_back(triangles(t, (k + 2) % 3));
    }
  }
  for (auto& list : neighbours)
  {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }

  std::vector<char> moved(static_cast<size_t>(n), 0), marked(static_cast<size_t>(n), 0);
  std::vector<Index> active;
  result.InitialFlips = CountFlippedTriangles(x, triangles);
  result.RemainingFlips = result.InitialFlips;
  for (int pass = 0; pass < maximumPasses && result.RemainingFlips > 0; ++pass)
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
        for (Index w : neighbours[active[i]])
        {
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
      for (Index w : neighbours[v])
      {
        sum += x.row(w);
      }
      const double norm = sum.norm();
      if (norm > 0.0)
      {
        x.row(v) = sum / norm;
        moved[v] = 1;
      }
      marked[v] = 0;
    }
    result.Passes = pass + 1;
    result.RemainingFlips = CountFlippedTriangles(x, triangles);
  }
  result.MovedVertices = std::count(moved.begin(), moved.end(), 1);
  return result;
}
}
