#include "vtkDenseCorrespondence.h"

#include "DenseCorrespondence.h"
#include "MobiusCorrespondenceOutput.h"
#include "MobiusSphericalMapData.h"
#include "ParallelFor.h"
#include "RegistrationParameters.h"

#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <utility>

vtkStandardNewMacro(vtkDenseCorrespondence);

namespace
{
const char* const InputNames[2] = { "Source (port 0)", "Target (port 1)" };

// Input `input`'s spherical map as the core reads it; the problem if it cannot be read.
// The map points are located in (`located`) needs triangles; SurfacePoints are needed where
// they make the output (`needsSurface`).
std::string ReadMap(vtkPolyData* input, bool located, bool needsSurface, const char* name,
  mobius::CorrespondenceMap& map)
{
  map.Name = name;
  std::string error = mobius::vtk::ExtractPoints(input, map.Sphere);
  if (error.empty())
  {
    error = mobius::vtk::ExtractTriangles(input, map.Triangles);
  }
  if (error.empty() && located && map.Triangles.rows() == 0)
  {
    error = "it has no triangles to locate points in";
  }
  if (error.empty())
  {
    error = mobius::vtk::CheckOnUnitSphere(map.Sphere);
  }
  if (error.empty() && needsSurface)
  {
    error = mobius::vtk::CheckSurfacePoints(input);
  }
  return error;
}

// The filter's direction, landmarks, threads, progress and abort as the core's parameters.
mobius::DenseCorrespondenceParameters CorrespondenceParameters(
  vtkDenseCorrespondence* filter, int threads)
{
  mobius::DenseCorrespondenceParameters parameters;
  parameters.TargetToSource =
    filter->GetDirection() == vtkDenseCorrespondence::TARGET_TO_SOURCE;
  for (vtkIdType k = 0; k < filter->GetNumberOfLandmarks(); ++k)
  {
    parameters.Landmarks.emplace_back(
      filter->GetLandmarkSourceVertex(k), filter->GetLandmarkTargetVertex(k));
  }
  parameters.NumberOfThreads = threads;
  parameters.Progress = mobius::vtk::ProgressAndAbort(filter);
  return parameters;
}

// The query map with its points' places in the located map and the data carried over.
void WriteOutput(vtkDenseCorrespondence* filter, vtkPolyData* inputs[2],
  const mobius::Triangles& locatedTriangles, mobius::DenseCorrespondence& correspondence,
  vtkPolyData* output)
{
  const bool targetToSource =
    filter->GetDirection() == vtkDenseCorrespondence::TARGET_TO_SOURCE;
  mobius::vtk::SurfaceLocations locations;
  locations.LocatedTriangles = &locatedTriangles;
  locations.Triangle = std::move(correspondence.Triangle);
  locations.Barycentric = std::move(correspondence.Barycentric);
  const std::string arrayWarning = mobius::vtk::AssembleCorrespondence(
    inputs[targetToSource ? 1 : 0], inputs[targetToSource ? 0 : 1], locations,
    filter->GetOutputGeometry() == vtkDenseCorrespondence::TARGET, output);
  if (!arrayWarning.empty())
  {
    vtkWarningWithObjectMacro(
      filter, << (targetToSource ? "Source: " : "Target: ") << arrayWarning << ".");
  }
}
}

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
  const int located = this->Direction == SOURCE_TO_TARGET ? 1 : 0;
  mobius::CorrespondenceMap maps[2];
  for (int k = 0; k < 2; ++k)
  {
    const std::string error = ReadMap(inputs[k], k == located,
      k == located || this->OutputGeometry == SOURCE, InputNames[k], maps[k]);
    if (!error.empty())
    {
      vtkErrorMacro(<< "Cannot map: the " << InputNames[k] << ": " << error << ".");
      return 0;
    }
  }
  const int threads = mobius::ResolveThreadCount(this->NumberOfThreads);
  mobius::DenseCorrespondence correspondence =
    mobius::CorrespondSphericalMaps(maps, CorrespondenceParameters(this, threads));
  if (correspondence.Stopped)
  {
    return 0;
  }
  if (!correspondence.Error.empty())
  {
    vtkErrorMacro(<< correspondence.Error);
    return 0;
  }
  WriteOutput(this, inputs, maps[located].Triangles, correspondence, output);
  vtkFieldData* fieldData = output->GetFieldData();
  mobius::vtk::SetFieldCount(
    fieldData, "ClampedPoints", static_cast<vtkIdType>(correspondence.ClampedPoints));
  mobius::vtk::SetFieldValue(
    fieldData, "MaximumClampDistance", correspondence.MaximumClampDistance);
  mobius::vtk::SetFieldInteger(fieldData, "NumberOfThreadsUsed", threads);
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
