#include "LandmarkConsistency.h"

#include "CotangentLaplacian.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

namespace mobius
{
namespace
{
// Edge-path distances from one vertex to every vertex (Dijkstra over the mesh's edges).
Vector EdgePathDistances(const SpectralSurface& surface, Index from)
{
  const Points& points = surface.Positions;
  Vector distance = Vector::Constant(points.rows(), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, Index>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  distance[from] = 0;
  queue.emplace(0.0, from);
  while (!queue.empty())
  {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[v])
    {
      continue;
    }
    for (Index k = surface.Neighbors.Begin(v); k < surface.Neighbors.End(v); ++k)
    {
      const Index u = surface.Neighbors.Items[k];
      const double du = d + (points.row(u) - points.row(v)).norm();
      if (du < distance[u])
      {
        distance[u] = du;
        queue.emplace(du, u);
      }
    }
  }
  return distance;
}
}

std::vector<Vector> LandmarkDistances(
  const SpectralSurface& surface, const std::vector<Index>& landmarks)
{
  const double scale = std::sqrt(TriangleAreas(surface.Positions, surface.Faces).sum());
  std::vector<Vector> distances;
  for (Index landmark : landmarks)
  {
    distances.push_back(EdgePathDistances(surface, landmark) / (scale > 0 ? scale : 1.0));
  }
  return distances;
}

double LandmarkDistanceDifference(const SpectralSurface& source, const SampleMap& map,
  const std::vector<Vector>& sourceDistances, const std::vector<Vector>& targetDistances)
{
  double sum = 0;
  Index count = 0;
  for (size_t l = 0; l < sourceDistances.size() && l < targetDistances.size(); ++l)
  {
    for (size_t s = 0; s < map.TargetVertex.size(); ++s)
    {
      const double difference =
        sourceDistances[l][source.Samples[s]] - targetDistances[l][map.TargetVertex[s]];
      if (std::isfinite(difference))
      {
        sum += std::abs(difference);
        ++count;
      }
    }
  }
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

std::vector<double> LandmarkDistanceDifferences(const SpectralSurface& source,
  const SpectralSurface& target, const std::vector<SampleMap>& screened,
  const std::vector<std::pair<Index, Index>>& landmarks)
{
  std::vector<double> differences(screened.size(), 0.0);
  if (landmarks.empty())
  {
    return differences;
  }
  std::vector<Index> sourceVertices, targetVertices;
  for (const auto& landmark : landmarks)
  {
    sourceVertices.push_back(landmark.first);
    targetVertices.push_back(landmark.second);
  }
  const std::vector<Vector> sourceDistances = LandmarkDistances(source, sourceVertices);
  const std::vector<Vector> targetDistances = LandmarkDistances(target, targetVertices);
  for (size_t c = 0; c < screened.size(); ++c)
  {
    differences[c] =
      LandmarkDistanceDifference(source, screened[c], sourceDistances, targetDistances);
  }
  return differences;
}

std::vector<bool> KeepsLandmarkDistances(
  const std::vector<double>& differences, const std::vector<bool>& eligible)
{
  double lowest = std::numeric_limits<double>::infinity();
  for (size_t c = 0; c < differences.size(); ++c)
  {
    if (c < eligible.size() && eligible[c])
    {
      lowest = std::min(lowest, differences[c]);
    }
  }
  std::vector<bool> keeps;
  for (double difference : differences)
  {
    keeps.push_back(
      !std::isfinite(lowest) || difference <= (1.0 + kLandmarkDistanceMargin) * lowest);
  }
  return keeps;
}
}
