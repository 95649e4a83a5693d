#include "OrbifoldMeasures.h"

#include "CotangentLaplacian.h"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace mobius
{
Eigen::Matrix3d RotationTaking(const Eigen::Vector3d& from, const Eigen::Vector3d& to)
{
  const Eigen::Vector3d a = from.normalized(), b = to.normalized();
  const double cosine = a.dot(b);
  if (cosine < -1.0 + 1e-12)
  {
    return Eigen::AngleAxisd(3.14159265358979323846, a.unitOrthogonal()).toRotationMatrix();
  }
  return Eigen::Quaterniond::FromTwoVectors(a, b).toRotationMatrix();
}

CyclicSymmetryError MeasureCyclicSymmetry(const Points& sphere,
  const std::vector<Index>& nextCopyVertex, const Eigen::Vector3d& axis, int copies)
{
  CyclicSymmetryError best;
  best.MaximumDistance = std::numeric_limits<double>::infinity();
  const Index count = sphere.rows();
  for (const int direction : { 1, -1 })
  {
    const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(direction * 2.0 * 3.14159265358979323846 / copies, axis.normalized())
        .toRotationMatrix();
    double maximum = 0.0, sum = 0.0;
    for (Index w = 0; w < count; ++w)
    {
      const Eigen::Vector3d x = sphere.row(w);
      const Eigen::Vector3d y = sphere.row(nextCopyVertex[w]);
      const double d = (rotation * x - y).norm();
      maximum = std::max(maximum, d);
      sum += d * d;
    }
    if (maximum < best.MaximumDistance)
    {
      best.MaximumDistance = maximum;
      best.RMSDistance = count > 0 ? std::sqrt(sum / count) : 0.0;
      best.Direction = direction;
    }
  }
  return best;
}

AreaDistortionStatistics MeasureAreaDistortion(
  const Points& surface, const Points& mapped, const Triangles& triangles)
{
  const Vector a = TriangleAreas(surface, triangles);
  const Vector b = TriangleAreas(mapped, triangles);
  double totalA = 0.0, totalB = 0.0;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    if (a[t] > 0.0 && b[t] > 0.0)
    {
      totalA += a[t];
      totalB += b[t];
    }
  }
  AreaDistortionStatistics result;
  if (!(totalA > 0.0) || !(totalB > 0.0))
  {
    return result;
  }
  double mean = 0.0, meanSquare = 0.0, meanAbs = 0.0;
  result.MinLogAreaRatio = std::numeric_limits<double>::infinity();
  result.MaxLogAreaRatio = -std::numeric_limits<double>::infinity();
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    if (!(a[t] > 0.0 && b[t] > 0.0))
    {
      continue;
    }
    const double weight = a[t] / totalA;
    const double logRatio = std::log((b[t] / totalB) / weight);
    mean += weight * logRatio;
    meanSquare += weight * logRatio * logRatio;
    meanAbs += weight * std::abs(logRatio);
    result.MinLogAreaRatio = std::min(result.MinLogAreaRatio, logRatio);
    result.MaxLogAreaRatio = std::max(result.MaxLogAreaRatio, logRatio);
  }
  result.StdLogAreaRatio = std::sqrt(std::max(0.0, meanSquare - mean * mean));
  result.MeanAbsLogAreaRatio = meanAbs;
  return result;
}
}
