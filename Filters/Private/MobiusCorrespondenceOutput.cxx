#include "MobiusCorrespondenceOutput.h"

#include "MobiusSphericalMapData.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <string>

namespace mobius
{
namespace vtk
{
namespace
{
vtkIdType Vertex(const SurfaceLocations& map, size_t query, int k)
{
  return (*map.LocatedTriangles)(map.Triangle[query], k);
}

vtkIdType NearestVertex(const SurfaceLocations& map, size_t query)
{
  Eigen::Index k;
  map.Barycentric[query].maxCoeff(&k);
  return Vertex(map, query, static_cast<int>(k));
}

// Floating-point arrays are interpolated; integer, string and other arrays hold categories
// or ids that must not be averaged, so they take the nearest vertex's value.
vtkSmartPointer<vtkAbstractArray> Transfer(vtkAbstractArray* source, const SurfaceLocations& map)
{
  vtkSmartPointer<vtkAbstractArray> result;
  result.TakeReference(source->NewInstance());
  result->SetName(source->GetName());
  result->SetNumberOfComponents(source->GetNumberOfComponents());
  const size_t n = map.Triangle.size();
  result->SetNumberOfTuples(static_cast<vtkIdType>(n));
  auto data = vtkDataArray::SafeDownCast(result);
  const bool interpolate =
    data && (source->GetDataType() == VTK_FLOAT || source->GetDataType() == VTK_DOUBLE);
  vtkNew<vtkIdList> ids;
  ids->SetNumberOfIds(3);
  for (size_t q = 0; q < n; ++q)
  {
    if (interpolate)
    {
      double weights[3];
      for (int k = 0; k < 3; ++k)
      {
        ids->SetId(k, Vertex(map, q, k));
        weights[k] = map.Barycentric[q][k];
      }
      data->InterpolateTuple(static_cast<vtkIdType>(q), ids, source, weights);
    }
    else
    {
      result->SetTuple(static_cast<vtkIdType>(q), NearestVertex(map, q), source);
    }
  }
  return result;
}

// Values of a floating-point array that are NaN or infinite (0 for other arrays).
vtkIdType NonFiniteValues(vtkAbstractArray* array)
{
  auto data = vtkDataArray::SafeDownCast(array);
  if (!data || (array->GetDataType() != VTK_FLOAT && array->GetDataType() != VTK_DOUBLE))
  {
    return 0;
  }
  vtkIdType count = 0;
  const vtkIdType values = data->GetNumberOfValues();
  for (vtkIdType k = 0; k < values; ++k)
  {
    count += std::isfinite(data->GetComponent(k / data->GetNumberOfComponents(),
               static_cast<int>(k % data->GetNumberOfComponents())))
      ? 0
      : 1;
  }
  return count;
}
}

std::string AssembleCorrespondence(vtkPolyData* queryMesh, vtkPolyData* locatedMesh,
  const SurfaceLocations& locations, bool pointsOnTarget, vtkPolyData* output,
  const LocatedNames& names)
{
  std::string warning;
  output->ShallowCopy(queryMesh);
  vtkPointData* outPD = output->GetPointData();

  vtkNew<vtkIdTypeArray> cellIds;
  cellIds->SetName((names.Prefix + "CellId").c_str());
  cellIds->SetNumberOfTuples(static_cast<vtkIdType>(locations.Triangle.size()));
  vtkNew<vtkDoubleArray> barycentric;
  barycentric->SetName((names.Prefix + "Barycentric").c_str());
  barycentric->SetNumberOfComponents(3);
  barycentric->SetNumberOfTuples(static_cast<vtkIdType>(locations.Triangle.size()));
  for (size_t q = 0; q < locations.Triangle.size(); ++q)
  {
    cellIds->SetValue(static_cast<vtkIdType>(q), locations.Triangle[q]);
    barycentric->SetTuple(static_cast<vtkIdType>(q), locations.Barycentric[q].data());
  }
  auto mapped =
    Transfer(locatedMesh->GetPointData()->GetArray(SurfacePointsArrayName), locations);
  mapped->SetName(names.MappedPoints.c_str());
  for (int a = 0; a < locatedMesh->GetPointData()->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = locatedMesh->GetPointData()->GetAbstractArray(a);
    if (!array->GetName() || std::string(array->GetName()) == SurfacePointsArrayName)
    {
      continue;
    }
    const vtkIdType nonFinite = NonFiniteValues(array);
    if (nonFinite > 0 && warning.empty())
    {
      warning = "the point array '" + std::string(array->GetName()) + "' holds " +
        std::to_string(nonFinite) + " NaN or infinite values, which the map carries over: "
        "a point mapped next to one of them gets NaN or infinity in that array";
    }
    auto transferred = Transfer(array, locations);
    // The located mesh's InputPointId always gets the suffix: under its own name it would
    // pass for the query mesh's numbering.
    if (outPD->HasArray(array->GetName()) ||
      std::string(array->GetName()) == InputPointIdArrayName)
    {
      transferred->SetName((std::string(array->GetName()) + "_" + names.Prefix).c_str());
    }
    outPD->AddArray(transferred);
  }
  outPD->AddArray(cellIds);
  outPD->AddArray(barycentric);
  outPD->AddArray(mapped);
  // TargetCellId names a triangle of the target map, whose point numbering repairs changed:
  // give its vertices in the target's input (file) numbering too (the same for the source).
  vtkDataArray* targetIds = locatedMesh->GetPointData()->GetArray(InputPointIdArrayName);
  if (targetIds && targetIds->GetNumberOfComponents() == 1 &&
    targetIds->GetNumberOfTuples() == locatedMesh->GetNumberOfPoints())
  {
    vtkNew<vtkIdTypeArray> cornerIds;
    cornerIds->SetName((names.Prefix + "InputPointIds").c_str());
    cornerIds->SetNumberOfComponents(3);
    cornerIds->SetNumberOfTuples(static_cast<vtkIdType>(locations.Triangle.size()));
    for (size_t q = 0; q < locations.Triangle.size(); ++q)
    {
      for (int k = 0; k < 3; ++k)
      {
        cornerIds->SetTypedComponent(static_cast<vtkIdType>(q), k,
          static_cast<vtkIdType>(targetIds->GetComponent(Vertex(locations, q, k), 0)));
      }
    }
    outPD->AddArray(cornerIds);
  }

  vtkNew<vtkPoints> outputPoints;
  outputPoints->SetDataTypeToDouble();
  outputPoints->SetData(pointsOnTarget
      ? vtkDataArray::SafeDownCast(mapped)
      : queryMesh->GetPointData()->GetArray(SurfacePointsArrayName));
  output->SetPoints(outputPoints);
  return warning;
}
}
}
