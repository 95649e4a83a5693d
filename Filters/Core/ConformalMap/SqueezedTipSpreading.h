// Spreads out the tips of a spherical map that double precision cannot resolve.
//
// Why: a conformal map squeezes a long thin part exponentially: each ring of triangles along
// a tube is smaller than the one before by a fixed factor (about exp(-2 pi h / c) for rings h
// apart around a circumference c), so a tail or finger many times longer than wide ends
// 1e-20 or 1e-30 across on the unit sphere. A double near 1 resolves 1e-16: stored, such
// triangles collapse to points or fold, and the map is neither conformal nor usable there.
// The map cannot be conformal at that scale and stored in doubles at once, so we give up
// conformality where it must go: around the tip p, the disk of radius R that reaches no
// well-resolved vertex (edges of ResolvedEdgeLength or more) is mapped radially by
// rho -> R (rho / R)^a, with the largest a in (0, 1] that leaves every edge touching the
// disk at least ResolvableEdgeLength long. That power map is one-to-one, keeps the disk's
// edge fixed and has the same quasi-conformal distortion 1/a everywhere inside: the tip keeps
// its shape up to that stretch instead of collapsing. Folds left by the spreading (a
// straight-edged triangle spanning much of the disk) are the flip repair's to undo, now at a
// scale where it has room.
//
// The positions come in extended precision (ExtendedPoints.h), accurate to about 1e-32 on
// the sphere; a tip squeezed further than that is noise, spread out like the rest.
#ifndef mobius_SqueezedTipSpreading_h
#define mobius_SqueezedTipSpreading_h

#include "ExtendedPoints.h"
#include "MeshTypes.h"

namespace mobius
{
/// Edges shorter than this on the unit sphere are spread out: a hundred units in the last
/// place of a coordinate near 1, so that a triangle's orientation survives rounding. The
/// development meshes' maps stay above it (CGAL's bull: shortest edge 1e-13).
constexpr double ResolvableEdgeLength = 1e-14;
/// A vertex whose edges reach this length is left where it is: it bounds the spread disk.
constexpr double ResolvedEdgeLength = 1e-9;

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
TipSpreadingResult SpreadUnresolvedTips(ExtendedPoints& x, const Triangles& triangles);
}

#endif
