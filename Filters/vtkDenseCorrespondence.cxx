#include "vtkDenseCorrespondence.h"

#include "SphericalPointLocator.h"
#include "vtkSphericalMapData.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <sstream>

vtkStandardNewMacro(vtkDenseCorrespondence);

namespace
{
// The located-in mesh's triangle vertex ids and barycentric weights of each query.
struct Correspondence
{
  std::vector<mobius::SphericalLocation> Locations;
  const mobius::Triangles* Triangles = nullptr;

  vtkIdType Vertex(size_t query, int k) const
  {
    return (*this->Triangles)(this->Locations[query].Triangle, k);
  }
  vtkIdType NearestVertex(size_t query) const
  {
    Eigen::Index k;
    this->Locations[query].Barycentric.maxCoeff(&k);
    return this->Vertex(query, static_cast<int>(k));
  }
};

// Floating-point arrays are interpolated; integer, string and other arrays hold categories
// or ids that must not be averaged, so they take the nearest vertex's value.
vtkSmartPointer<vtkAbstractArray> Transfer(vtkAbstractArray* source, const Correspondence& map)
{
  vtkSmartPointer<vtkAbstractArray> result;
  result.TakeReference(source->NewInstance());
  result->SetName(source->GetName());
  result->SetNumberOfComponents(source->GetNumberOfComponents());
  const size_t n = map.Locations.size();
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
        ids->SetId(k, map.Vertex(q, k));
        weights[k] = map.Locations[q].Barycentric[k];
      }
      data->InterpolateTuple(static_cast<vtkIdType>(q), ids, source, weights);
    }
    else
    {
      result->SetTuple(static_cast<vtkIdType>(q), map.NearestVertex(q), source);
    }
  }
  return result;
}

std::string CheckSurfacePoints(vtkPolyData* map)
{
  vtkDataArray* surface = map->GetPointData()->GetArray(mobius::vtk::SurfacePointsArrayName);
  if (!surface || surface->GetNumberOfComponents() != 3 ||
    surface->GetNumberOfTuples() != map->GetNumberOfPoints())
  {
    return std::string("it has no 3-component point array '") +
      mobius::vtk::SurfacePointsArrayName +
      "' (the original surface positions; vtkSphericalConformalMap makes it)";
  }
  return {};
}
}

//------------------------------------------------------------------------------
vtkDenseCorrespondence::vtkDenseCorrespondence()
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
int vtkDenseCorrespondence::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkDenseCorrespondence::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // No exception may leave the pipeline (in ParaView it would end the application): running
  // out of memory, or a failure in a worker thread, becomes this filter's error.
  try
  {
    return this->ComputeOutput(request, inputVector, outputVector);
  }
  catch (...)
  {
    return mobius::vtk::ReportException(this, outputVector);
  }
}

