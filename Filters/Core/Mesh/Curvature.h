// Mean and Gaussian curvature of a closed surface, smoothed over a small neighbourhood:
// shape descriptors that a map between two poses of one shape should keep. Mean curvature
// is extrinsic, so it sees what intrinsic descriptors (eigenfunctions, heat kernels) miss on
// a body whose front and back are nearly isometric: a face against the back of a head, toes
// against a heel, a kneecap against the hollow behind the knee. It is unchanged by rigid
// motions and, away from the joints a pose bends, by the pose itself. Gaussian curvature is
// intrinsic, unchanged by any bend that does not stretch the surface: it tells a saddle (an
// armpit, the neck, the small of the back) from a dome (a shoulder, a buttock), which mean
// curvature, positive on both, does not.
#ifndef mobius_Curvature_h
#define mobius_Curvature_h

#include "MeshTypes.h"

#include <array>
#include <limits>
#include <vector>

namespace mobius
{
/// Per vertex, the mean curvature H = (k1 + k2) / 2 of the surface scaled to unit area
/// (positive where it is convex, for outward-facing triangles), diffused by the heat flow
/// for `smoothingTime` (on the unit-area surface: mean curvature is noisy from one vertex to
/// the next, and the diffusion over a distance of about sqrt(4 smoothingTime) makes it
/// comparable between two triangulations of one shape). Both the curvature and the
/// diffusion use the intrinsic Delaunay cotangent Laplacian, which stays well-shaped on
/// meshes with needle triangles. Each vertex's value is clamped as kCandidateCurvature's.
/// Empty if the Laplacian cannot be built (a zero-length edge, non-manifold edges).
Vector SmoothedMeanCurvature(const Points& points, const Triangles& triangles, double smoothingTime);

/// Which curvature: the mean curvature H, or the Gaussian curvature K as sign(K) sqrt(|K|)
/// (the same unit as H, an inverse length: equal to H on a sphere; the root is taken after
/// the smoothing, which averages K itself).
enum class CurvatureKind
{
  Mean,
  SignedRootGaussian
};

/// How SmoothedCurvatures smooths: the heat flow's time, the bound each vertex's curvature
/// is clamped to before it, and the range the smoothed values are clamped to after it (for
/// the Gaussian kind, bound and range are of K and of its signed root). Mean curvature of
/// one vertex is |L x| / (2 area), Gaussian curvature its angle defect over its area; a few
/// needle or folded vertices can give values far beyond any real feature, which the
/// diffusion would spread. The flow takes `Steps` implicit steps: one step's kernel, the
/// resolvent of the Laplacian, has a logarithmic peak at its centre, which a mesh resolves
/// the higher the finer it is; a curvature concentrated at vertices (a faceted surface's
/// angle defects) then comes out peakier on a finer copy of the same surface. The kernel of
/// two or more steps is bounded.
struct CurvatureScale
{
  double SmoothingTime;
  double Bound;
  double Range;
  CurvatureKind Kind = CurvatureKind::Mean;
  int Steps = 1;
};

/// The same at several scales or of both kinds, one vector per scale, in their order: the
/// curvatures and the Laplacian are computed once. Empty vectors where
/// SmoothedMeanCurvature's would be.
std::vector<Vector> SmoothedCurvatures(
  const Points& points, const Triangles& triangles, const std::vector<CurvatureScale>& scales);

/// The smoothing time SmoothedMeanCurvature is used with to compare maps: a diffusion over
/// about 6% of sqrt(area), the size of a nose or a heel on a human body. Measured on FAUST
/// training pairs, times of 1e-4..1e-3 tell a body's front from its back; 1e-2 blurs it away.
constexpr double kCurvatureSmoothingTime = 1e-3;

/// Candidate maps are compared at kCurvatureSmoothingTime, each vertex's curvature within
/// that of a sphere of radius 1/50 of sqrt(area) (SmoothedMeanCurvature).
constexpr CurvatureScale kCandidateCurvature{ kCurvatureSmoothingTime, 50.0,
  std::numeric_limits<double>::infinity() };

/// The finer curvature the geometric polish matches (SurfacePolish), point by point between
/// two triangulations. Its time is a diffusion over about 3% of sqrt(area), fine enough to
/// locate a feature within an edge or two of a 5,000-vertex body: on FAUST_r training pairs
/// 1e-4 and 5e-4 scored slightly worse, 1e-3 clearly (docs/DEVELOPMENT.md, "Curvature in the
/// polish"). Its bound only stops outliers: a sharp tip is one vertex of a coarse mesh and
/// several of a finer copy, with higher curvatures over smaller areas, and clamping them
/// alike breaks what the diffusion keeps, the integral (CGAL's cow onto its 4 times finer
/// copy by midpoint subdivision mapped 2.8 times worse than without curvature with a bound
/// of 50). The range is clamped after the diffusion instead, alike at any resolution: parts
/// thinner than 1/30 of sqrt(area) (fingers, tails, horns) all look the same, so that two
/// bodies whose fingers differ do not pull each other along them (SMPL's man -> woman
/// 0.00353 unclamped, 0.00315 at 50, 0.00301 at 30).
constexpr CurvatureScale kPolishMeanCurvature{ 2.5e-4, 1000.0, 30.0 };

/// The Gaussian curvature the polish matches beside it, at the same smoothing time (on
/// FAUST_r training pairs 1e-4 and 1e-3 scored worse, 5e-4 the same) in 4 steps. A faceted
/// surface's Gaussian curvature sits at its vertices, the same angle defects on a finer copy
/// of it at the same points: one step made CGAL's cow onto its midpoint-subdivided copy map
/// 1.4 times worse than without this curvature, 4 steps better than without it
/// (docs/DEVELOPMENT.md, "Gaussian curvature too"). No clamp: angle defects sum to 4 pi on a
/// closed genus-0 mesh of any resolution.
constexpr CurvatureScale kPolishGaussianCurvature{ 2.5e-4,
  std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
  CurvatureKind::SignedRootGaussian, 4 };

/// The curvatures the geometric polish matches, in this order.
constexpr std::array<CurvatureScale, 2> kPolishCurvatures{ kPolishMeanCurvature,
  kPolishGaussianCurvature };
}

#endif
