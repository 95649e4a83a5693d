// Signed mean curvature of a closed surface, smoothed over a small neighbourhood: a shape
// descriptor that a map between two poses of one shape should keep. Mean curvature is
// extrinsic, so it sees what intrinsic descriptors (eigenfunctions, heat kernels) miss on a
// body whose front and back are nearly isometric: a face against the back of a head, toes
// against a heel, a kneecap against the hollow behind the knee. It is unchanged by rigid
// motions and, away from the joints a pose bends, by the pose itself.
#ifndef mobius_MeanCurvature_h
#define mobius_MeanCurvature_h

#include "MeshTypes.h"

namespace mobius
{
/// Per vertex, the mean curvature H = (k1 + k2) / 2 of the surface scaled to unit area
/// (positive where it is convex, for outward-facing triangles), diffused by the heat flow
/// for `smoothingTime` (on the unit-area surface: mean curvature is noisy from one vertex to
/// the next, and the diffusion over a distance of about sqrt(4 smoothingTime) makes it
/// comparable between two triangulations of one shape). Both the curvature and the
/// diffusion use the intrinsic Delaunay cotangent Laplacian, which stays well-shaped on
/// meshes with needle triangles. Empty if the Laplacian cannot be built (a zero-length edge,
/// non-manifold edges).
Vector SmoothedMeanCurvature(const Points& points, const Triangles& triangles, double smoothingTime);

/// The smoothing time SmoothedMeanCurvature is used with to compare maps: a diffusion over
/// about 6% of sqrt(area), the size of a nose or a heel on a human body. Measured on FAUST
/// training pairs, times of 1e-4..1e-3 tell a body's front from its back; 1e-2 blurs it away.
constexpr double kCurvatureSmoothingTime = 1e-3;
}

#endif
