#include "vtkMobiusRegistration.h"

#include "MobiusInputRows.h"
#include "MobiusPipeline.h"
#include "MobiusSphericalMapOptions.h"
#include "MobiusPullBack.h"
#include "ParameterRules.h"
#include "RegistrationParameters.h"

#include "vtkAbstractArray.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <thread>

vtkStandardNewMacro(vtkMobiusRegistration);

namespace
{
// Adds to `fields` the field arrays of `stage` that its input `before` did not have (a
// stage passes its input's field data on), each named `prefix` + its name.
void AddStageFields(vtkFieldData* fields, const std::string& prefix, vtkPolyData* stage,
  vtkPolyData* before = nullptr)
{
  vtkFieldData* stageFields = stage ? stage->GetFieldData() : nullptr;
  for (int a = 0; stageFields && a < stageFields->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = stageFields->GetAbstractArray(a);
    if (!array || !array->GetName() ||
      (before && before->GetFieldData()->GetAbstractArray(array->GetName())))
    {
      continue;
    }
    vtkSmartPointer<vtkAbstractArray> copy = vtkSmartPointer<vtkAbstractArray>::Take(array->NewInstance());
    copy->DeepCopy(array);
    copy->SetName((prefix + array->GetName()).c_str());
    fields->AddArray(copy);
  }
}

// The filter's properties, as the pipeline takes them.
mobius::RegistrationParameters ParametersOf(vtkMobiusRegistration* filter)
{
  mobius::RegistrationParameters options;
  options.InputsAreCenteredMaps = filter->GetInputsAreCenteredMaps();
  mobius::vtk::CopySphericalMapOptions(filter, options);
  options.Resolution = filter->GetResolution();
  options.SmoothingTime = filter->GetSmoothingTime();
  options.TransformMode = filter->GetTransformMode();
  options.NumberOfCandidates = filter->GetNumberOfCandidates();
  options.CandidateSeparation = filter->GetCandidateSeparation();
  options.Refine = filter->GetRefine();
  options.BasisSize = filter->GetBasisSize();
  options.GeometricPolish = filter->GetGeometricPolish();
  options.BothDirections = filter->GetBothDirections();
  options.Candidate = filter->GetCandidate();
  options.OutputGeometry = filter->GetOutputGeometry();
  options.NumberOfThreads = filter->GetNumberOfThreads();
  options.LandmarkMode = filter->GetLandmarkMode();
  for (vtkIdType k = 0; k < filter->GetNumberOfLandmarks(); ++k)
  {
    options.Landmarks.push_back(
      { filter->GetLandmarkSourceVertex(k), filter->GetLandmarkTargetVertex(k) });
  }
  return options;
}

// How many vertex numbers a landmark may name on `input`: its points, or for a centered map
// the numbers of the mesh it was made from (its InputPointId values).
mobius::Index LandmarkVertexCount(vtkPolyData* input, const mobius::RegistrationParameters& options)
{
  vtkDataArray* ids = input->GetPointData()->GetArray("InputPointId");
  if (options.InputsAreCenteredMaps && ids && ids->GetNumberOfTuples() > 0)
  {
    return static_cast<mobius::Index>(ids->GetRange(0)[1]) + 1;
  }
  return input->GetNumberOfPoints();
}

// The first parameter outside its allowed values, the landmarks' vertices checked against
// the inputs when there are inputs; empty if none is.
std::string CheckOptions(const mobius::RegistrationParameters& options, vtkPolyData* source,
  vtkPolyData* target, mobius::ParameterNaming naming)
{
  std::string problem = mobius::CheckRegistrationParameters(options, naming);
  if (problem.empty() && source && target)
  {
    problem = mobius::CheckLandmarkVertices(options, LandmarkVertexCount(source, options),
      LandmarkVertexCount(target, options), naming);
  }
  return problem;
}

// The share of the job's progress before each stage, roughly its share of the time.
double StageStart(const std::string& stage, double& length)
{
  if (stage == "rotational alignment")
  {
    length = 0.3;
    return 0.3;
  }
  if (stage == "dense correspondence")
  {
    length = 0.1;
    return 0.6;
  }
  length = 0.3; // the refinement
  return 0.7;
}

// The job's progress as the filter's, from this thread only: the two conformal maps may run
// on others, where VTK's observers (ParaView's progress bar) must not be called.
StageProgress ProgressOf(vtkMobiusRegistration* filter)
{
  const std::thread::id caller = std::this_thread::get_id();
  return [filter, caller](const std::string& stage, double fraction) {
    if (std::this_thread::get_id() != caller || stage.rfind("conformal map", 0) == 0 ||
      stage.rfind("centering", 0) == 0)
    {
      return;
    }
    double length = 0;
    const double start = StageStart(stage, length);
    filter->UpdateProgress(start + length * fraction);
  };
}

// The output's field data: the final map's, with each stage's own under its prefix.
vtkSmartPointer<vtkFieldData> RegistrationFields(
  const PipelineResult& result, const mobius::RegistrationParameters& options)
{
  auto fields = vtkSmartPointer<vtkFieldData>::New();
  fields->ShallowCopy(result.Correspondence->GetFieldData());
  if (!options.InputsAreCenteredMaps) // else these are the inputs, which the caller has
  {
    AddStageFields(fields, "SourceMap.", result.SourceMap);
    AddStageFields(fields, "TargetMap.", result.TargetMap);
    AddStageFields(fields, "SourceCentering.", result.SourceCentered, result.SourceMap);
    AddStageFields(fields, "TargetCentering.", result.TargetCentered, result.TargetMap);
  }
  AddStageFields(fields, "Registration.", result.Aligned, result.SourceCentered);
  if (result.Correspondence != result.MobiusCorrespondence)
  {
    AddStageFields(fields, "MobiusCorrespondence.", result.MobiusCorrespondence, result.Aligned);
  }
  return fields;
}

// Outputs 1 to 3: the aligned source map, the target's centered map, and the map on the
// target's own mesh (every vertex of the target as given, when its repair changed it).
void WriteStageOutputs(vtkMobiusRegistration* filter, vtkPolyData* target,
  const mobius::RegistrationParameters& options, const PipelineResult& result,
  vtkInformationVector* outputVector)
{
  if (vtkPolyData* aligned = vtkPolyData::GetData(outputVector, 1))
  {
    aligned->ShallowCopy(result.Aligned);
  }
  if (vtkPolyData* targetSphere = vtkPolyData::GetData(outputVector, 2))
  {
    targetSphere->ShallowCopy(result.TargetCentered);
  }
  vtkPolyData* pulledBack = vtkPolyData::GetData(outputVector, 3);
  const vtkSmartPointer<vtkPolyData> targetSurface =
    !options.InputsAreCenteredMaps && mobius::vtk::MapWasRepaired(result.TargetMap)
    ? mobius::vtk::SurfaceAsGiven(target)
    : vtkSmartPointer<vtkPolyData>(result.TargetCentered);
  if (pulledBack &&
    !mobius::vtk::PullBackToTarget(result.Aligned,
      result.Correspondence->GetPointData()->GetArray("MappedPoints"), targetSurface, pulledBack))
  {
    vtkWarningWithObjectMacro(
      filter, << "The map could not be shown on the target's own mesh (output 3).");
  }
}
}

