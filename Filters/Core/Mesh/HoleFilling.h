// Closing the holes of a manifold, consistently oriented triangle mesh with faired patches.
//
// Each boundary loop gets a disc: concentric rings of new points, their spacing the loop's
// own edge length at the rim and growing inward (so that a large hole gets a few hundred
// points, not the hundred thousand of a uniform fill), zipped together by angle and closed
// by a point at the middle. The new points are then placed by least squares on the
// discrete Laplacians: zero at each new point (with mean-value weights of the disc's planar
// layout, which keep its spacing) and at each rim point over all its neighbours, old and
// new (so the patch leaves the surface along its tangent). A hole in a sphere is closed by
// a cap close to the sphere, a hole in a plane by a flat disc; the conformal map sees a
// surface continued smoothly across the hole, not a fan of long triangles to one point.
#ifndef mobius_HoleFilling_h
#define mobius_HoleFilling_h

#include "MeshTopology.h"
#include "MeshTypes.h"

namespace mobius
{
struct HoleFillResult
{
  Index Holes = 0;         ///< loops closed
  Index BoundaryEdges = 0; ///< their edges
  double Area = 0;         ///< the patches' area
  /// Loops left open: chains that do not close, or visit a vertex twice (only at a vertex
  /// with several fans, which SplitVertexFans removes).
  Index Skipped = 0;
};

/// Closes every simple boundary loop (see above). New points and triangles are appended;
/// `provenance` (optional) gets the identity for the old rows and -1 for the new ones.
HoleFillResult FillHoles(Points& points, Triangles& triangles, MeshProvenance* provenance = nullptr);
}

#endif
