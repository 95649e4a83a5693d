// How far a piecewise-linear map between two triangulations with the same connectivity is
// from conformal and from area-preserving, and whether a spherical map folds.
#ifndef mobius_MapDistortion_h
#define mobius_MapDistortion_h

#include "MeshTypes.h"

namespace mobius
{
/// The distortion of a triangle flattened to a segment or a point: unbounded, reported as
/// 1e15, beyond which double precision cannot tell the two singular values apart.
constexpr double MaximumQuasiConformalDistortion = 1e15;
/// A triangle whose quasi-conformal distortion is above this is squashed: its map stretches
/// one direction ten times more than the other (a conformal map of a smooth surface, well
/// triangulated, stays below 2 almost everywhere; the triangles of a tail or finger that the
/// map squeezes to a speck reach millions).
constexpr double SquashedQuasiConformalDistortion = 10.0;

struct MapDistortion
{
  /// Triangles of the spherical map whose signed volume det(a, b, c) (the tetrahedron with
  /// the sphere's center) is <= 0: folded over, or facing inward.
  Index FlippedTriangles = 0;
  /// Quasi-conformal distortion of a triangle: sigma_max / sigma_min of the linear map from
  /// the original triangle to the mapped (flat) triangle; 1 for a similarity. The mean is
  /// weighted by original area. A mapped triangle with no area (a segment or a point)
  /// counts as MaximumQuasiConformalDistortion.
  double MeanQuasiConformal = 1.0;
  double MaxQuasiConformal = 1.0;
  /// Area-weighted quantiles of the same: the distortion below which the triangles holding
  /// 50%, 95% and 99% of the surface's area lie. Unlike the mean, they are not carried off
  /// by the few triangles of a part the map squeezes to a speck.
  double MedianQuasiConformal = 1.0;
  double P95QuasiConformal = 1.0;
  double P99QuasiConformal = 1.0;
  /// Share of the surface's area (0 to 1) in squashed triangles (distortion above
  /// SquashedQuasiConformalDistortion).
  double SquashedAreaShare = 0.0;
  /// Mapped area / original area per triangle, after scaling both totals to 1.
  double MinAreaRatio = 1.0;
  double MaxAreaRatio = 1.0;
  /// The smallest mapped (flat) triangle's area over 4 pi, the unit sphere's: how small the
  /// map squeezes a triangle. Double precision resolves positions on the unit sphere to
  /// about 1e-16, so triangles below about 1e-28 of the sphere are at its limit.
  double SmallestMappedAreaShare = 1.0;
  /// The mapped (flat) triangles' total area over 4 pi: near 1 for a map that covers the
  /// sphere, near 0 for one whose vertices crowd into one spot.
  double MappedAreaShare = 1.0;
};

/// Six times the signed volume of the tetrahedron (0, a, b, c), computed as
/// a . ((b - a) x (c - a)): the textbook a . (b x c) cancels catastrophically for a tiny
/// triangle on the unit sphere (a 1e-9 triangle's volume drowns in 1e-16 rounding), which
/// reports correct triangles as flipped.
double SignedVolume(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// Six times the signed volume the triangles enclose (positive when they face outward),
/// summed relative to the points' mean: the same for a closed surface in exact arithmetic,
/// but a mesh far from the origin (a unit-size mesh at 1e6) otherwise loses its volume to
/// cancellation between terms a million times larger, and may be taken for inside out.
double EnclosedVolume(const Points& points, const Triangles& triangles);

/// Distortion of the map original[i] -> mapped[i] over the triangles. Original triangles
/// with no area are skipped (they have no defined distortion). `mapped` is taken to be
/// centered at the origin for the flip count (true of a spherical map).
/// The smallest interior angle of any triangle, in degrees (180 for no triangles; degenerate
/// triangles count as 0). Needle triangles make cotangent weights extreme.
double SmallestTriangleAngleDegrees(const Points& points, const Triangles& triangles);

MapDistortion MeasureMapDistortion(
  const Points& original, const Points& mapped, const Triangles& triangles);

/// Quasi-conformal distortion of one triangle map (sigma_max / sigma_min, >= 1; at most
/// MaximumQuasiConformalDistortion).
double TriangleQuasiConformalDistortion(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
  const Eigen::Vector3d& p2, const Eigen::Vector3d& q0, const Eigen::Vector3d& q1,
  const Eigen::Vector3d& q2);
}

#endif
