#include "vtkSO3Register.h"

#include "MobiusSphericalMapData.h"
#include "ParallelFor.h"
#include "RegistrationParameters.h"
#include "RotationalAlignment.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <array>

vtkStandardNewMacro(vtkSO3Register);

namespace
{
std::array<double, 9> RowMajor(const Eigen::Matrix3d& matrix)
{
  std::array<double, 9> values;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      values[3 * r + c] = matrix(r, c);
    }
  }
  return values;
}

void AddTupleArray(vtkFieldData* fieldData, const char* name, int components,
  const std::vector<std::vector<double>>& tuples)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfComponents(components);
  for (const auto& tuple : tuples)
  {
    array->InsertNextTuple(tuple.data());
  }
  fieldData->RemoveArray(name);
  fieldData->AddArray(array);
}

// Input `port`'s spherical map as the core reads it (Problem says why it cannot be read).
mobius::AlignmentMap AlignmentMapOf(vtkPolyData* input, int port)
{
  mobius::AlignmentMap map;
  map.Name = port == 0 ? "Source (port 0)" : "Target (port 1)";
  map.Problem =
    mobius::vtk::ExtractSphericalMap(input, false, map.Sphere, map.Triangles, map.Areas);
  return map;
}

// The landmarks as point-id pairs of the two maps.
std::vector<std::pair<mobius::Index, mobius::Index>> LandmarkIds(vtkSO3Register* filter)
{
  std::vector<std::pair<mobius::Index, mobius::Index>> ids;
  for (vtkIdType k = 0; k < filter->GetNumberOfLandmarks(); ++k)
  {
    ids.emplace_back(filter->GetLandmarkSourceVertex(k), filter->GetLandmarkTargetVertex(k));
  }
  return ids;
}

// The filter's settings as the core's parameters, with its progress and abort.
mobius::RotationalAlignmentParameters AlignmentParameters(vtkSO3Register* filter, int threads)
{
  mobius::RotationalAlignmentParameters parameters;
  parameters.Signal.Resolution = filter->GetResolution();
  parameters.Signal.NumberOfThreads = threads;
  parameters.Signal.SmoothingTime = filter->GetSmoothingTime();
  parameters.Signal.Value = filter->GetValueMode() == 0
    ? mobius::ScaleFactorValue::AreaRatio
    : mobius::ScaleFactorValue::SquareRootAreaRatio;
  mobius::SO3CorrelationOptions& options = parameters.Correlation;
  options.NumberOfCandidates = filter->GetNumberOfCandidates();
  options.MinimumCandidateSeparation =
    vtkMath::RadiansFromDegrees(filter->GetCandidateSeparation());
  options.NumberOfThreads = threads;
  options.Reflections = static_cast<mobius::SO3ReflectionMode>(filter->GetTransformMode());
  parameters.CheckMirroring = filter->GetCheckMirroring();
  parameters.FitMobius =
    filter->GetLandmarkMode() == static_cast<int>(mobius::LandmarkMode::FitMobius);
  parameters.Progress = mobius::vtk::ProgressAndAbort(filter);
  return parameters;
}

// The kept transform and its figures, the mirror check's errors and the settings that ran.
void AddTransformFields(const mobius::RotationalAlignment& alignment, int resolution,
  int threads, vtkFieldData* fieldData)
{
  const mobius::SO3CorrelationResult& result = alignment.Correlation;
  const auto transform = RowMajor(result.Transform);
  mobius::vtk::SetFieldValues(fieldData, "Rotation", transform.data(), 9);
  mobius::vtk::SetFieldInteger(fieldData, "Determinant", static_cast<int>(result.Determinant));
  mobius::vtk::SetFieldValues(fieldData, "EulerAngles", result.EulerAngles.data(), 3);
  mobius::vtk::SetFieldValue(fieldData, "CorrelationScore", result.Score);
  mobius::vtk::SetFieldValue(fieldData, "RegistrationError", result.RegistrationError);
  const double coarseErrors[2] = { alignment.Mirroring.ChosenError,
    alignment.Mirroring.OtherError };
  mobius::vtk::SetFieldValues(fieldData, "MirrorCheckErrors", coarseErrors, 2);
  mobius::vtk::SetFieldValue(fieldData, "CorrelationCoefficient", result.CorrelationCoefficient);
  mobius::vtk::SetFieldInteger(fieldData, "Resolution", resolution);
  mobius::vtk::SetFieldInteger(fieldData, "CorrelationBandwidth", result.CorrelationBandwidth);
  mobius::vtk::SetFieldInteger(fieldData, "NumberOfThreadsUsed", threads);
}

