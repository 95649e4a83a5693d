#include "vtkMobiusCenter.h"

#include "RegistrationParameters.h"
#include "GeneralizedCentering.h"
#include "MobiusCentering.h"
#include "MobiusSphericalMapData.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

vtkStandardNewMacro(vtkMobiusCenter);

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
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output)
  {
    vtkErrorMacro(<< "Missing input or output polydata.");
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

  mobius::MobiusCenteringParameters parameters;
  parameters.Tolerance = this->Tolerance;
  parameters.MaximumNumberOfIterations = this->MaximumNumberOfIterations;
  mobius::MobiusCenteringResult result;
  auto progress = [this](double fraction) {
    this->UpdateProgress(fraction);
    return !this->GetAbortExecute();
  };
  if (!mobius::CenterSphericalMap(points, triangles, areas, parameters, result, progress))
  {
    if (!this->GetAbortExecute())
    {
      vtkErrorMacro(<< "Centering failed: " << result.Error << ".");
    }
    return 0;
  }
  mobius::GeneralizedCenteringResult generalized;
  if (this->Degree > 1)
  {
    if (triangles.rows() == 0)
    {
      vtkErrorMacro(<< "Cannot center: Degree " << this->Degree
                    << " needs triangles; a point set can only be centered with Degree 1.");
      return 0;
    }
    mobius::GeneralizedCenteringParameters generalParameters;
    generalParameters.Degree = this->Degree;
    generalParameters.Tolerance = this->GeneralizedTolerance;
    generalParameters.MaximumNumberOfIterations = this->GeneralizedMaximumNumberOfIterations;
    if (!mobius::CenterWithSphericalHarmonics(
          points, triangles, areas, generalParameters, generalized, progress))
    {
      if (!this->GetAbortExecute())
      {
        vtkErrorMacro(<< "Generalized centering failed: " << generalized.Error << ".");
      }
      return 0;
    }
    result.CenterOfMassNorm = generalized.CenterOfMassNorm;
    result.Converged = generalized.Converged;
  }
  if (!result.Converged)
  {
    const bool generalizedRun = this->Degree > 1;
    vtkWarningMacro(<< (generalizedRun ? "Generalized centering" : "Centering") << " stopped after "
                    << (generalizedRun ? generalized.NumberOfIterations : result.NumberOfIterations)
                    << " iterations with |mu| = " << result.CenterOfMassNorm
                    << " above the tolerance "
                    << (generalizedRun ? this->GeneralizedTolerance : this->Tolerance) << ".");
  }

  output->ShallowCopy(input);
  mobius::vtk::SetPoints(output, points);
  // The centered map's own distortion (the input's arrays describe the uncentered one),
  // colored by default by the area it gives each triangle: what centering evens out.
  // (The output's cell data holds the input's arrays, not the input's cell data object.)
  mobius::vtk::AddDistortionArrays(output, "LogAreaRatio");

  vtkFieldData* fieldData = output->GetFieldData();
  mobius::vtk::SetFieldValue(fieldData, "CenterOfMassNorm", result.CenterOfMassNorm);
  mobius::vtk::SetFieldValue(
    fieldData, "InitialCenterOfMassNorm", result.InitialCenterOfMassNorm);
  mobius::vtk::SetFieldInteger(fieldData, "CenteringIterations", result.NumberOfIterations);
  mobius::vtk::SetFieldInteger(fieldData, "CenteringDegree", this->Degree);
  mobius::vtk::SetFieldInteger(
    fieldData, "GeneralizedCenteringIterations", generalized.NumberOfIterations);
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
