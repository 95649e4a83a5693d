// The repairs that turn a triangle mesh into what the spherical conformal map needs (a
// closed, oriented, connected genus-0 surface), or the reason it cannot be: merge a
// triangle soup's duplicated points, collapse zero-length edges, keep the largest
// component, drop unused points, fill holes, orient the triangles consistently. Every
// repair is reported, and where each output point and triangle came from is kept so that
// callers can carry their attributes.
#ifndef mobius_RepairMesh_h
#define mobius_RepairMesh_h

#include "MeshTopology.h"
#include "MeshTypes.h"

#include <string>

namespace mobius
{
/// The repairs that change what a user may want kept, done only on request. No defaults
/// here: RegistrationParameters holds them.
struct MeshRepairOptions
{
  bool FillHoles;
  bool KeepLargestComponent;
};

struct RepairedMesh
{
  mobius::Points Points;
  mobius::Triangles Triangles;
  /// Per output point and triangle, its row in the mesh given to RepairMesh; -1: created by
  /// a repair (a hole's fill).
  MeshProvenance Provenance;
  Index MergedDuplicatePoints = 0;
  /// Edges whose two ends were at one position, collapsed (see CollapseZeroLengthEdges).
  Index CollapsedEdges = 0;
  Index FilledHoles = 0;
  /// The topology of the repaired mesh.
  MeshTopologyReport Topology;
  /// Why the repaired mesh is not a topological sphere, with the option that would repair
  /// each problem (e.g. "2 connected components. Set KeepLargestComponent to map only the
  /// largest component"); empty if it is one.
  std::string Problem;
};

/// Repairs `points` and `triangles` (see above). Repairs that change nothing a user could
/// want kept are always done; FillHoles and KeepLargestComponent on request.
RepairedMesh RepairMesh(Points points, Triangles triangles, const MeshRepairOptions& options);

/// Drops points no triangle uses (e.g. the copies left by merging duplicates) and
/// renumbers the triangles.
MeshProvenance RemoveUnusedPoints(Points& points, Triangles& triangles);
}

#endif
