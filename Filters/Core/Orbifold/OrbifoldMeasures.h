// Measures of a spherical map of a cyclic covering: how far it is from n-fold rotational
// symmetry about its cone axis, and how much it distorts area.
#ifndef mobius_OrbifoldMeasures_h
#define mobius_OrbifoldMeasures_h

#include "MeshTypes.h"

#include <Eigen/Core>

#include <vector>

namespace mobius
{
/// The rotation taking unit vector `from` to unit vector `to` (about their cross product; for
/// opposite vectors, a half turn about an axis perpendicular to both).
Eigen::Matrix3d RotationTaking(const Eigen::Vector3d& from, const Eigen::Vector3d& to);

struct CyclicSymmetryError
{
  /// The largest distance on the unit sphere between the image of a vertex of copy i under
  /// the rotation by 2 pi / n about the axis and the same vertex of copy i + 1.
  double MaximumDistance = 0.0;
  /// The root-mean-square of those distances over the vertices.
  double RMSDistance = 0.0;
  /// +1 or -1: the rotation's direction (counterclockwise about the axis or clockwise) that
  /// fits best; the gluing's orientation fixes it.
  int Direction = 1;
};

/// How far `sphere` (a map of a covering, unit vectors) is from commuting with the deck
/// transformation `nextCopyVertex`: compares the rotation by 2 pi / copies about `axis`
/// (a unit vector) of every vertex with its next copy.
CyclicSymmetryError MeasureCyclicSymmetry(const Points& sphere,
  const std::vector<Index>& nextCopyVertex, const Eigen::Vector3d& axis, int copies);

struct AreaDistortionStatistics
{
  /// Over the triangles, the logarithm of (mapped area share) / (surface area share), each
  /// share relative to its total: the area-weighted standard deviation (0 for an
  /// area-preserving map; a map that doubles one half and halves the other: 0.69)...
  double StdLogAreaRatio = 0.0;
  /// ... the area-weighted mean of its absolute value, and its extremes.
  double MeanAbsLogAreaRatio = 0.0;
  double MinLogAreaRatio = 0.0;
  double MaxLogAreaRatio = 0.0;
};

/// Area distortion of the map surface -> mapped (same triangles, flat triangle areas on both
/// sides). Triangles with zero area on either side are left out.
AreaDistortionStatistics MeasureAreaDistortion(
  const Points& surface, const Points& mapped, const Triangles& triangles);
}

#endif
