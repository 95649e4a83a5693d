// The steps of RepairMesh's Repair mode (RepairMesh.h), each a function of its own: from a
// mesh with any defects to a closed, oriented, connected genus-0 proxy, or the reason none
// can be made.
#ifndef mobius_GenusZeroProxy_h
#define mobius_GenusZeroProxy_h

#include "RepairMesh.h"

#include <string>

namespace mobius
{
/// Repairs `points` and `triangles` into a genus-0 proxy, composing each step's provenance
/// into `provenance` and recording it in `log`. Returns the reason when no proxy can be made
/// (loose parts of comparable size without KeepLargestComponent, nothing left, too many
/// handles); empty on success.
std::string RepairIntoGenusZeroProxy(Points& points, Triangles& triangles,
  MeshProvenance& provenance, MeshRepairLog& log, const MeshRepairOptions& options);

/// The summed area of the valid triangles.
double SurfaceArea(const Points& points, const Triangles& triangles);
}

#endif
