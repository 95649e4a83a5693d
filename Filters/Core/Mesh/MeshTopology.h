// Topology analysis and small repairs of triangle meshes, so that the filters can say
// precisely why an input cannot be mapped to the sphere ("3 boundary loops (holes)") and
// offer the repairs that make it mappable (merge a triangle soup's duplicated points, keep
// the largest component, fill holes, orient the triangles consistently).
#ifndef mobius_MeshTopology_h
#define mobius_MeshTopology_h

#include "MeshTypes.h"

#include <string>
#include <utility>
#include <vector>

namespace mobius
{
/// Counts describing what kind of surface a triangle array is. Edges and everything built on
/// them only consider the valid triangles (indices in range, three distinct points).
struct MeshTopologyReport
{
  Index NumberOfPoints = 0;
  Index NumberOfTriangles = 0;
  Index NonFinitePoints = 0;         ///< points with a NaN or infinite coordinate
  Index InvalidTriangles = 0;        ///< triangles with an index outside [0, NumberOfPoints)
  Index RepeatedVertexTriangles = 0; ///< triangles naming the same point twice
  Index ZeroAreaTriangles = 0;       ///< three distinct points but (numerically) no area
  Index DuplicateTriangles = 0;      ///< the same three points as an earlier triangle, either way round
  Index DuplicatePoints = 0;         ///< points with exactly the coordinates of another point
  Index UnusedPoints = 0;            ///< points no valid triangle refers to
  Index Edges = 0;
  Index BoundaryEdges = 0;      ///< edges with one triangle
  Index BoundaryLoops = 0;      ///< closed chains of boundary edges, i.e. holes
  Index NonManifoldEdges = 0;   ///< edges with more than two triangles
  Index NonManifoldVertices = 0; ///< vertices whose triangles form more than one fan
  Index InconsistentlyOrientedEdges = 0; ///< two-triangle edges traversed twice the same way
  Index ConnectedComponents = 0; ///< edge-connected pieces of the valid triangles
  Index EulerCharacteristic = 0; ///< used points - edges + valid triangles
  /// (2 - EulerCharacteristic) / 2 for a closed, manifold, consistently oriented, connected
  /// surface; -1 when the genus is not defined.
  int Genus = -1;

  /// Every edge has two triangles and every vertex a single fan.
  bool IsClosedManifold() const;
  /// What the spherical conformal map needs: a closed, oriented, connected genus-0 surface
  /// with finite coordinates and no triangle naming a point twice. Zero-area triangles are
  /// geometry, not topology: the intrinsic Delaunay weights take them.
  bool IsTopologicalSphere() const;
};

/// Analyzes the triangles; runs in O(points log points + triangles) (the log: finding
/// duplicate points by sorting them).
MeshTopologyReport AnalyzeMeshTopology(const Points& points, const Triangles& triangles);

/// The problems that keep the mesh from being a topological sphere, as readable phrases
/// separated by "; " (e.g. "3 boundary loops (holes); 2 connected components"); empty if none.
/// The filters prepend their own context and append the option that repairs each problem.
std::string DescribeTopologyProblems(const MeshTopologyReport& report);

/// Where each row of a repaired mesh came from, so callers can carry their point and cell
/// attributes along. -1 marks a point or triangle the repair created.
struct MeshProvenance
{
  std::vector<Index> PointSource;
  std::vector<Index> TriangleSource;
};

/// Each row its own source.
MeshProvenance IdentityProvenance(Index points, Index triangles);

/// Follows `provenance` (rows of the original mesh) by a repair's `step` (rows of the mesh
/// before it): afterwards each row names its source in the original mesh; -1 stays -1.
void ComposeProvenance(MeshProvenance& provenance, const MeshProvenance& step);

/// Merges points with exactly equal coordinates (a triangle soup, or an STL-style file) into
/// their first occurrence, renumbers the triangles and drops those that then name a point
/// twice. Unused points are kept, so that merging alone changes nothing else.
MeshProvenance MergeDuplicatePoints(Points& points, Triangles& triangles);

/// Collapses every edge whose two ends are at exactly the same position (a triangle with two
/// corners in one place): the ends are merged into the lower-numbered one, and the triangles
/// that then name a point twice (those on the edge) are dropped. The surface is the same, and
/// its cotangent weights are defined again. The merged-away points are kept, unused.
/// `collapsed` receives the number of edges collapsed.
MeshProvenance CollapseZeroLengthEdges(Points& points, Triangles& triangles, Index* collapsed);

/// Keeps the edge-connected component with the most triangles and the points it uses.
/// Invalid triangles (bad index, repeated point) are dropped as well.
MeshProvenance ExtractLargestComponent(Points& points, Triangles& triangles);

/// An edge by its two end points, smaller first.
using EdgeKey = std::pair<Index, Index>;

inline EdgeKey MakeEdgeKey(Index a, Index b)
{
  return a < b ? EdgeKey(a, b) : EdgeKey(b, a);
}

/// Reverses triangles so that every two-triangle edge is traversed once in each direction,
/// component by component (each component keeps the orientation of its first triangle).
/// Returns false when the surface is not orientable or has non-manifold edges. Without
/// `disagreeing`, the triangles are then left unchanged; with it, a surface with no orientation
/// is still oriented along a breadth-first spanning tree of its triangles, and `disagreeing`
/// receives (sorted) the edges where two triangles still disagree: cut there, it is oriented.
/// `reversedTriangles` receives how many triangles were reversed.
bool OrientConsistently(Triangles& triangles, Index* reversedTriangles = nullptr,
  std::vector<EdgeKey>* disagreeing = nullptr);
}

#endif
