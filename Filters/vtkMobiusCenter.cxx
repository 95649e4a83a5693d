#include "vtkMobiusCenter.h"

#include "MapCentering.h"
#include "MobiusSphericalMapData.h"
#include "RegistrationParameters.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

vtkStandardNewMacro(vtkMobiusCenter);

namespace
{
// The filter's settings, progress and abort as the core's parameters.
mobius::MapCenteringParameters CenteringParameters(vtkMobiusCenter* filter)
{
  mobius::MapCenteringParameters parameters;
  parameters.Mobius.Tolerance = filter->GetTolerance();
  parameters.Mobius.MaximumNumberOfIterations = filter->GetMaximumNumberOfIterations();
  parameters.Degree = filter->GetDegree();
  parameters.Generalized.Tolerance = filter->GetGeneralizedTolerance();
  parameters.Generalized.MaximumNumberOfIterations =
    filter->GetGeneralizedMaximumNumberOfIterations();
  parameters.Progress = mobius::vtk::ProgressAndAbort(filter);
  return parameters;
}

// |mu| before and after, the steps of both centerings, the degree, the Möbius
// transformation as a Lorentz matrix and its inversions' centers.
void AddCenteringFields(const mobius::MapCentering& centering, int degree, vtkFieldData* fieldData)
{
  const mobius::MobiusCenteringResult& result = centering.Mobius;
  mobius::vtk::SetFieldValue(fieldData, "CenterOfMassNorm", result.CenterOfMassNorm);
  mobius::vtk::SetFieldValue(
    fieldData, "InitialCenterOfMassNorm", result.InitialCenterOfMassNorm);
  mobius::vtk::SetFieldInteger(fieldData, "CenteringIterations", result.NumberOfIterations);
  mobius::vtk::SetFieldInteger(fieldData, "CenteringDegree", degree);
  mobius::vtk::SetFieldInteger(
    fieldData, "GeneralizedCenteringIterations", centering.Generalized.NumberOfIterations);
  double lorentz[16];
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      lorentz[4 * r + c] = result.LorentzTransform(r, c);
    }
  }
  mobius::vtk::SetFieldValues(fieldData, "MobiusTransform", lorentz, 16);
  vtkNew<vtkDoubleArray> centers;
  centers->SetName("InversionCenters");
  centers->SetNumberOfComponents(3);
  for (const auto& c : result.InversionCenters)
  {
    centers->InsertNextTuple3(c.x(), c.y(), c.z());
  }
  fieldData->RemoveArray("InversionCenters");
  fieldData->AddArray(centers);
}
}

//------------------------------------------------------------------------------
vtkMobiusCenter::vtkMobiusCenter()
{
  const mobius::RegistrationParameters defaults;
  this->Tolerance = defaults.CenteringTolerance;
  this->Degree = defaults.CenteringDegree;
  this->GeneralizedTolerance = defaults.GeneralizedCenteringTolerance;
}

//------------------------------------------------------------------------------
int vtkMobiusCenter::ComputeOutput(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = nullptr;
  vtkPolyData* output = nullptr;
  if (!this->GetInputAndOutput(inputVector, outputVector, input, output))
  {
    return 0;
  }
  mobius::Points points;
  mobius::Triangles triangles;
  mobius::Vector areas;
  const std::string error =
    mobius::vtk::ExtractSphericalMap(input, true, points, triangles, areas);
  if (!error.empty())
  {
    vtkErrorMacro(<< "Cannot center: " << error << ".");
    return 0;
  }
  const mobius::MapCentering centering =
    mobius::CenterMap(points, triangles, areas, CenteringParameters(this));
  if (!centering.Error.empty())
  {
    vtkErrorMacro(<< centering.Error);
    return 0;
  }
  if (centering.Stopped)
  {
    return 0;
  }
  for (const std::string& warning : centering.Warnings)
  {
    vtkWarningMacro(<< warning);
  }
  output->ShallowCopy(input);
  mobius::vtk::SetPoints(output, points);
  // The centered map's own distortion (the input's arrays describe the uncentered one),
  // colored by default by the area it gives each triangle: what centering evens out.
  // (The output's cell data holds the input's arrays, not the input's cell data object.)
  mobius::vtk::AddDistortionArrays(output, "LogAreaRatio");
  AddCenteringFields(centering, this->Degree, output->GetFieldData());
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkMobiusCenter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MaximumNumberOfIterations: " << this->MaximumNumberOfIterations << "\n";
  os << indent << "Degree: " << this->Degree << "\n";
  os << indent << "GeneralizedTolerance: " << this->GeneralizedTolerance << "\n";
  os << indent << "GeneralizedMaximumNumberOfIterations: "
     << this->GeneralizedMaximumNumberOfIterations << "\n";
}
