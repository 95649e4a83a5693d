#include "vtkSO3Register.h"

#include "LandmarkAlignment.h"
#include "RegistrationParameters.h"
#include "MirrorCheck.h"
#include "ParallelFor.h"
#include "SO3Correlation.h"
#include "ScaleFactorSignal.h"
#include "MobiusSphericalMapData.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unistd.h>

vtkStandardNewMacro(vtkSO3Register);

namespace
{
// Bytes of RAM, 0 if unknown.
double PhysicalMemory()
{
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? static_cast<double>(pages) * static_cast<double>(pageSize) : 0;
}
}

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

// The landmarks' points on the two spheres (`ids`: point ids of the maps); the error if an
// id is not a point of its map.
std::string GatherLandmarks(const std::vector<std::pair<vtkIdType, vtkIdType>>& ids,
  const mobius::Points& source, const mobius::Points& target, mobius::SphereLandmarks& landmarks)
{
  const std::string error = mobius::vtk::CheckLandmarkPoints(ids, source.rows(), target.rows());
  const auto count = static_cast<Eigen::Index>(error.empty() ? ids.size() : 0);
  landmarks.Source.resize(count, 3);
  landmarks.Target.resize(count, 3);
  for (Eigen::Index k = 0; k < count; ++k)
  {
    landmarks.Source.row(k) = source.row(ids[k].first);
    landmarks.Target.row(k) = target.row(ids[k].second);
  }
  return error;
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
  const double n = resolution;
  return 160.0 * n * n + 50e6;
}

