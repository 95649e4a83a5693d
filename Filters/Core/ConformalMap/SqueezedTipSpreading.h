// Spreads out the tips of a spherical map that double precision cannot resolve.
//
// Why: a conformal map squeezes a long thin part exponentially: each ring of triangles along
// a tube is smaller than the one before by a fixed factor (about exp(-2 pi h / c) for rings h
// apart around a circumference c), so a tail or finger many times longer than wide ends
// 1e-20 or 1e-30 across on the unit sphere. A double near 1 resolves 1e-16: stored, such
// triangles collapse to points or fold, and the map is neither conformal nor usable there.
// The map cannot be conformal at that scale and stored in doubles at once, so we give up
// conformality where it must go: around the tip p, a disk of radius R (reaching no vertex
// whose edges are 1e-9 long; or 1e-7, 1e-5, 1e-3 if that gives a better spreading) is mapped
// radially by rho -> R (rho / R)^a. That power map is one-to-one, keeps the disk's edge
// fixed and has the same quasi-conformal distortion 1/a everywhere inside: the tip keeps its
// shape up to that stretch instead of collapsing. The exponent is the largest that leaves
// every edge at the disk at least ResolvableEdgeLength long with the fewest folded triangles:
// a ring of m vertices whose straight edges cut inside the next ring (the rings brought
// closer than the polygon's sagitta, about pi^2 / 2m^2 of the radius) folds, so a cannot go
// far below pi / 4m. The few folds left are the flip repair's to undo, at a scale where it
// has room (generated branches 30 to 40 times as long as wide: 32 to 139 folds, all undone).
//
// The offsets from the tip come from the nested levels (NestedFrames.h), accurate relative
// to their size at any depth, so the spread tip keeps the conformal map's shape (up to the
// stretch 1/a).
#ifndef mobius_SqueezedTipSpreading_h
#define mobius_SqueezedTipSpreading_h

#include "NestedFrames.h"
#include "MeshTypes.h"

namespace mobius
{
/// Edges shorter than this on the unit sphere are spread out: a hundred units in the last
/// place of a coordinate near 1, so that a triangle's orientation survives rounding. The
/// development meshes' maps stay above it (CGAL's bull: shortest edge 5e-14).
constexpr double ResolvableEdgeLength = 1e-14;

struct TipSpreadingResult
{
  Index SpreadTips = 0;     ///< disks spread out
  Index SpreadVertices = 0; ///< distinct vertices moved
  /// The smallest exponent a used (1 / the quasi-conformal distortion of the spreading); 1
  /// when nothing was spread.
  double SmallestExponent = 1.0;
  /// Edges still shorter than ResolvableEdgeLength (the spreading found no room for them).
  Index UnresolvedEdges = 0;
};

/// Spreads the tips of `x` (a map onto the unit sphere) whose edges are shorter than
/// ResolvableEdgeLength, deepest first, until none is left or no disk helps.
TipSpreadingResult SpreadUnresolvedTips(NestedFrames& x, const Triangles& triangles);
}

#endif
