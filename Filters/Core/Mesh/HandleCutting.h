// Short non-separating loops of a closed surface of genus > 0, for cutting its handles (a
// hand fused to a thigh, arms fused to the body: the loop around the fused place is short).
//
// Through a base point, the shortest loop that does not separate the surface is the first of
// Erickson & Whittlesey's greedy system of loops ("Greedy optimal homotopy and homology
// generators", SODA 2005): the shortest-path tree from the base point, a maximum spanning
// tree of the dual graph weighted by the length of each remaining edge's loop (its two tree
// paths and itself), and the shortest of the edges left in neither tree. Over every base point
// that would be the shortest non-separating loop; here the base points are spread over the
// surface until they cover it within a sixth of the best loop's length, then they are the
// points of the best loop, which find a shorter loop crossing it when there is one.
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
