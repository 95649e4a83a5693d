/**
 * @file MobiusPullBack.h
 * @brief A map shown on the target's own mesh.
 *
 * A correspondence is the source's mesh placed on the target (its `MappedPoints`): where the
 * map is many-to-one that mesh folds over itself, and parts of the target it misses are not
 * drawn. The pull-back goes the other way: every vertex of the target's own mesh takes the
 * source's point arrays at its closest point on the placed source. vtkMobiusRegistration
 * gives it as its fourth output, mobius-register --png draws it.
 */
#ifndef MobiusPullBack_h
#define MobiusPullBack_h

#include "vtkMobiusRegistrationFiltersModule.h" // For export macro

class vtkDataArray;
class vtkPolyData;

namespace mobius
{
namespace vtk
{
/// Fills `output` with the target's map `targetMap` (its connectivity and point arrays, its
/// points at its `SurfacePoints`: the target's own surface) and, per vertex, where on the
/// source it comes from: `SourceCellId`, `SourceBarycentric` (a triangle of `sourceMap` and
/// the weights of the closest point of the placed source), `SourcePoints` (that point on
/// the source's surface), `SourceInputPointIds`, and the source's point arrays carried back
/// (floating-point arrays interpolated, others from the nearest vertex; a clash gets
/// `_Source`). `sourceMap`: the source's map with `SurfacePoints` (the correspondence's query
/// mesh: the same points and triangles); `mappedPoints`: where the map sends each of its
/// points. False (output empty) when the sizes disagree or the placed source has no
/// triangle.
VTKMOBIUSREGISTRATIONFILTERS_EXPORT bool PullBackToTarget(
  vtkPolyData* sourceMap, vtkDataArray* mappedPoints, vtkPolyData* targetMap,
  vtkPolyData* output);
}
}

#endif
