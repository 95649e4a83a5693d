// Local repair of folded triangles in a spherical map.
//
// Why: a conformal map shrinks long thin limbs exponentially (a camel's legs, a man's
// fingers end up 1e-12 wide on the unit sphere), below what the linear solver resolves, and a
// needle triangle's apex can land on the wrong side of its long edge. Both are local. Two
// remedies, in order:
// 1. smoothing sweeps: moving the vertices of folded triangles to the normalized average of
//    their neighbours (a vertex at the centroid of its star is inside the star's kernel
//    whenever that is nearly convex) unfolds most folds with a negligible change to the map.
//    The sweeps can also spread a fold (measured: a bent copy of CGAL's bull, whose 17 folds
//    in a squeezed region became 551), so the sweep with the fewest folds is the one kept;
// 2. kernel placement: each vertex of a fold left is moved into the kernel of its star (the
//    points from which every triangle around it is unfolded), computed in the plane tangent to
//    the sphere at the vertex (gnomonic projection, which keeps great circles straight and the
//    triangles' orientations). Such a move changes only the vertex's own triangles and unfolds
//    all of them, so it never adds a fold; rounds continue while some vertex moves (the bent
//    bull: 17 -> 0).
// The repair never returns a map with more folds than it was given.
#ifndef mobius_SphericalFlipRepair_h
#define mobius_SphericalFlipRepair_h

#include "MeshTypes.h"

namespace mobius
{
/// Triangles with det(a, b, c) <= 0 on a sphere centered at the origin.
Index CountFlippedTriangles(const Points& sphere, const Triangles& triangles);

struct FlipRepairResult
{
  Index InitialFlips = 0;
  Index RemainingFlips = 0;
  Index MovedVertices = 0; ///< distinct vertices whose position changed
  int Passes = 0;          ///< smoothing sweeps made
};

/// Smoothing sweeps over the vertices of flipped triangles (growing to their k-ring
/// neighbourhood when a fold persists) until no triangle is flipped or `maximumPasses` sweeps
/// were made, then kernel placement of the vertices of the folds left (see above). Points stay
/// on the unit sphere. `maximumPasses` = 0 repairs nothing.
FlipRepairResult RepairFlippedTriangles(
  Points& sphere, const Triangles& triangles, int maximumPasses = 100);
}

#endif
