// Compressed adjacency lists of a triangle mesh: the neighbours of each vertex along edges
// and the triangles around each vertex, for walks and local searches on the surface.
#ifndef mobius_MeshAdjacency_h
#define mobius_MeshAdjacency_h

#include "MeshTypes.h"

#include <vector>

namespace mobius
{
/// Item lists per vertex in one array: the items of vertex v are
/// Items[Offsets[v]] ... Items[Offsets[v + 1] - 1].
struct VertexLists
{
  std::vector<Index> Offsets;
  std::vector<Index> Items;

  Index Begin(Index v) const { return this->Offsets[v]; }
  Index End(Index v) const { return this->Offsets[v + 1]; }
};

/// The distinct vertices sharing an edge with each vertex.
VertexLists VertexNeighbors(Index numberOfPoints, const Triangles& triangles);

/// The triangles having each vertex as a corner.
VertexLists VertexTriangles(Index numberOfPoints, const Triangles& triangles);

/// The point at `vertex` itself as a triangle around it and barycentric coordinates (1 at
/// that corner); `vertexTriangles` from VertexTriangles. The vertex must be in a triangle.
void PlaceAtVertex(const Triangles& triangles, const VertexLists& vertexTriangles, Index vertex,
  Index& triangle, Eigen::Vector3d& barycentric);
}

#endif
