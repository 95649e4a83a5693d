// Local repair of folded triangles in a spherical map.
//
// Why: a conformal map shrinks long thin limbs exponentially (a camel's legs, a man's
// fingers end up 1e-12 wide on the unit sphere), below what the linear solver resolves, and a
// needle triangle's apex can land on the wrong side of its long edge. Both are local: moving
// the vertices of folded triangles to the normalized average of their neighbours (Gauss-Seidel
// sweeps; a vertex at the centroid of its star is inside the star's kernel whenever that is
// nearly convex) unfolds them with a negligible change to the rest of the map.
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
  Index MovedVertices = 0; ///< distinct vertices moved
  int Passes = 0;
};

/// Sweeps over the vertices of flipped triangles (growing to their k-ring neighbourhood when a
/// fold persists), moving each to the normalized average of its neighbours, until no triangle
/// is flipped or `maximumPasses` sweeps were made. Points stay on the unit sphere.
FlipRepairResult RepairFlippedTriangles(
  Points& sphere, const Triangles& triangles, int maximumPasses = 100);
}

#endif
