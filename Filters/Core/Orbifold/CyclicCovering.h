// The n-fold cyclic branched covering of a closed genus-0 mesh, branched at two cone
// vertices (paper §7.2): cut the mesh along an edge path between the cones, take n copies
// of the cut surface and glue the "left" side of the cut on copy i to the "right" side on
// copy i + 1 (mod n). The result is again a closed genus-0 mesh; the cones' angles are n
// times the original ones, every other vertex keeps its angle, and shifting every copy by
// one (the deck transformation) is a symmetry of it.
//
// Numbering. With V original vertices, the covering has n (V - 2) + 2 vertices: vertex v of
// copy i (v not a cone) is i (V - 2) + r(v), r numbering the non-cone vertices in order; the
// two cones come last and belong to every copy. An interior vertex p of the cut is shared by
// the triangles of copy i on the right of the cut and those of copy i - 1 on its left, so
// it is duplicated n times like any other vertex, and the deck transformation is the same
// shift for every vertex. Triangle t of copy i is triangle i F + t; all copies keep the
// input's orientation.
#ifndef mobius_CyclicCovering_h
#define mobius_CyclicCovering_h

#include "MeshTypes.h"

#include <string>
#include <vector>

namespace mobius
{
struct CyclicCovering
{
  int Copies = 0;
  /// The cut path, cone to cone, in input vertex numbers.
  std::vector<Index> CutPath;
  /// The covering's triangles (Copies * F of them, copy by copy).
  Triangles CoveringTriangles;
  /// The input vertex each covering vertex is a copy of.
  std::vector<Index> SourceVertex;
  /// The copy each covering vertex belongs to (-1 for the two cones).
  std::vector<int> VertexCopy;
  /// The deck transformation: the same vertex in the next copy (cones map to themselves).
  std::vector<Index> NextCopyVertex;
  /// The cones' covering vertex numbers.
  Index ConeVertices[2] = { -1, -1 };
  /// Per input triangle: at each corner, whether it lies on the left of the cut (used only
  /// at interior cut vertices; 0 elsewhere). Bit k is corner k.
  std::vector<unsigned char> LeftCorners;
  std::string Error;

  /// The covering vertex of input vertex v in copy i (v not a cone, i in [0, Copies)).
  Index Vertex(int copy, Index v) const;
  /// Points of the covering: every covering vertex at the position of its source vertex.
  Points CoveringPoints(const Points& points) const;
  Index NumberOfInputVertices = 0;
  std::vector<Index> NonConeRank;
};

/// Builds the covering of the closed, consistently oriented genus-0 mesh cut along `cutPath`
/// (an edge path of at least two edges between the two cones, no vertex twice). Returns false
/// with covering.Error set if the path is not such a path, or if the fan of a cut vertex
/// cannot be split into the two sides of the cut (a non-manifold vertex).
bool BuildCyclicCovering(Index numberOfPoints, const Triangles& triangles,
  const std::vector<Index>& cutPath, int copies, CyclicCovering& covering);
}

#endif
