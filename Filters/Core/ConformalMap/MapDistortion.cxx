#include "MapDistortion.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace mobius
{
namespace
{
// The triangle's edge vectors p1 - p0, p2 - p0 as the columns of a 2x2 matrix, in an
// orthonormal frame of the triangle's own plane with x along p1 - p0 (so the matrix is upper
// triangular with a non-negative determinant).
Eigen::Matrix2d PlanarEdges(
  const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2)
{
  const Eigen::Vector3d e1 = p1 - p0, e2 = p2 - p0;
  const double length = e1.norm();
  Eigen::Matrix2d edges;
  edges(0, 0) = length;
  edges(1, 0) = 0.0;
  edges(0, 1) = length > 0.0 ? e1.dot(e2) / length : 0.0;
  edges(1, 1) = length > 0.0 ? e1.cross(e2).norm() / length : 0.0;
  return edges;
}

// The values q of `samples` (value, weight), at which the samples below q hold the given
// shares of the total weight, for ascending shares. Sorts `samples`.
std::vector<double> WeightedQuantiles(
  std::vector<std::pair<double, double>>& samples, const std::vector<double>& shares)
{
  std::vector<double> quantiles(shares.size(), 1.0);
  if (samples.empty())
  {
    return quantiles;
  }
  std::sort(samples.begin(), samples.end());
  double total = 0.0;
  for (const auto& sample : samples)
  {
    total += sample.second;
  }
  double below = 0.0;
  size_t next = 0, s = 0;
  for (; s < samples.size() && next < shares.size(); ++s)
  {
    below += samples[s].second;
    while (next < shares.size() && below >= shares[next] * total)
    {
      quantiles[next++] = samples[s].first;
    }
  }
  for (; next < shares.size(); ++next)
  {
    quantiles[next] = samples.back().first; // rounding left the last share unreached
  }
  return quantiles;
}
}

double SignedVolume(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  return a.dot((b - a).cross(c - a));
}

double EnclosedVolume(const Points& points, const Triangles& triangles)
{
  const Eigen::Vector3d center = points.colwise().mean().transpose();
  double volume = 0.0;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    const Eigen::Vector3d a = points.row(triangles(t, 0)).transpose() - center;
    const Eigen::Vector3d b = points.row(triangles(t, 1)).transpose() - center;
    const Eigen::Vector3d c = points.row(triangles(t, 2)).transpose() - center;
    volume += SignedVolume(a, b, c);
  }
  return volume;
}

double TriangleQuasiConformalDistortion(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
  const Eigen::Vector3d& p2, const Eigen::Vector3d& q0, const Eigen::Vector3d& q1,
  const Eigen::Vector3d& q2)
{
  const Eigen::Matrix2d from = PlanarEdges(p0, p1, p2), to = PlanarEdges(q0, q1, q2);
  if (!(from(0, 0) > 0.0 && from(1, 1) > 0.0))
  {
    return std::numeric_limits<double>::quiet_NaN(); // callers skip degenerate originals
  }
  // The map A with A * from = to; from is upper triangular, so invert it directly.
  Eigen::Matrix2d inverse;
  inverse << 1.0 / from(0, 0), -from(0, 1) / (from(0, 0) * from(1, 1)), 0.0, 1.0 / from(1, 1);
  const Eigen::Matrix2d a = to * inverse;
  // Closed-form singular values of a 2x2 matrix: (E +- F) with these two norms.
  const double e = 0.5 * std::hypot(a(0, 0) + a(1, 1), a(1, 0) - a(0, 1));
  const double f = 0.5 * std::hypot(a(0, 0) - a(1, 1), a(1, 0) + a(0, 1));
  const double largest = e + f, smallest = std::abs(e - f);
  // Flattened to a segment or a point (within rounding): the distortion is unbounded. It is
  // reported as the largest ratio double precision resolves, so that the figures stay
  // numbers in the outputs (field data, JSON) rather than infinities.
  if (!(smallest > largest * (1.0 / MaximumQuasiConformalDistortion)))
  {
    return MaximumQuasiConformalDistortion;
  }
  return largest / smallest;
}

