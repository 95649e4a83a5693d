#include "vtkDenseCorrespondence.h"

#include "MeshAdjacency.h"
#include "RegistrationParameters.h"
#include "ParallelFor.h"
#include "SphericalPointLocator.h"
#include "MobiusCorrespondenceOutput.h"
#include "MobiusSphericalMapData.h"

#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <sstream>

vtkStandardNewMacro(vtkDenseCorrespondence);

//------------------------------------------------------------------------------
vtkDenseCorrespondence::vtkDenseCorrespondence()
{
  this->SetNumberOfInputPorts(2);
  const mobius::RegistrationParameters defaults;
  this->OutputGeometry = defaults.OutputGeometry;
  this->NumberOfThreads = defaults.NumberOfThreads;
}

//------------------------------------------------------------------------------
int vtkDenseCorrespondence::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
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
      error = mobius::vtk::CheckSurfacePoints(inputs[k]);
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
  std::vector<mobius::SphericalLocation> locations;
  auto progress = [this](double fraction) {
    this->UpdateProgress(0.2 + 0.6 * fraction);
    return !this->GetAbortExecute();
  };
  const int threads = mobius::ResolveThreadCount(this->NumberOfThreads);
  if (!locator.LocateAll(points[query], locations, threads, progress))
  {
    if (!this->GetAbortExecute())
    {
      vtkErrorMacro(<< "Point location failed.");
    }
    return 0;
  }

  mobius::vtk::SurfaceLocations map;
  map.LocatedTriangles = &triangles[located];
  vtkIdType clamped = 0;
  double maximumClampDistance = 0;
  for (const auto& location : locations)
  {
    map.Triangle.push_back(location.Triangle);
    map.Barycentric.push_back(location.Barycentric);
    clamped += location.Clamped ? 1 : 0;
    maximumClampDistance = std::max(maximumClampDistance, location.AngularDistance);
  }
  // The landmarks on their own vertices: the located mesh's landmark, a triangle's corner.
  error = mobius::vtk::CheckLandmarkPoints(this->Landmarks, points[0].rows(), points[1].rows());
  const mobius::VertexLists corners =
    mobius::VertexTriangles(points[located].rows(), triangles[located]);
  for (size_t k = 0; error.empty() && k < this->Landmarks.size(); ++k)
  {
    const vtkIdType ends[2] = { this->Landmarks[k].first, this->Landmarks[k].second };
    const vtkIdType from = ends[query], to = ends[located];
    if (corners.Begin(to) == corners.End(to))
    {
      error = "landmark " + std::to_string(k) + " names point " + std::to_string(to) +
        ", which is in no triangle";
      break;
    }
    mobius::PlaceAtVertex(triangles[located], corners, to, map.Triangle[from], map.Barycentric[from]);
  }
  if (!error.empty())
  {
    vtkErrorMacro(<< "Cannot map: " << error << ".");
    return 0;
  }
  const std::string arrayWarning = mobius::vtk::AssembleCorrespondence(
    inputs[query], inputs[located], map, this->OutputGeometry == TARGET, output);
  if (!arrayWarning.empty())
  {
    vtkWarningMacro(<< (located == 1 ? "Target: " : "Source: ") << arrayWarning << ".");
  }

  mobius::vtk::SetFieldCount(
    output->GetFieldData(), "ClampedPoints", static_cast<vtkIdType>(clamped));
  mobius::vtk::SetFieldValue(output->GetFieldData(), "MaximumClampDistance", maximumClampDistance);
  mobius::vtk::SetFieldInteger(output->GetFieldData(), "NumberOfThreadsUsed", threads);
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
