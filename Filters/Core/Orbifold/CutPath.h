// Edge paths on a triangle mesh for cutting it open: the shortest path between two vertices
// (Dijkstra on edge lengths) and a cheap pair of far-apart vertices to cut between.
#ifndef mobius_CutPath_h
#define mobius_CutPath_h

#include "MeshTypes.h"

#include <utility>
#include <vector>

namespace mobius
{
/// Edge-path distances from `source` to every vertex (Dijkstra, Euclidean edge lengths);
/// +infinity for unreachable vertices. `previous` (optional) receives each vertex's
/// predecessor on its shortest path (-1 for the source and unreachable vertices).
Vector EdgePathDistances(const Points& points, const Triangles& triangles, Index source,
  std::vector<Index>* previous = nullptr);

/// The shortest edge path from `from` to `to`, both ends included; empty if `to` cannot be
/// reached.
std::vector<Index> ShortestEdgePath(
  const Points& points, const Triangles& triangles, Index from, Index to);

/// Two vertices far apart along the surface, by a double sweep: the vertex farthest (in edge
/// path length) from the vertex with the smallest x coordinate, and the vertex farthest from
/// that one. On elongated shapes these are the ends of the longest geodesic (the two
/// extremities); a cheap stand-in for the diameter, two Dijkstra runs.
std::pair<Index, Index> FarApartVertices(const Points& points, const Triangles& triangles);
}

#endif
