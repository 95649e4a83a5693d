/**
 * @file MobiusCorrespondenceOutput.h
 * @brief The output of a dense correspondence, shared by vtkDenseCorrespondence and
 * vtkCorrespondenceRefinement so that both honour one data contract (private to the module).
 *
 * Given, for every vertex of the query mesh, a triangle of the located mesh and barycentric
 * coordinates in it, builds the output: the query mesh's connectivity and point arrays,
 * `TargetCellId`, `TargetBarycentric`, `MappedPoints` (the located mesh's `SurfacePoints`
 * interpolated), every other point array of the located mesh transferred (floating-point
 * arrays interpolated, others from the nearest vertex; a name clash gets `_Target`), and the
 * points placed on the target surface or kept on the source surface.
 */
#ifndef MobiusCorrespondenceOutput_h
#define MobiusCorrespondenceOutput_h

#include "MeshTypes.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace mobius
{
namespace vtk
{
struct SurfaceLocations
{
  const Triangles* LocatedTriangles = nullptr;
  std::vector<Index> Triangle;
  std::vector<Eigen::Vector3d> Barycentric;
};

/// What the output calls the located mesh's data: "Target" for a map onto the target
/// (`TargetCellId`, `TargetBarycentric`, `TargetInputPointIds`, a clash suffix `_Target`,
/// and `MappedPoints`); the pull-back onto the target's own mesh (MobiusPullBack.h) names
/// the source the same way.
struct LocatedNames
{
  std::string Prefix = "Target";
  std::string MappedPoints = "MappedPoints";
};

/// Fills `output` as described above. `pointsOnTarget` places the output's points at the
/// mapped positions, otherwise at the query mesh's own `SurfacePoints`. Returns a warning
/// for the filter to give, or an empty string: a floating-point array of the located mesh
/// that holds NaN or infinite values, which interpolation carries into the output (a NaN
/// corner makes the mapped value NaN).
std::string AssembleCorrespondence(vtkPolyData* queryMesh, vtkPolyData* locatedMesh,
  const SurfaceLocations& locations, bool pointsOnTarget, vtkPolyData* output,
  const LocatedNames& names = LocatedNames());
}
}

#endif
