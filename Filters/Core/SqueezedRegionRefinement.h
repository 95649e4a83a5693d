// Re-solves the parts of a spherical conformal map that the map squeezes to a tiny size.
//
// Why: a conformal map shrinks long thin limbs exponentially; a camel's hooves end up
// 1e-12 wide on the unit sphere. Their positions are stored to 1e-16 absolutely, enough in
// principle, but the global solve's rounding error is relative to the whole sphere, so they
// come out folded; and where the map's scale changes by orders of magnitude from one ring of
// triangles to the next, a cotangent-harmonic map need not be injective on the original
// triangles anyway. In such a region the map is nearly harmonic (the mass term is negligible
// at that scale), so we replace it by the solution of W_II y = -W_IB (x_B - c) with Floater's
// mean-value weights W (positive: a Tutte-type embedding, fold-free for a convex boundary),
// for each squeezed region I with boundary B, in coordinates y = x - c relative to a point c
// of the region: the rounding error is then relative to the region's own size. Repeating at
// ever smaller thresholds resolves regions nested inside squeezed regions (a leg, its hoof).
#ifndef mobius_SqueezedRegionRefinement_h
#define mobius_SqueezedRegionRefinement_h

#include "CotangentLaplacian.h"
#include "MeshTypes.h"

namespace mobius
{
struct SqueezedRegionRefinementResult
{
  Index RefinedVertices = 0; ///< vertices re-solved at least once
  int Levels = 0;            ///< thresholds at which some region was re-solved
  bool Success = true;       ///< false if a local factorization failed (map left unchanged there)
};

/// `sphere` holds unit-sphere positions, `original` the surface the map is of. A vertex belongs to the squeezed region of threshold tau when all its edges on the
/// sphere are shorter than tau; thresholds run from `largestThreshold` down by factors of
/// 100 while any region remains.
SqueezedRegionRefinementResult RefineSqueezedRegions(Points& sphere, const Triangles& triangles,
  const Points& original, double largestThreshold = 1e-3);
}

#endif
