#include "vtkCenteredSphericalMap.h"

#include "MobiusPipeline.h"
#include "MobiusSphericalMapOptions.h"
#include "ParameterRules.h"
#include "RegistrationParameters.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

vtkStandardNewMacro(vtkCenteredSphericalMap);

//------------------------------------------------------------------------------
vtkCenteredSphericalMap::vtkCenteredSphericalMap()
{
  const mobius::RegistrationParameters defaults;
  this->Repair = defaults.Repair;
  this->FillHoles = defaults.FillHoles;
  this->KeepLargestComponent = defaults.KeepLargestComponent;
  this->AllowPoorMaps = defaults.AllowPoorMaps;
  this->MaximumNumberOfIterations = defaults.FlowIterations;
  this->ConvergenceTolerance = defaults.FlowTolerance;
  this->CenterBetweenSteps = defaults.CenterBetweenSteps;
  this->CenteringDegree = defaults.CenteringDegree;
}

//------------------------------------------------------------------------------
void vtkCenteredSphericalMap::SetMeshName(const char* name)
{
  if (name && this->MeshName != name)
  {
    this->MeshName = name;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkCenteredSphericalMap::ComputeOutput(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = nullptr;
  vtkPolyData* output = nullptr;
  if (!this->GetInputAndOutput(inputVector, outputVector, input, output))
  {
    return 0;
  }
  // The job's parameters: the ones of this filter, the rest at their defaults.
  mobius::RegistrationParameters options;
  mobius::vtk::CopySphericalMapOptions(this, options);
  const std::string outOfRange =
    mobius::CheckRegistrationParameters(options, mobius::ParameterNaming::Filter);
  if (!outOfRange.empty())
  {
    vtkErrorMacro(<< outOfRange);
    return 0;
  }

  // On a copy: the pipeline's input object stays out of the stages' internal pipelines.
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(input);
  OneMeshStages stages;
  stages.Abort = [this] { return this->GetAbortExecute() != 0; };
  const StageProgress progress = [this](const std::string& stage, double fraction) {
    // The conformal map takes most of the time.
    this->UpdateProgress(stage == "centering" ? 0.9 + 0.1 * fraction : 0.9 * fraction);
  };
  PipelineResult result;
  vtkSmartPointer<vtkPolyData> map, centered;
  std::string error;
  const bool mapped =
    MapAndCenter(copy, this->MeshName, options, stages, progress, result, map, centered, error);
  for (const auto& warning : result.Warnings)
  {
    vtkWarningMacro(<< warning);
  }
  if (!mapped)
  {
    if (!this->GetAbortExecute())
    {
      vtkErrorMacro(<< error);
    }
    return 0;
  }
  output->ShallowCopy(centered);
  return 1;
}

//------------------------------------------------------------------------------
void vtkCenteredSphericalMap::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MeshName: " << this->MeshName << "\n";
  os << indent << "Repair: " << this->Repair << "\n";
  os << indent << "FillHoles: " << this->FillHoles << "\n";
  os << indent << "KeepLargestComponent: " << this->KeepLargestComponent << "\n";
  os << indent << "AllowPoorMaps: " << this->AllowPoorMaps << "\n";
  os << indent << "MaximumNumberOfIterations: " << this->MaximumNumberOfIterations << "\n";
  os << indent << "ConvergenceTolerance: " << this->ConvergenceTolerance << "\n";
  os << indent << "CenterBetweenSteps: " << this->CenterBetweenSteps << "\n";
  os << indent << "CenteringDegree: " << this->CenteringDegree << "\n";
}
