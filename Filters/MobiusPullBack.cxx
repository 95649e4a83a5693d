#include "MobiusPullBack.h"

#include "MobiusCorrespondenceOutput.h"
#include "MobiusSphericalMapData.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkGenericCell.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkCellLocator.h"

namespace mobius
{
namespace vtk
{
namespace
{
// For every point of `queries`, the triangle of `placed` holding its closest point and that
// point's barycentric weights.
SurfaceLocations LocateClosest(vtkPolyData* placed, vtkDataArray* queries)
{
  // vtkCellLocator: VTK 9.2's vtkStaticCellLocator gives wrong closest points (measured by
  // TestPullBackToTarget: off by a quarter of the radius on a sphere).
  vtkNew<vtkCellLocator> locator;
  locator->SetDataSet(placed);
  locator->BuildLocator();
  SurfaceLocations locations;
  const vtkIdType n = queries->GetNumberOfTuples();
  locations.Triangle.resize(static_cast<size_t>(n));
  locations.Barycentric.resize(static_cast<size_t>(n));
  vtkNew<vtkGenericCell> cell;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double point[3], closest[3], parametric[3], weights[3] = { 1, 0, 0 }, distance2 = 0;
    queries->GetTuple(i, point);
    vtkIdType cellId = 0;
    int subId = 0;
    locator->FindClosestPoint(point, closest, cell, cellId, subId, distance2);
    cell->EvaluatePosition(closest, nullptr, subId, parametric, distance2, weights);
    locations.Triangle[static_cast<size_t>(i)] = cellId;
    locations.Barycentric[static_cast<size_t>(i)] = Eigen::Vector3d(weights[0], weights[1], weights[2]);
  }
  return locations;
}
}

bool PullBackToTarget(
  vtkPolyData* sourceMap, vtkDataArray* mappedPoints, vtkPolyData* targetMap, vtkPolyData* output)
{
  output->Initialize();
  vtkDataArray* targetSurface = targetMap->GetPointData()->GetArray(SurfacePointsArrayName);
  Triangles sourceTriangles;
  if (!mappedPoints || !targetSurface ||
    mappedPoints->GetNumberOfTuples() != sourceMap->GetNumberOfPoints() ||
    !ExtractTriangles(sourceMap, sourceTriangles).empty() || sourceTriangles.rows() == 0)
  {
    return false;
  }
  vtkNew<vtkPolyData> placed;
  vtkNew<vtkPoints> placedPoints;
  placedPoints->SetData(mappedPoints);
  placed->SetPoints(placedPoints);
  placed->SetPolys(sourceMap->GetPolys());
  SurfaceLocations locations = LocateClosest(placed, targetSurface);
  locations.LocatedTriangles = &sourceTriangles;
  LocatedNames names;
  names.Prefix = "Source";
  names.MappedPoints = "SourcePoints";
  AssembleCorrespondence(targetMap, sourceMap, locations, false, output, names);
  // The target map's own field data describes its stages, reported on the first output.
  vtkNew<vtkFieldData> noFields;
  output->SetFieldData(noFields);
  return true;
}
}
}