MapDistortion MeasureMapDistortion(
  const Points& original, const Points& mapped, const Triangles& triangles)
{
  MapDistortion d;
  const Index m = triangles.rows();
  Vector originalArea(m), mappedArea(m);
  for (Index t = 0; t < m; ++t)
  {
    const Eigen::Vector3d p0 = original.row(triangles(t, 0)), p1 = original.row(triangles(t, 1)),
                          p2 = original.row(triangles(t, 2));
    const Eigen::Vector3d q0 = mapped.row(triangles(t, 0)), q1 = mapped.row(triangles(t, 1)),
                          q2 = mapped.row(triangles(t, 2));
    originalArea[t] = 0.5 * (p1 - p0).cross(p2 - p0).norm();
    mappedArea[t] = 0.5 * (q1 - q0).cross(q2 - q0).norm();
    d.FlippedTriangles += SignedVolume(q0, q1, q2) <= 0.0 ? 1 : 0;
  }
  const double originalTotal = originalArea.sum(), mappedTotal = mappedArea.sum();
  double weightedSum = 0.0, weight = 0.0, squashed = 0.0;
  std::vector<std::pair<double, double>> samples; // (distortion, original area)
  samples.reserve(static_cast<size_t>(m));
  d.MaxQuasiConformal = 1.0;
  d.MinAreaRatio = std::numeric_limits<double>::infinity();
  d.MaxAreaRatio = 0.0;
  for (Index t = 0; t < m; ++t)
  {
    if (!(originalArea[t] > 0.0))
    {
      continue;
    }
    const double qc = TriangleQuasiConformalDistortion(original.row(triangles(t, 0)),
      original.row(triangles(t, 1)), original.row(triangles(t, 2)), mapped.row(triangles(t, 0)),
      mapped.row(triangles(t, 1)), mapped.row(triangles(t, 2)));
    if (std::isnan(qc))
    {
      continue;
    }
    weightedSum += originalArea[t] * qc;
    weight += originalArea[t];
    squashed += qc > SquashedQuasiConformalDistortion ? originalArea[t] : 0.0;
    samples.emplace_back(qc, originalArea[t]);
    d.MaxQuasiConformal = std::max(d.MaxQuasiConformal, qc);
    // A map collapsed to a point has no area at all: every ratio is 0, not 0 / 0.
    const double ratio =
      mappedTotal > 0.0 ? (mappedArea[t] / mappedTotal) / (originalArea[t] / originalTotal) : 0.0;
    d.MinAreaRatio = std::min(d.MinAreaRatio, ratio);
    d.MaxAreaRatio = std::max(d.MaxAreaRatio, ratio);
  }
  d.MeanQuasiConformal = weight > 0.0 ? weightedSum / weight : 1.0;
  d.SquashedAreaShare = weight > 0.0 ? squashed / weight : 0.0;
  const std::vector<double> quantiles = WeightedQuantiles(samples, { 0.5, 0.95, 0.99 });
  d.MedianQuasiConformal = quantiles[0];
  d.P95QuasiConformal = quantiles[1];
  d.P99QuasiConformal = quantiles[2];
  d.SmallestMappedAreaShare = m > 0 ? mappedArea.minCoeff() / (4.0 * M_PI) : 1.0;
  d.MappedAreaShare = mappedTotal / (4.0 * M_PI);
  if (d.MaxAreaRatio == 0.0 && d.MinAreaRatio == std::numeric_limits<double>::infinity())
  {
    d.MinAreaRatio = d.MaxAreaRatio = 1.0; // nothing measured
  }
  return d;
}

double SmallestTriangleAngleDegrees(const Points& points, const Triangles& triangles)
{
  double smallest = M_PI;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d apex = points.row(triangles(t, k));
      const Eigen::Vector3d u = Eigen::Vector3d(points.row(triangles(t, (k + 1) % 3))) - apex;
      const Eigen::Vector3d v = Eigen::Vector3d(points.row(triangles(t, (k + 2) % 3))) - apex;
      // atan2 of |u x v| and u.v stays accurate for tiny angles, unlike acos.
      smallest = std::min(smallest, std::atan2(u.cross(v).norm(), u.dot(v)));
    }
  }
  return smallest * 180.0 / M_PI;
}
}
