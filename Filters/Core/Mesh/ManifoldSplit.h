// The repairs that make a triangle soup with defects a manifold: duplicate triangles
// removed, and every vertex split into one copy per fan of its triangles, so that an edge
// of three or more triangles (a fin, a duplicated face, two surfaces glued along an edge) and
// a vertex where cones touch become ordinary edges and vertices again. The same split, with
// chosen edges treated as cuts, opens a surface along a path (where no orientation agrees)
// or a loop (a handle).
#ifndef mobius_ManifoldSplit_h
#define mobius_ManifoldSplit_h

#include "MeshTopology.h"
#include "MeshTypes.h"

#include <vector>

namespace mobius
{
/// Drops every triangle that names the same three points as an earlier one (either way
/// round); the points stay. `removed` receives the count.
MeshProvenance RemoveDuplicateTriangles(Index numberOfPoints, Triangles& triangles, Index* removed);

struct FanSplit
{
  MeshProvenance Provenance; ///< the copies' source is the vertex split
  Index SplitVertices = 0;   ///< vertices that became two or more
};

/// Splits each vertex into one copy per fan: the triangles around it that are joined through
/// edges of exactly two triangles, none of them in `cuts` (sorted). After the split no edge
/// has more than two triangles and every vertex has one fan. The first fan (in triangle
/// order) keeps the vertex's number; the copies are appended.
FanSplit SplitVertexFans(Points& points, Triangles& triangles, const std::vector<EdgeKey>& cuts = {});
}

#endif