// One tuple per candidate, best first: transforms, scores, errors, correlation
// coefficients and, with landmarks, their angles.
void AddCandidateArrays(const mobius::RotationalAlignment& alignment, vtkFieldData* fieldData)
{
  std::vector<std::vector<double>> transforms, scores, errors, coefficients, angles;
  for (const auto& candidate : alignment.Correlation.Candidates)
  {
    const auto values = RowMajor(candidate.Transform);
    transforms.emplace_back(values.begin(), values.end());
    scores.push_back({ candidate.Score });
    errors.push_back({ candidate.RegistrationError });
    coefficients.push_back({ candidate.CorrelationCoefficient });
  }
  AddTupleArray(fieldData, "CandidateTransforms", 9, transforms);
  AddTupleArray(fieldData, "CandidateScores", 1, scores);
  AddTupleArray(fieldData, "CandidateRegistrationErrors", 1, errors);
  AddTupleArray(fieldData, "CandidateCorrelationCoefficients", 1, coefficients);
  for (double angle : alignment.LandmarkAngles)
  {
    angles.push_back({ angle });
  }
  if (!angles.empty())
  {
    AddTupleArray(fieldData, "CandidateLandmarkAngles", 1, angles);
  }
}
}

//------------------------------------------------------------------------------
vtkSO3Register::vtkSO3Register()
{
  this->SetNumberOfInputPorts(2);
  const mobius::RegistrationParameters defaults;
  this->Resolution = defaults.Resolution;
  this->SmoothingTime = defaults.SmoothingTime;
  this->TransformMode = defaults.TransformMode;
  this->NumberOfCandidates = defaults.NumberOfCandidates;
  this->CandidateSeparation = defaults.CandidateSeparation;
  this->NumberOfThreads = defaults.NumberOfThreads;
  this->LandmarkMode = defaults.LandmarkMode;
}

//------------------------------------------------------------------------------
int vtkSO3Register::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  (void)port;
  return 1;
}

//------------------------------------------------------------------------------
double vtkSO3Register::EstimateMemory(int resolution)
{
  return mobius::AlignmentMemoryEstimate(resolution);
}

//------------------------------------------------------------------------------
int vtkSO3Register::LargestResolution(double bytes)
{
  return mobius::LargestAlignmentResolution(bytes);
}

//------------------------------------------------------------------------------
int vtkSO3Register::ComputeOutput(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* source = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* target = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!source || !target || !output)
  {
    vtkErrorMacro(<< "Both a Source (port 0) and a Target (port 1) spherical map are required.");
    return 0;
  }
  const int threads = mobius::ResolveThreadCount(this->NumberOfThreads);
  const mobius::RotationalAlignment alignment = mobius::AlignSphericalMaps(
    AlignmentMapOf(source, 0), AlignmentMapOf(target, 1), LandmarkIds(this),
    AlignmentParameters(this, threads));
  for (const std::string& warning : alignment.Warnings)
  {
    vtkWarningMacro(<< warning);
  }
  if (alignment.Stopped)
  {
    return 1; // stopped by the user: an empty output, not an error
  }
  if (!alignment.Error.empty())
  {
    vtkErrorMacro(<< alignment.Error);
    return 0;
  }
  output->ShallowCopy(source);
  mobius::vtk::SetPoints(output, alignment.AlignedSource);
  AddTransformFields(alignment, this->Resolution, threads, output->GetFieldData());
  AddCandidateArrays(alignment, output->GetFieldData());
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkSO3Register::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "CheckMirroring: " << (this->CheckMirroring ? "on" : "off") << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "SmoothingTime: " << this->SmoothingTime << "\n";
  os << indent << "ValueMode: " << this->ValueMode << "\n";
  os << indent << "TransformMode: " << this->TransformMode << "\n";
  os << indent << "NumberOfCandidates: " << this->NumberOfCandidates << "\n";
  os << indent << "CandidateSeparation: " << this->CandidateSeparation << "\n";
  os << indent << "LandmarkMode: " << this->LandmarkMode << "\n";
}