//------------------------------------------------------------------------------
vtkMobiusRegistration::vtkMobiusRegistration()
{
  this->SetNumberOfInputPorts(2);
  // The correspondence, the two centered maps aligned, the map on the target's own mesh.
  this->SetNumberOfOutputPorts(4);
  const mobius::RegistrationParameters defaults;
  this->InputsAreCenteredMaps = defaults.InputsAreCenteredMaps;
  this->Repair = defaults.Repair;
  this->FillHoles = defaults.FillHoles;
  this->KeepLargestComponent = defaults.KeepLargestComponent;
  this->AllowPoorMaps = defaults.AllowPoorMaps;
  this->MaximumNumberOfIterations = defaults.FlowIterations;
  this->ConvergenceTolerance = defaults.FlowTolerance;
  this->CenterBetweenSteps = defaults.CenterBetweenSteps;
  this->CenteringDegree = defaults.CenteringDegree;
  this->Resolution = defaults.Resolution;
  this->SmoothingTime = defaults.SmoothingTime;
  this->TransformMode = defaults.TransformMode;
  this->NumberOfCandidates = defaults.NumberOfCandidates;
  this->CandidateSeparation = defaults.CandidateSeparation;
  this->Refine = defaults.Refine;
  this->BasisSize = defaults.BasisSize;
  this->GeometricPolish = defaults.GeometricPolish;
  this->BothDirections = defaults.BothDirections;
  this->Candidate = defaults.Candidate;
  this->OutputGeometry = defaults.OutputGeometry;
  this->NumberOfThreads = defaults.NumberOfThreads;
  this->LandmarkMode = defaults.LandmarkMode;
}

