#include "SurfaceSampling.h"

#include <functional>
#include <limits>
#include <queue>

namespace mobius
{
std::vector<Index> FarthestPointSamples(const Points& points, Index count)
{
  const Index n = points.rows();
  count = std::min(count, n);
  std::vector<Index> samples;
  if (count <= 0)
  {
    return samples;
  }
  samples.reserve(static_cast<size_t>(count));
  const Eigen::RowVector3d centroid = points.colwise().mean();
  Index first = 0;
  (points.rowwise() - centroid).rowwise().squaredNorm().maxCoeff(&first);
  Vector distance = Vector::Constant(n, std::numeric_limits<double>::infinity());
  Index next = first;
  while (static_cast<Index>(samples.size()) < count)
  {
    samples.push_back(next);
    const Eigen::RowVector3d p = points.row(next);
    distance = distance.cwiseMin((points.rowwise() - p).rowwise().squaredNorm());
    distance.maxCoeff(&next);
  }
  return samples;
}

std::vector<Index> NearestSampleLabels(
  const Points& points, const VertexLists& neighbors, const std::vector<Index>& samples)
{
  const Index n = points.rows();
  std::vector<double> distance(static_cast<size_t>(n), std::numeric_limits<double>::infinity());
  std::vector<Index> label(static_cast<size_t>(n), -1);
  using Entry = std::pair<double, Index>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (size_t s = 0; s < samples.size(); ++s)
  {
    distance[samples[s]] = 0;
    label[samples[s]] = static_cast<Index>(s);
    queue.emplace(0.0, samples[s]);
  }
  while (!queue.empty())
  {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[v])
    {
      continue;
    }
    for (Index k = neighbors.Begin(v); k < neighbors.End(v); ++k)
    {
      const Index u = neighbors.Items[k];
      const double du = d + (points.row(u) - points.row(v)).norm();
      if (du < distance[u])
      {
        distance[u] = du;
        label[u] = label[v];
        queue.emplace(du, u);
      }
    }
  }
  return label;
}
}
