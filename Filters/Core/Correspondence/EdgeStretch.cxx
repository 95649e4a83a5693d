#include "EdgeStretch.h"

#include "CotangentLaplacian.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace mobius
{
Vector EdgeStretch(const Points& source, const Triangles& triangles, const Points& mapped)
{
  // Each edge of a closed mesh appears in two triangles: once in each direction, so every
  // edge is counted once per triangle side, twice in all, which weights all edges alike.
  std::vector<double> logRatios;
  logRatios.reserve(static_cast<size_t>(3 * triangles.rows()));
  std::vector<std::pair<Index, Index>> ends;
  ends.reserve(logRatios.capacity());
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index a = triangles(t, k), b = triangles(t, (k + 1) % 3);
      const double before = (source.row(a) - source.row(b)).norm();
      const double after = (mapped.row(a) - mapped.row(b)).norm();
      if (before > 0)
      {
        // A collapsed image edge counts as shrunk a million times, not as infinitely.
        logRatios.push_back(std::log(std::max(after, 1e-6 * before) / before));
        ends.emplace_back(a, b);
      }
    }
  }
  Vector stretch = Vector::Zero(source.rows());
  if (logRatios.empty())
  {
    return stretch;
  }
  std::vector<double> sorted = logRatios;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double logScale = sorted[sorted.size() / 2];
  Vector count = Vector::Zero(source.rows());
  for (size_t e = 0; e < logRatios.size(); ++e)
  {
    const double value = std::abs(logRatios[e] - logScale);
    for (Index v : { ends[e].first, ends[e].second })
    {
      stretch[v] += value;
      count[v] += 1;
    }
  }
  for (Index v = 0; v < source.rows(); ++v)
  {
    stretch[v] = count[v] > 0 ? stretch[v] / count[v] : 0.0;
  }
  return stretch;
}

double MeanEdgeStretch(const Points& source, const Triangles& triangles, const Points& mapped)
{
  const Vector mass = LumpedMass(source, triangles);
  return mass.sum() > 0 ? EdgeStretch(source, triangles, mapped).dot(mass) / mass.sum() : 0.0;
}
}