//------------------------------------------------------------------------------
int vtkSO3Register::LargestResolution(double bytes)
{
  if (bytes <= 0)
  {
    bytes = PhysicalMemory();
  }
  if (bytes <= 50e6)
  {
    return 4;
  }
  const double n = std::sqrt((bytes - 50e6) / 160.0);
  const int even = 2 * static_cast<int>(std::min(n, 1e9) / 2);
  return std::max(4, even);
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
  if (this->Resolution < mobius::MinimumResolution || this->Resolution % 2 != 0)
  {
    vtkErrorMacro(<< "Resolution must be even and at least " << mobius::MinimumResolution
                  << " (it is " << this->Resolution << "): a coarser grid cannot tell the rotation.");
    return 0;
  }
  if (this->Resolution < mobius::ReliableResolution)
  {
    vtkWarningMacro(<< "Resolution " << this->Resolution << " resolves the rotation only to about "
                    << 360 / this->Resolution << " degrees: the map may come back turned; "
                    << mobius::ReliableResolution << " or more is reliable.");
  }
  const double memory = PhysicalMemory();
  if (memory > 0 && EstimateMemory(this->Resolution) > memory)
  {
    vtkErrorMacro(<< "Resolution " << this->Resolution << " needs about "
                  << EstimateMemory(this->Resolution) / 1e9 << " GB, more than this machine's "
                  << memory / 1e9 << " GB; Resolution " << LargestResolution(memory)
                  << " would fit.");
    return 0;
  }

  const int threads = mobius::ResolveThreadCount(this->NumberOfThreads);
  mobius::ScaleFactorSignalParameters parameters;
  parameters.Resolution = this->Resolution;
  parameters.NumberOfThreads = threads;
  parameters.SmoothingTime = this->SmoothingTime;
  parameters.Value = this->ValueMode == 0 ? mobius::ScaleFactorValue::AreaRatio
                                          : mobius::ScaleFactorValue::SquareRootAreaRatio;
  mobius::Points sourcePoints, targetPoints;
  mobius::ScaleFactorSignal signals[2];
  vtkPolyData* inputs[2] = { source, target };
  const char* names[2] = { "Source", "Target" };
  for (int k = 0; k < 2; ++k)
  {
    mobius::Points points;
    mobius::Triangles triangles;
    mobius::Vector areas;
    std::string error =
      mobius::vtk::ExtractSphericalMap(inputs[k], false, points, triangles, areas);
    auto progress = [this, k](double fraction) {
      this->UpdateProgress(0.25 * (k + fraction));
      return !this->GetAbortExecute();
    };
    if (error.empty() &&
      !mobius::ComputeScaleFactorSignal(
        points, triangles, areas, parameters, false, signals[k], error, progress))
    {
      if (this->GetAbortExecute())
      {
        return 1; // stopped by the user: an empty output, not an error
      }
    }
    if (!error.empty())
    {
      vtkErrorMacro(<< "Cannot register: the " << names[k] << " (port " << k << "): " << error
                    << ".");
      return 0;
    }
    (k == 0 ? sourcePoints : targetPoints).swap(points);
  }
  mobius::SphereLandmarks landmarks;
  const std::string landmarkError =
    GatherLandmarks(this->Landmarks, sourcePoints, targetPoints, landmarks);
  const bool fitMobius = this->LandmarkMode == 1;
  if (landmarkError.empty() && fitMobius && landmarks.Source.rows() < mobius::FittedLandmarkCount)
  {
    vtkErrorMacro(<< "Cannot register: LandmarkMode 1 fits a Moebius transformation to "
                  << mobius::FittedLandmarkCount << " landmarks, and there are "
                  << landmarks.Source.rows() << ".");
    return 0;
  }
  if (!landmarkError.empty())
  {
    vtkErrorMacro(<< "Cannot register: " << landmarkError << ".");
    return 0;
  }

  mobius::SO3CorrelationOptions options;
  options.NumberOfCandidates = this->NumberOfCandidates;
  options.MinimumCandidateSeparation = vtkMath::RadiansFromDegrees(this->CandidateSeparation);
  options.NumberOfThreads = threads;
  options.Reflections = static_cast<mobius::SO3ReflectionMode>(this->TransformMode);
  // The correlation (grid search and Newton refinement) is half the work or more at high
  // Resolution: it reports progress and hears the abort button too.
  options.Progress = [this](double fraction) {
    this->UpdateProgress(0.5 + 0.45 * fraction);
    return !this->GetAbortExecute();
  };
  mobius::SO3CorrelationResult result =
    mobius::CorrelateOverRotations(signals[0].Coefficients, signals[1].Coefficients, options);
  if (result.Aborted || this->GetAbortExecute())
  {
    return 1; // stopped by the user: an empty output, not an error
  }
  this->UpdateProgress(0.95);
  if (result.Candidates.empty() || !result.Transform.allFinite())
  {
    vtkErrorMacro(<< "Cannot register: the correlation found no peak (are both signals zero?).");
    return 0;
  }
  std::vector<double> landmarkAngles;
  if (fitMobius)
  {
    // The Möbius transformation takes the rotation's place: of the rotation only its kind
    // (a reflection or not) is kept.
    const bool reflect = this->TransformMode == REFLECTIONS ||
      (this->TransformMode == ROTATIONS_AND_REFLECTIONS &&
        mobius::LandmarksReverseOrientation(landmarks));
    if (!mobius::MoveByLandmarkMobius(landmarks, reflect, sourcePoints))
    {
      vtkErrorMacro(<< "Cannot register: two of the first " << mobius::FittedLandmarkCount
                    << " landmarks are at the same point of a sphere: no Moebius "
                       "transformation sends them onto their targets.");
      return 0;
    }
    const Eigen::Matrix3d kind = Eigen::Vector3d(1.0, reflect ? -1.0 : 1.0, 1.0).asDiagonal();
    result.Candidates = { mobius::ScoreTransform(
      signals[0].Coefficients, signals[1].Coefficients, kind, threads) };
    mobius::TakeFirstCandidate(result);
  }
  else if (landmarks.Source.rows() > 0)
  {
    landmarkAngles = mobius::OrderCandidatesByLandmarks(result.Candidates, landmarks,
      options.Reflections, [&](const Eigen::Matrix3d& transform) {
        return mobius::ScoreTransform(
          signals[0].Coefficients, signals[1].Coefficients, transform, threads);
      });
    mobius::TakeFirstCandidate(result);
  }
  mobius::MirrorCheck mirroring;
  if (this->CheckMirroring)
  {
    mirroring = mobius::CheckMirroring(signals[0].Coefficients, signals[1].Coefficients, options);
  }
  if (mirroring.OtherFitsFarBetter)
  {
    vtkWarningMacro(<< (this->TransformMode == ROTATIONS
                           ? "The shapes look mirrored: a reflection aligns them far better ("
                           : "The shapes look the same way round: a rotation aligns them far better (")
                    << "registration error " << std::max(0.0, mirroring.OtherError) << " against "
                    << mirroring.ChosenError
                    << " in a coarse search); set TransformMode to ROTATIONS_AND_REFLECTIONS to "
                       "search both kinds.");
  }

  output->ShallowCopy(source);
  for (Eigen::Index i = 0; i < sourcePoints.rows() && !fitMobius; ++i)
  {
    sourcePoints.row(i) = (result.Transform * sourcePoints.row(i).transpose()).transpose();
  }
  mobius::vtk::SetPoints(output, sourcePoints);

  vtkFieldData* fieldData = output->GetFieldData();
  const auto transform = RowMajor(result.Transform);
  mobius::vtk::SetFieldValues(fieldData, "Rotation", transform.data(), 9);
  mobius::vtk::SetFieldInteger(fieldData, "Determinant", static_cast<int>(result.Determinant));
  mobius::vtk::SetFieldValues(fieldData, "EulerAngles", result.EulerAngles.data(), 3);
  mobius::vtk::SetFieldValue(fieldData, "CorrelationScore", result.Score);
  mobius::vtk::SetFieldValue(fieldData, "RegistrationError", result.RegistrationError);
  const double coarseErrors[2] = { mirroring.ChosenError, mirroring.OtherError };
  mobius::vtk::SetFieldValues(fieldData, "MirrorCheckErrors", coarseErrors, 2);
  mobius::vtk::SetFieldValue(fieldData, "CorrelationCoefficient", result.CorrelationCoefficient);
  mobius::vtk::SetFieldInteger(fieldData, "Resolution", this->Resolution);
  mobius::vtk::SetFieldInteger(fieldData, "CorrelationBandwidth", result.CorrelationBandwidth);
  mobius::vtk::SetFieldInteger(fieldData, "NumberOfThreadsUsed", threads);
  std::vector<std::vector<double>> transforms, scores, errors, coefficients;
  for (const auto& candidate : result.Candidates)
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
  if (!landmarkAngles.empty())
  {
    std::vector<std::vector<double>> angles;
    for (double angle : landmarkAngles)
    {
      angles.push_back({ angle });
    }
    AddTupleArray(fieldData, "CandidateLandmarkAngles", 1, angles);
  }
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
