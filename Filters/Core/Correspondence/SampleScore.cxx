#include "SampleScore.h"

#include "ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mobius
{
//------------------------------------------------------------------------------
Index NearestCorner(
  const Points& points, const std::array<Index, 3>& corners, const Eigen::Vector3d& weights)
{
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double weightSum = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    if (corners[k] >= 0 && corners[k] < points.rows())
    {
      position += weights[k] * points.row(corners[k]).transpose();
      weightSum += weights[k];
    }
  }
  // Corners the caller cannot name (points a hole filling made) drop out; the rest keep
  // their share, so the position stays on the part of the triangle they span.
  if (weightSum != 0.0)
  {
    position /= weightSum;
  }
  Index nearest = -1;
  double nearestDistance = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k)
  {
    if (corners[k] < 0 || corners[k] >= points.rows())
    {
      continue;
    }
    const double distance = (points.row(corners[k]).transpose() - position).squaredNorm();
    if (nearest < 0 || distance < nearestDistance)
    {
      nearest = corners[k];
      nearestDistance = distance;
    }
  }
  return nearest;
}

//------------------------------------------------------------------------------
bool ScoreSamples(const EdgePathGeodesics& target, const std::vector<Index>& mapped,
  const std::vector<Index>& truth, const SampleGeodesics& geodesics, int numberOfThreads,
  std::vector<double>& errors, bool& shortened, std::string& error)
{
  const Index n = target.GetNumberOfPoints();
  if (mapped.size() != truth.size())
  {
    error = "the map gives " + std::to_string(mapped.size()) + " samples, the truth " +
      std::to_string(truth.size());
    return false;
  }
  for (size_t k = 0; k < mapped.size(); ++k)
  {
    if (mapped[k] >= n || truth[k] < 0 || truth[k] >= n)
    {
      error = "sample " + std::to_string(k + 1) + ": vertex " +
        std::to_string(mapped[k] >= n ? mapped[k] : truth[k]) + " is out of range (the target has " +
        std::to_string(n) + " vertices)";
      return false;
    }
  }
  const double scale = std::sqrt(target.GetSurfaceArea());
  if (!(scale > 0.0) || !std::isfinite(scale))
  {
    error = "the target has no surface area";
    return false;
  }
  errors.assign(mapped.size(), std::numeric_limits<double>::quiet_NaN());
  const int count = static_cast<int>(mapped.size());
  const int threads = std::max(1, std::min(ResolveThreadCount(numberOfThreads), count));
  // Edge paths first; a pair that scores well enough is measured again with shortened paths.
  CorridorGeodesics corridor;
  std::vector<CorridorGeodesics::Workspace> workspaces(threads);
  auto measure = [&](int steinerPoints) {
    corridor.Build(target, steinerPoints);
    ParallelFor(count, threads, [&](int k, int thread) {
      if (mapped[k] >= 0)
      {
        errors[k] = corridor.Distance(truth[k], mapped[k], workspaces[thread]) / scale;
      }
    });
  };
  measure(0);
  shortened = false;
  double sum = 0.0;
  Index scored = 0;
  for (double e : errors)
  {
    sum += std::isnan(e) ? 0.0 : e;
    scored += std::isnan(e) ? 0 : 1;
  }
  if (geodesics.SteinerPoints > 0 && scored > 0 && sum / scored <= geodesics.ShortenPairsUpTo)
  {
    measure(geodesics.SteinerPoints);
    shortened = true;
  }
  return true;
}

//------------------------------------------------------------------------------
PairErrorSummary SummarizePairErrors(const std::vector<double>& pairErrors)
{
  PairErrorSummary summary;
  std::vector<double> sorted;
  for (double e : pairErrors)
  {
    if (!std::isnan(e))
    {
      sorted.push_back(e);
    }
  }
  if (sorted.empty())
  {
    summary.Mean = summary.Median = summary.ShareFailed = std::numeric_limits<double>::quiet_NaN();
    return summary;
  }
  std::sort(sorted.begin(), sorted.end());
  const size_t m = sorted.size();
  summary.Pairs = static_cast<Index>(m);
  double sum = 0.0;
  size_t failed = 0;
  for (double e : sorted)
  {
    sum += e;
    failed += e > FailedPairThreshold ? 1 : 0;
  }
  summary.Mean = sum / static_cast<double>(m);
  summary.Median = m % 2 ? sorted[m / 2] : 0.5 * (sorted[m / 2 - 1] + sorted[m / 2]);
  summary.ShareFailed = static_cast<double>(failed) / static_cast<double>(m);
  return summary;
}
}