//------------------------------------------------------------------------------
void vtkMobiusRegistration::SetSourceName(const char* name)
{
  if (name && this->SourceName != name)
  {
    this->SourceName = name;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkMobiusRegistration::SetTargetName(const char* name)
{
  if (name && this->TargetName != name)
  {
    this->TargetName = name;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkMobiusRegistration::SetNumberOfThreads(int threads)
{
  if (this->NumberOfThreads != threads)
  {
    this->NumberOfThreads = threads;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
std::string vtkMobiusRegistration::CheckParameters(int names)
{
  const mobius::ParameterNaming naming = names == PYTHON_NAMES ? mobius::ParameterNaming::Python
    : names == COMMAND_LINE_NAMES ? mobius::ParameterNaming::CommandLine
                                  : mobius::ParameterNaming::Filter;
  // The landmarks' vertices are checked when the meshes are there.
  return CheckOptions(ParametersOf(this), vtkPolyData::SafeDownCast(this->GetInputDataObject(0, 0)),
    vtkPolyData::SafeDownCast(this->GetInputDataObject(1, 0)), naming);
}

//------------------------------------------------------------------------------
int vtkMobiusRegistration::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkMobiusRegistration::ComputeOutput(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* source = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* target = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!source || !target || !output)
  {
    vtkErrorMacro(<< "Both a Source (port 0) and a Target (port 1) mesh are required.");
    return 0;
  }
  const mobius::RegistrationParameters options = ParametersOf(this);
  const std::string outOfRange =
    CheckOptions(options, source, target, mobius::ParameterNaming::Filter);
  if (!outOfRange.empty())
  {
    vtkErrorMacro(<< outOfRange);
    return 0;
  }
  PipelineResult result;
  std::string error;
  const bool succeeded = RunRegistrationPipeline(source, target, this->SourceName,
    this->TargetName, options, result, error, ProgressOf(this));
  for (const auto& warning : result.Warnings)
  {
    vtkWarningMacro(<< warning);
  }
  if (!succeeded)
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  output->ShallowCopy(result.InputCorrespondence);
  output->SetFieldData(RegistrationFields(result, options));
  WriteStageOutputs(this, target, options, result, outputVector);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkMobiusRegistration::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SourceName: " << this->SourceName << "\n";
  os << indent << "TargetName: " << this->TargetName << "\n";
  os << indent << "InputsAreCenteredMaps: " << this->InputsAreCenteredMaps << "\n";
  os << indent << "Repair: " << this->Repair << "\n";
  os << indent << "FillHoles: " << this->FillHoles << "\n";
  os << indent << "KeepLargestComponent: " << this->KeepLargestComponent << "\n";
  os << indent << "AllowPoorMaps: " << this->AllowPoorMaps << "\n";
  os << indent << "MaximumNumberOfIterations: " << this->MaximumNumberOfIterations << "\n";
  os << indent << "ConvergenceTolerance: " << this->ConvergenceTolerance << "\n";
  os << indent << "CenterBetweenSteps: " << this->CenterBetweenSteps << "\n";
  os << indent << "CenteringDegree: " << this->CenteringDegree << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "SmoothingTime: " << this->SmoothingTime << "\n";
  os << indent << "TransformMode: " << this->TransformMode << "\n";
  os << indent << "NumberOfCandidates: " << this->NumberOfCandidates << "\n";
  os << indent << "CandidateSeparation: " << this->CandidateSeparation << "\n";
  os << indent << "Refine: " << this->Refine << "\n";
  os << indent << "BasisSize: " << this->BasisSize << "\n";
  os << indent << "GeometricPolish: " << this->GeometricPolish << "\n";
  os << indent << "BothDirections: " << this->BothDirections << "\n";
  os << indent << "Candidate: " << this->Candidate << "\n";
  os << indent << "OutputGeometry: " << this->OutputGeometry << "\n";
  os << indent << "LandmarkMode: " << this->LandmarkMode << "\n";
}
