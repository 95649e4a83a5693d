// Short non-separating loops of a closed surface of genus > 0, for cutting its handles (a
// hand fused to a thigh, arms fused to the body: the loop around the fused place is short).
//
// Through a base point, the shortest loop that does not separate the surface is one of the
// loops of its shortest-path tree: two tree paths and the edge that joins their ends
// (Erickson & Whittlesey, "Greedy optimal homotopy and homology generators", SODA 2005).
// Whether such a loop separates the surface is told by a basis of cocycles made once from a
// tree-cotree decomposition: a loop separates if and only if it crosses each of them an even
// number of times, which the XOR of its edges' classes gives. So a search from a base point
// bounded by the best loop so far never looks beyond that bound. Over every base point that
// would be the shortest non-separating loop; here the base points are spread over the surface
// until they cover it within a sixth of the best loop's length, then they are points of the
// best loop, which find a shorter loop crossing it when there is one.
#ifndef mobius_HandleCutting_h
#define mobius_HandleCutting_h

#include "MeshTypes.h"

#include <vector>

namespace mobius
{
struct SurfaceLoop
{
  std::vector<Index> Vertices; ///< a simple cycle of edges, each vertex once
  double Length = 0;           ///< 0 and no vertices when none was found
};

/// A short non-separating loop of a closed, connected, manifold, consistently oriented
/// surface of genus > 0 (see above); an empty loop for genus 0.
SurfaceLoop ShortNonSeparatingLoop(const Points& points, const Triangles& triangles);
}

#endif