//------------------------------------------------------------------------------
int vtkDenseCorrespondence::ComputeOutput(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* inputs[2] = { vtkPolyData::GetData(inputVector[0]),
    vtkPolyData::GetData(inputVector[1]) };
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!inputs[0] || !inputs[1] || !output)
  {
    vtkErrorMacro(<< "Both a Source (port 0) and a Target (port 1) spherical map are required.");
    return 0;
  }
  // The query mesh's vertices are located in the other one.
  const int query = this->Direction == SOURCE_TO_TARGET ? 0 : 1;
  const int located = 1 - query;
  const char* names[2] = { "Source (port 0)", "Target (port 1)" };

  mobius::Points points[2];
  mobius::Triangles triangles[2];
  for (int k = 0; k < 2; ++k)
  {
    std::string error = mobius::vtk::ExtractPoints(inputs[k], points[k]);
    if (error.empty())
    {
      error = mobius::vtk::ExtractTriangles(inputs[k], triangles[k]);
    }
    if (error.empty() && k == located && triangles[k].rows() == 0)
    {
      error = "it has no triangles to locate points in";
    }
    if (error.empty())
    {
      error = mobius::vtk::CheckOnUnitSphere(points[k]);
    }
    if (error.empty() && (k == located || this->OutputGeometry == SOURCE))
    {
      error = CheckSurfacePoints(inputs[k]);
    }
    if (!error.empty())
    {
      vtkErrorMacro(<< "Cannot map: the " << names[k] << ": " << error << ".");
      return 0;
    }
  }

  mobius::SphericalPointLocator locator;
  std::string error;
  if (!locator.Build(points[located], triangles[located], error))
  {
    vtkErrorMacro(<< "Cannot map: the " << names[located] << ": " << error << ".");
    return 0;
  }
  this->UpdateProgress(0.2);
  Correspondence map;
  map.Triangles = &triangles[located];
  auto progress = [this](double fraction) {
    this->UpdateProgress(0.2 + 0.6 * fraction);
    return !this->GetAbortExecute();
  };
  if (!locator.LocateAll(points[query], map.Locations, 0, progress))
  {
    if (!this->GetAbortExecute())
    {
      vtkErrorMacro(<< "Point location failed.");
    }
    return 0;
  }

  vtkPolyData* queryMesh = inputs[query];
  vtkPolyData* locatedMesh = inputs[located];
  output->ShallowCopy(queryMesh);
  vtkPointData* outPD = output->GetPointData();

  vtkNew<vtkIdTypeArray> cellIds;
  cellIds->SetName("TargetCellId");
  vtkNew<vtkDoubleArray> barycentric;
  barycentric->SetName("TargetBarycentric");
  barycentric->SetNumberOfComponents(3);
  vtkIdType clamped = 0;
  double maximumClampDistance = 0;
  for (const auto& location : map.Locations)
  {
    cellIds->InsertNextValue(location.Triangle);
    barycentric->InsertNextTuple(location.Barycentric.data());
    clamped += location.Clamped ? 1 : 0;
    maximumClampDistance = std::max(maximumClampDistance, location.AngularDistance);
  }
  auto mapped = Transfer(
    locatedMesh->GetPointData()->GetArray(mobius::vtk::SurfacePointsArrayName), map);
  mapped->SetName("MappedPoints");
  for (int a = 0; a < locatedMesh->GetPointData()->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = locatedMesh->GetPointData()->GetAbstractArray(a);
    if (!array->GetName() ||
      std::string(array->GetName()) == mobius::vtk::SurfacePointsArrayName)
    {
      continue;
    }
    auto transferred = Transfer(array, map);
    // The target's InputPointId always gets the suffix: under its own name it would pass
    // for the source's numbering.
    if (outPD->HasArray(array->GetName()) ||
      std::string(array->GetName()) == mobius::vtk::InputPointIdArrayName)
    {
      transferred->SetName((std::string(array->GetName()) + "_Target").c_str());
    }
    outPD->AddArray(transferred);
  }
  outPD->AddArray(cellIds);
  outPD->AddArray(barycentric);
  outPD->AddArray(mapped);
  // TargetCellId names a triangle of the target map, whose point numbering repairs changed:
  // give its vertices in the target's input (file) numbering too.
  vtkDataArray* targetIds =
    locatedMesh->GetPointData()->GetArray(mobius::vtk::InputPointIdArrayName);
  if (targetIds && targetIds->GetNumberOfComponents() == 1 &&
    targetIds->GetNumberOfTuples() == locatedMesh->GetNumberOfPoints())
  {
    vtkNew<vtkIdTypeArray> cornerIds;
    cornerIds->SetName("TargetInputPointIds");
    cornerIds->SetNumberOfComponents(3);
    cornerIds->SetNumberOfTuples(static_cast<vtkIdType>(map.Locations.size()));
    for (size_t q = 0; q < map.Locations.size(); ++q)
    {
      for (int k = 0; k < 3; ++k)
      {
        cornerIds->SetTypedComponent(static_cast<vtkIdType>(q), k,
          static_cast<vtkIdType>(targetIds->GetComponent(map.Vertex(q, k), 0)));
      }
    }
    outPD->AddArray(cornerIds);
  }

  vtkNew<vtkPoints> outputPoints;
  outputPoints->SetDataTypeToDouble();
  outputPoints->SetData(this->OutputGeometry == TARGET
      ? vtkDataArray::SafeDownCast(mapped)
      : queryMesh->GetPointData()->GetArray(mobius::vtk::SurfacePointsArrayName));
  output->SetPoints(outputPoints);

  mobius::vtk::SetFieldValue(output->GetFieldData(), "ClampedPoints", static_cast<double>(clamped));
  mobius::vtk::SetFieldValue(output->GetFieldData(), "MaximumClampDistance", maximumClampDistance);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkDenseCorrespondence::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OutputGeometry: " << this->OutputGeometry << "\n";
  os << indent << "Direction: " << this->Direction << "\n";
}
