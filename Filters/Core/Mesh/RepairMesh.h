// The repairs that turn a triangle mesh into what the spherical conformal map needs (a
// closed, oriented, connected genus-0 surface), or the reason it cannot be.
//
// A mesh that is one already is left as it is, bit for bit. Two repairs change nothing a
// user could want kept and are always done: a triangle soup's duplicated points merged, edges
// of zero length collapsed. With Repair (the default), whatever else keeps the mesh from
// being a topological sphere is repaired into a genus-0 *proxy* of it: triangles naming a
// point twice, touching a point with a NaN coordinate, or repeating another triangle removed;
// vertices split where their triangles form several fans (non-manifold edges and vertices);
// the triangles oriented consistently (where no orientation agrees, cut open where they
// disagree); loose parts small against the largest dropped; holes closed with faired patches
// (HoleFilling.h); handles cut along short non-separating loops and the cuts closed
// (HandleCutting.h). Every repair is counted and measured (MeshRepairLog), and where each
// point and triangle of the proxy came from is kept so that callers can carry their
// attributes and report results on the user's own vertices. Without Repair (strict mode)
// only FillHoles and KeepLargestComponent repair, on request, and anything else is refused
// with the option that would repair it.
#ifndef mobius_RepairMesh_h
#define mobius_RepairMesh_h

#include "MeshTopology.h"
#include "MeshTypes.h"

#include <string>
#include <vector>

namespace mobius
{
/// The repairs asked for. No defaults here: RegistrationParameters holds them.
struct MeshRepairOptions
{
  bool Repair;               ///< build a genus-0 proxy of whatever can be made one
  bool FillHoles;            ///< strict mode: close holes
  bool KeepLargestComponent; ///< keep only the largest part, whatever the others' size
};

/// Loose parts whose area is below this share of the largest part's are dropped by Repair;
/// larger ones are refused (which to map is the user's choice: KeepLargestComponent). A
/// part of a body that came loose is below it (CGAL's man, parts by its skeleton: a leg with
/// its foot 22% of the rest of him, an arm 12%, the head 10%, a hand 2%); two bodies in one
/// file are far above it.
constexpr double kLooseComponentShare = 0.25;

/// Handles cut at most: more are the tunnels of a scan's noise, or a mesh that is not one
/// closed surface, which the map could not use anyway.
constexpr int kMaximumHandleCuts = 64;

/// What a repair did, with sizes, for the warning and the field data.
struct MeshRepairLog
{
  Index MergedDuplicatePoints = 0;
  /// Edges whose two ends were at one position, collapsed (see CollapseZeroLengthEdges).
  Index CollapsedEdges = 0;
  Index RemovedRepeatedVertexTriangles = 0;
  Index RemovedNonFiniteTriangles = 0; ///< touching a point with a NaN or infinite coordinate
  Index RemovedDuplicateTriangles = 0;
  Index SplitVertices = 0;    ///< non-manifold vertices split into one copy per fan
  Index ReversedTriangles = 0; ///< turned to agree with their neighbours
  Index OrientationCutEdges = 0; ///< edges cut open where no orientation agrees
  Index DroppedComponents = 0;
  Index DroppedComponentTriangles = 0;
  double DroppedComponentArea = 0;
  Index FilledHoles = 0;
  Index FilledBoundaryEdges = 0;
  double FilledArea = 0;
  /// Handles cut, and each cut loop's length.
  std::vector<double> HandleLoopLengths;
  /// Points no triangle used (or only removed ones), dropped.
  Index DroppedUnusedPoints = 0;
  /// The area of the mesh as given (its valid triangles) and of the proxy: the shares in
  /// Describe are of the first, loop lengths over the square root of the second.
  double InputArea = 0;
  double ProxyArea = 0;

  /// True if any repair changed the mesh.
  bool Any() const;
  /// The repairs as readable phrases with their sizes, e.g. "3 holes filled (100 boundary
  /// edges, 0.4% of the area)", "1 handle cut (loop length 0.08 sqrt(area))"; empty if none.
  std::vector<std::string> Describe() const;
};

struct RepairedMesh
{
  mobius::Points Points;
  mobius::Triangles Triangles;
  /// Per output point and triangle, its row in the mesh given to RepairMesh; -1: created by
  /// a repair (a hole's patch). A split vertex's copies share their source.
  MeshProvenance Provenance;
  MeshRepairLog Log;
  /// The topology of the repaired mesh.
  MeshTopologyReport Topology;
  /// Why the repaired mesh is not a topological sphere, with the option that would repair
  /// each problem (e.g. "2 connected components. Set KeepLargestComponent to map only the
  /// largest component"); empty if it is one.
  std::string Problem;
};

/// Repairs `points` and `triangles` (see above).
RepairedMesh RepairMesh(Points points, Triangles triangles, const MeshRepairOptions& options);

/// Drops points no triangle uses (e.g. the copies left by merging duplicates) and
/// renumbers the triangles.
MeshProvenance RemoveUnusedPoints(Points& points, Triangles& triangles);
}

#endif
