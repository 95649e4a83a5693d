// Re-solves the parts of a spherical conformal map that the map squeezes to a tiny size.
//
// Why: a conformal map shrinks long thin limbs exponentially; a camel's hooves end up
// 1e-12 wide on the unit sphere. Their positions are stored to 1e-16 absolutely, enough in
// principle, but the global solve's rounding error is relative to the whole sphere, so they
// come out as noise; and where the map's scale changes by orders of magnitude across a few
// rings of triangles, the cotangent-harmonic map of the (intrinsic) triangulation gives the
// original triangles quasi-conformal distortions in the millions (measured: camel, man).
// In such a region the map is harmonic up to the mass term, negligible at that scale, so we
// replace it by the solution of W_II y = -W_IB (x_B - c) with Floater's mean-value weights W
// of the original surface (positive for every triangulation: a Tutte-type embedding), for
// each squeezed region I with boundary B, in coordinates y = x - c relative to a point c of
// the region: the rounding error is then relative to the region's own size. Repeating at
// ever smaller thresholds resolves regions nested inside squeezed regions (a leg, its hoof).
// Measured on the camel (threshold 1e-7): mean quasi-conformal distortion 1551 -> 1.39.
//
// Each level's solution is kept in its own coordinates (NestedFrames.h), so the nesting goes
// on to any depth (1e-150): a hoof 1e-40 across is resolved relative to its own size. Where
// the map squeezes a tip below what a double on the unit sphere resolves, the tip is then
// spread out (SqueezedTipSpreading.h).
#ifndef mobius_SqueezedRegionRefinement_h
#define mobius_SqueezedRegionRefinement_h

#include "CotangentLaplacian.h"
#include "MeshTypes.h"
#include "SqueezedTipSpreading.h"

namespace mobius
{
/// The thresholds of the nested levels stop above this edge length, whose square double
/// precision still holds (1e-300).
constexpr double SmallestSqueezedRegionThreshold = 1e-150;

struct SqueezedRegionRefinementResult
{
  Index RefinedVertices = 0; ///< vertices re-solved at least once
  int Levels = 0;            ///< thresholds at which some region was re-solved
  /// False if the weights were not finite or a local factorization failed; the regions of
  /// that level and below keep the flow's positions.
  bool Success = true;
  /// The shortest edge of the re-solved map on the unit sphere, before any spreading: how
  /// far the map squeezes the thinnest part.
  double SmallestEdge = 0.0;
  /// What the spreading of unresolved tips did.
  TipSpreadingResult Spreading;
};

/// `sphere` holds unit-sphere positions, `original` the surface the map is of. A vertex
/// belongs to the squeezed region of threshold tau when all its edges on the sphere are
/// shorter than tau; thresholds run from `largestThreshold` (1e-7 by default: below the
/// scale where the flow's own map is accurate, so well-resolved maps are untouched) down by
/// factors of 100 while any region remains. Then tips with edges shorter than
/// ResolvableEdgeLength are spread out.
SqueezedRegionRefinementResult RefineSqueezedRegions(Points& sphere, const Triangles& triangles,
  const Points& original, double largestThreshold = 1e-7);
}

#endif
