/**
 * @file MobiusInputRows.h
 * @brief The correspondence on the meshes as given, when a repair changed one (private to
 * the module).
 *
 * The pipeline maps the repaired proxies (vtkSphericalConformalMap's outputs): their vertices
 * are not the user's when a repair merged, dropped, split or added some, and their
 * triangles not the user's when it removed, cut or added some. The user's outputs have one
 * row per vertex of the source as given, in its numbering, and name target triangles and
 * vertices as given: each source vertex takes the image of its own proxy point, or, when
 * the proxy has none (merged into a duplicate, dropped with a loose part or with the
 * triangles the repair removed), the image of its closest point on the proxy; an image on a
 * patch the repair created on the target is moved to the closest point of the target as
 * given.
 */
#ifndef MobiusInputRows_h
#define MobiusInputRows_h

#include "vtkSmartPointer.h"

#include <string>

class vtkPolyData;

namespace mobius
{
namespace vtk
{
/// Point array of the correspondence on the inputs: per source vertex, 0 if its row is its
/// own proxy point's image on the target's own triangles; otherwise the sum of
/// kRepairedSourceVertex (the proxy has no point of it: the image of its closest point on the
/// proxy) and kImageMovedOffPatch (the image was on a patch the target's repair created).
constexpr const char* RepairedVertexArrayName = "RepairedVertex";
constexpr int kRepairedSourceVertex = 1;
constexpr int kImageMovedOffPatch = 2;

/// True when a repair changed `map` (a vtkSphericalConformalMap output: its field data
/// `MeshRepairs` is not empty), so that its rows and triangles are not its input's.
bool MapWasRepaired(vtkPolyData* map);

/// `mesh` as given (polygons split into triangles) with the arrays of a spherical map's
/// surface: point data `SurfacePoints` (its own points) and `InputPointId` (its own numbers),
/// for whatever shows a result on the user's own mesh.
vtkSmartPointer<vtkPolyData> SurfaceAsGiven(vtkPolyData* mesh);

/// `correspondence` (one row per point of `sourceMap`, triangles of `targetMap`) on the
/// meshes as given (see above): the source's points, cells and point arrays, the map's
/// arrays (`TargetCellId` and `TargetBarycentric` in the triangulated target as given,
/// `TargetInputPointIds`, `MappedPoints`, the target's point arrays carried over), its field
/// data, and `RepairedVertex`. `pointsOnTarget` as in vtkDenseCorrespondence. An empty
/// pointer and `error` set when a mesh cannot be located (no triangles).
vtkSmartPointer<vtkPolyData> CorrespondenceOnInputs(vtkPolyData* source, vtkPolyData* target,
  vtkPolyData* sourceMap, vtkPolyData* targetMap, vtkPolyData* correspondence,
  bool pointsOnTarget, std::string& error);
}
}

#endif
