#include "vtkCorrespondenceRefinement.h"

#include "CotangentLaplacian.h"
#include "EdgeStretch.h"
#include "MobiusCorrespondenceOutput.h"
#include "MobiusLaplaceBeltramiBasisData.h"
#include "MirrorCheck.h"
#include "MobiusSphericalMapData.h"
#include "ParallelFor.h"
#include "RefineCorrespondence.h"
#include "RegistrationParameters.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkPointData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <Eigen/Core>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <utility>

vtkStandardNewMacro(vtkCorrespondenceRefinement);

namespace
{
const char* const InputNames[2] = { "Source (port 0)", "Target (port 1)" };

// "Cannot refine: the Target (port 1): <error>."
std::string InputError(int input, const std::string& error)
{
  return std::string("Cannot refine: the ") + InputNames[input] + ": " + error + ".";
}

// One spherical map of the pipeline, as the core sees it.
struct MapInput
{
  mobius::Points Sphere;
  mobius::Points Surface;
  mobius::Triangles Triangles;
};

std::string ExtractMapInput(vtkPolyData* input, int basisSize, MapInput& map)
{
  std::string error = mobius::vtk::ExtractPoints(input, map.Sphere);
  if (error.empty())
  {
    error = mobius::vtk::ExtractTriangles(input, map.Triangles);
  }
  if (error.empty() && map.Triangles.rows() == 0)
  {
    error = "it has no triangles";
  }
  if (error.empty())
  {
    error = mobius::vtk::CheckOnUnitSphere(map.Sphere);
  }
  if (error.empty())
  {
    error = mobius::vtk::ExtractSurfacePoints(input, map.Surface);
  }
  if (error.empty())
  {
    // The spectral surface does not depend on the scale; the basis filter scales the same
    // way, so that a stored basis has the same fingerprint.
    mobius::vtk::NormalizeSurfaceScale(map.Surface);
  }
  if (error.empty() && !mobius::RefinementApplies(map.Sphere.rows(), basisSize))
  {
    std::ostringstream message;
    message << "it has " << map.Sphere.rows() << " points, fewer than twice the BasisSize ("
            << basisSize << ")";
    error = message.str();
  }
  return error;
}

// The transforms to start from, as rotations of the already aligned source (field data
// Rotation, the best transform, and CandidateTransforms; mobius::CandidateStarts).
std::vector<mobius::RotationMatrix> CandidateStarts(vtkPolyData* aligned, bool searchCandidates)
{
  vtkDataArray* best = aligned->GetFieldData()->GetArray("Rotation");
  vtkDataArray* candidates = aligned->GetFieldData()->GetArray("CandidateTransforms");
  if (!searchCandidates || !best || !candidates || best->GetNumberOfComponents() != 9 ||
    candidates->GetNumberOfComponents() != 9)
  {
    return { mobius::RotationMatrix::Identity() };
  }
  mobius::RotationMatrix bestTransform;
  best->GetTuple(0, bestTransform.data());
  std::vector<mobius::RotationMatrix> transforms(candidates->GetNumberOfTuples());
  for (vtkIdType c = 0; c < candidates->GetNumberOfTuples(); ++c)
  {
    candidates->GetTuple(c, transforms[c].data());
  }
  return mobius::CandidateStarts(bestTransform, transforms);
}

// The spectral surfaces of both maps. A basis stored on an input (vtkLaplaceBeltramiBasis)
// is used when it is this surface's, of BasisSize functions; one of another size is
// ignored, one of another surface refused. Returns the error, naming the input.
std::string PrepareSurfaces(vtkCorrespondenceRefinement* filter, vtkPolyData* inputs[2],
  MapInput maps[2], int threads, mobius::SpectralSurface surfaces[2], bool stored[2])
{
  const int basisSize = filter->GetBasisSize();
  const double massShare = filter->GetConsistentMassShare();
  std::string errors[2];
  mobius::LaplaceBeltramiBasis bases[2];
  for (int k = 0; k < 2; ++k)
  {
    const mobius::vtk::StoredBasis found = mobius::vtk::ReadBasisArrays(inputs[k], basisSize,
      mobius::vtk::SurfaceFingerprint(maps[k].Surface, maps[k].Triangles), bases[k], errors[k]);
    if (!errors[k].empty())
    {
      return InputError(k, errors[k]);
    }
    // A stored basis is built with the lumped mass; a blended mass needs its own basis.
    stored[k] = found == mobius::vtk::StoredBasis::Found && massShare == 0.0;
  }
  // After the stored bases were matched: their fingerprints are of the surfaces as stored.
  for (int k = 0; k < 2; ++k)
  {
    mobius::vtk::CenterSurface(maps[k].Surface);
  }
  // The two surfaces are independent (each eigensolve runs on one core): side by side
  // when there are two threads.
  bool prepared[2] = { false, false };
  mobius::ParallelFor(2, threads, [&](int k, int) {
    if (!stored[k])
    {
      prepared[k] = mobius::PrepareSpectralSurface(maps[k].Surface, maps[k].Triangles, basisSize,
        filter->GetNumberOfSamples(), surfaces[k], errors[k], massShare);
    }
    // The mass is cheap to rebuild, and rebuilt exactly as the eigensolver built it.
    else if (mobius::BuildUnitAreaMassMatrix(
               maps[k].Surface, maps[k].Triangles, 0.0, bases[k].Mass, errors[k]))
    {
      mobius::PrepareSpectralSurface(maps[k].Surface, maps[k].Triangles, std::move(bases[k]),
        filter->GetNumberOfSamples(), surfaces[k]);
      prepared[k] = true;
    }
  });
  for (int k = 0; k < 2; ++k)
  {
    if (!prepared[k])
    {
      return InputError(k, errors[k]);
    }
  }
  return std::string();
}

// Both inputs' maps and spectral surfaces; the error, naming the input, if one cannot be
// refined.
std::string PrepareInputs(vtkCorrespondenceRefinement* filter, vtkPolyData* inputs[2],
  int threads, MapInput maps[2], mobius::SpectralSurface surfaces[2], bool stored[2])
{
  for (int k = 0; k < 2; ++k)
  {
    const std::string error = ExtractMapInput(inputs[k], filter->GetBasisSize(), maps[k]);
    if (!error.empty())
    {
      return InputError(k, error);
    }
  }
  return PrepareSurfaces(filter, inputs, maps, threads, surfaces, stored);
}

// The correspondence output (vtkDenseCorrespondence's) of the refined map, without the
// inputs' basis arrays.
void AssembleOutput(vtkCorrespondenceRefinement* filter, vtkPolyData* inputs[2],
  const MapInput maps[2], const mobius::RefinedCorrespondence& refined, vtkPolyData* output)
{
  const mobius::vtk::SurfaceLocations locations{ &maps[1].Triangles, refined.Dense.Triangle,
    refined.Dense.Barycentric };
  const std::string arrayWarning = mobius::vtk::AssembleCorrespondence(inputs[0], inputs[1],
    locations, filter->GetOutputGeometry() == vtkCorrespondenceRefinement::TARGET, output);
  if (!arrayWarning.empty())
  {
    vtkWarningWithObjectMacro(filter, << "Target: " << arrayWarning << ".");
  }
  mobius::vtk::RemoveBasisArrays(output);
}

// The filter's settings, progress and abort as the core's options.
mobius::CorrespondenceRefinementOptions RefinementOptions(
  vtkCorrespondenceRefinement* filter, int threads)
{
  mobius::CorrespondenceRefinementOptions options;
  options.ZoomOut.StartSize = filter->GetStartBasisSize();
  options.ZoomOut.Growth = filter->GetBasisGrowth();
  options.ZoomOut.FinalSize =
    mobius::ClampToBasisSize(filter->GetScreeningBasisSize(), filter->GetBasisSize());
  options.ZoomOut.FullResolutionIterations = filter->GetFullResolutionIterations();
  options.ZoomOut.NumberOfThreads = threads;
  options.BasisSize = filter->GetBasisSize();
  options.RepairOrientation = filter->GetRepairOrientation();
  options.SphereAnchorWeight = filter->GetSphereAnchorWeight();
  options.Criterion = filter->GetCandidateCriterion() == vtkCorrespondenceRefinement::ORTHOGONALITY
    ? mobius::CandidateCriterion::Orthogonality
    : mobius::CandidateCriterion::Curvature;
  options.Candidate = filter->GetCandidate();
  options.GeometricPolish = filter->GetGeometricPolish();
  options.BothDirections = filter->GetBothDirections();
  options.Progress = mobius::vtk::ProgressAndAbort(filter);
  return options;
}

// How the kept candidate was chosen, as the field data RefinementChoice and --json say it.
std::string ChoiceName(const mobius::RefinedCorrespondence& refined, int candidate)
{
  if (candidate >= 0)
  {
    return "given";
  }
  const double curvature = refined.Screened[refined.Choice.Kept].CurvatureDifference;
  const std::string criterion = std::isfinite(curvature) ? "curvature" : "orthogonality";
  return refined.Choice.ByFinishedMaps ? criterion + " and map stretch" : criterion;
}

// One sentence on the choice for the field data RefinementChoiceSummary, which ParaView's
// Information panel shows: what was kept and by what, and how close the runner-up came.
std::string ChoiceSummary(const mobius::RefinedCorrespondence& refined, int candidate)
{
  const mobius::CandidateChoice& choice = refined.Choice;
  std::ostringstream summary;
  summary << "Candidate " << choice.Kept;
  if (candidate >= 0)
  {
    summary << " kept as given (Candidate).";
    return summary.str();
  }
  const std::string by = ChoiceName(refined, candidate);
  summary << " kept by " << by;
  if (choice.ByFinishedMaps)
  {
    summary << " (score " << choice.Score[choice.Kept] << " times stretch "
            << choice.Stretch[choice.Kept]
            << "; both maps finished and compared, their scores having come within "
            << 100 * mobius::kFinishRunnerUpMargin << "%)";
  }
  else
  {
    summary << " (score " << choice.Score[choice.Kept] << ")";
  }
  if (choice.RunnerUp < 0)
  {
    summary << "; no other candidate of the expected orientation gave a different map.";
    return summary.str();
  }
  summary << "; runner-up " << choice.RunnerUp << " is " << 100 * choice.Margin << "% worse";
  if (choice.Margin < mobius::kNearEqualMargin)
  {
    summary << ": near-equal, check the map and see the other with Candidate = "
            << choice.RunnerUp;
  }
  summary << ".";
  return summary.str();
}

// The warning when the kept candidate's runner-up came almost as close by what decided
// (the screened maps' curvature, or the finished maps' stretch); empty when it did not (or
// there is none).
std::string NearEqualCandidatesWarning(const mobius::CandidateChoice& choice)
{
  if (choice.RunnerUp < 0 || !(choice.Margin < mobius::kNearEqualMargin))
  {
    return std::string();
  }
  std::ostringstream message;
  message << "Candidates " << choice.Kept << " (kept) and " << choice.RunnerUp
          << (choice.ByFinishedMaps
                 ? " give different maps that, finished, keep the surfaces' curvature and "
                   "stretch them almost equally (margin "
                 : " give different maps that keep the surfaces' curvature almost equally "
                   "well (margin ")
          << 100 * choice.Margin
          << "%): the map may be the wrong one of two, such as a body turned half a turn. "
             "Check it, and keep the other with Candidate = "
          << choice.RunnerUp << " (mobius-register --candidate " << choice.RunnerUp << ").";
  return message.str();
}

// Whether the registration's best transform is a reflection (field data Determinant < 0).
bool BestReflects(vtkPolyData* aligned)
{
  vtkDataArray* determinant = aligned->GetFieldData()->GetArray("Determinant");
  return determinant && determinant->GetComponent(0, 0) < 0;
}

// Whether SO3 Register's mirror check found that a transform of the other kind (a reflection
// for a search of rotations) aligns the pair far better (field data MirrorCheckErrors).
bool LooksMirrored(vtkPolyData* aligned)
{
  vtkDataArray* errors = aligned->GetFieldData()->GetArray("MirrorCheckErrors");
  return errors && errors->GetNumberOfValues() == 2 &&
    mobius::OtherKindFitsFarBetter(errors->GetComponent(0, 0), errors->GetComponent(0, 1));
}

// The warnings about a refined map: a near-equal runner-up (unless the candidate was given,
// or the pair looks mirrored: no candidate of the kind searched is right then, and SO3
// Register's warning says what is), a failed polish.
void WarnAboutRefinement(vtkCorrespondenceRefinement* filter, vtkPolyData* aligned,
  const mobius::RefinedCorrespondence& refined)
{
  const std::string nearEqual = filter->GetCandidate() < 0 && !LooksMirrored(aligned)
    ? NearEqualCandidatesWarning(refined.Choice)
    : std::string();
  if (!nearEqual.empty())
  {
    vtkWarningWithObjectMacro(filter, << nearEqual);
  }
  if (!refined.PolishError.empty())
  {
    vtkWarningWithObjectMacro(filter, << "The geometric polish failed (" << refined.PolishError
                                      << "); the spectral map is kept.");
  }
}

// The landmarks as vertex pairs of the surfaces, each source vertex made a sample; the
// error if one names a point an input does not have.
std::string LandmarkVertices(const std::vector<std::pair<vtkIdType, vtkIdType>>& landmarks,
  mobius::SpectralSurface surfaces[2], std::vector<std::pair<mobius::Index, mobius::Index>>& pairs)
{
  const std::string error = mobius::vtk::CheckLandmarkPoints(
    landmarks, surfaces[0].Positions.rows(), surfaces[1].Positions.rows());
  if (!error.empty())
  {
    return "Cannot refine: " + error + ".";
  }
  std::vector<mobius::Index> sourceVertices;
  for (const auto& landmark : landmarks)
  {
    pairs.emplace_back(landmark.first, landmark.second);
    sourceVertices.push_back(landmark.first);
  }
  mobius::AddPinnedSamples(surfaces[0], sourceVertices);
  return {};
}

// What the refinement starts from: both maps and their spectral surfaces (Stored: made from
// a basis stored on the input), the target's point locator, the landmarks as vertex pairs,
// the candidates' start rotations, and the seconds the surfaces took.
struct RefinementStart
{
  MapInput Maps[2];
  mobius::SpectralSurface Surfaces[2];
  bool Stored[2] = { false, false };
  mobius::SphericalPointLocator Locator;
  std::vector<std::pair<mobius::Index, mobius::Index>> Landmarks;
  std::vector<mobius::RotationMatrix> Starts;
  double SurfaceSeconds = 0;
};

// Everything the refinement starts from; false with the error (a sentence), or with none
// when the filter was aborted.
bool PrepareRefinement(vtkCorrespondenceRefinement* filter, vtkPolyData* inputs[2],
  const std::vector<std::pair<vtkIdType, vtkIdType>>& landmarks, int threads,
  RefinementStart& start, std::string& error)
{
  const auto surfacesStart = std::chrono::steady_clock::now();
  error = PrepareInputs(filter, inputs, threads, start.Maps, start.Surfaces, start.Stored);
  if (!error.empty())
  {
    return false;
  }
  const std::chrono::duration<double> surfaceTime =
    std::chrono::steady_clock::now() - surfacesStart;
  start.SurfaceSeconds = surfaceTime.count();
  filter->UpdateProgress(0.5);
  if (filter->GetAbortExecute())
  {
    return false;
  }
  if (!start.Locator.Build(start.Maps[1].Sphere, start.Maps[1].Triangles, error))
  {
    error = InputError(1, error);
    return false;
  }
  error = LandmarkVertices(landmarks, start.Surfaces, start.Landmarks);
  if (!error.empty())
  {
    return false;
  }
  start.Starts = CandidateStarts(inputs[0], filter->GetSearchCandidates());
  error = mobius::CheckCandidate(filter->GetCandidate(), start.Starts.size());
  return error.empty();
}

// The point array MapStretch (mobius::EdgeStretch of the mapped points) and its
// area-weighted mean in field data.
void AddMapStretch(const MapInput& source, vtkPolyData* output)
{
  vtkDataArray* mapped = output->GetPointData()->GetArray("MappedPoints");
  if (!mapped || mapped->GetNumberOfTuples() != source.Surface.rows())
  {
    return;
  }
  mobius::Points mappedPoints(source.Surface.rows(), 3);
  for (vtkIdType i = 0; i < mapped->GetNumberOfTuples(); ++i)
  {
    mapped->GetTuple(i, mappedPoints.row(i).data());
  }
  const mobius::Vector stretch =
    mobius::EdgeStretch(source.Surface, source.Triangles, mappedPoints);
  vtkNew<vtkDoubleArray> array;
  array->SetName("MapStretch");
  array->SetNumberOfTuples(stretch.size());
  for (vtkIdType i = 0; i < stretch.size(); ++i)
  {
    array->SetValue(i, stretch[i]);
  }
  output->GetPointData()->AddArray(array);
  const mobius::Vector mass = mobius::LumpedMass(source.Surface, source.Triangles);
  mobius::vtk::SetFieldValue(
    output->GetFieldData(), "RefinementMeanStretch", stretch.dot(mass) / mass.sum());
}

// Field data holds no NaN or infinity: a figure that was not measured (no curvature, no
// runner-up to measure a margin to) is -1.
double OrMinusOne(double value)
{
  return std::isfinite(value) ? value : -1.0;
}

void SetFieldString(vtkFieldData* fieldData, const char* name, const std::string& value)
{
  vtkNew<vtkStringArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  fieldData->RemoveArray(name);
  fieldData->AddArray(array);
}

void SetFieldVector(vtkFieldData* fieldData, const char* name, const std::vector<double>& values)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (size_t i = 0; i < values.size(); ++i)
  {
    array->SetValue(static_cast<vtkIdType>(i), values[i]);
  }
  fieldData->RemoveArray(name);
  fieldData->AddArray(array);
}

// The candidates' screening figures, the choice and the refined map's figures as field
// data, with the MapStretch point array.
void AddRefinementFieldData(const mobius::RefinedCorrespondence& refined, int candidate,
  const MapInput& source, const double stageSeconds[4], const bool stored[2], int threads,
  vtkPolyData* output)
{
  vtkFieldData* fieldData = output->GetFieldData();
  using mobius::vtk::SetFieldInteger;
  using mobius::vtk::SetFieldValue;
  SetFieldInteger(fieldData, "RefinementCandidate", refined.Choice.Kept);
  std::vector<double> residuals, coverage, orientation, curvature;
  for (const mobius::SampleMap& map : refined.Screened)
  {
    residuals.push_back(map.OrthogonalityResidual);
    coverage.push_back(map.TargetCoverage);
    orientation.push_back(map.OrientationAgreement);
    curvature.push_back(OrMinusOne(map.CurvatureDifference));
  }
  SetFieldVector(fieldData, "CandidateOrthogonalityResiduals", residuals);
  SetFieldVector(fieldData, "CandidateTargetCoverage", coverage);
  SetFieldVector(fieldData, "CandidateOrientationAgreement", orientation);
  SetFieldVector(fieldData, "CandidateCurvatureDifferences", curvature);
  SetFieldVector(
    fieldData, "CandidateLandmarkDistanceDifferences", refined.LandmarkDistanceDifferences);
  std::vector<double> stretch;
  for (double value : refined.Choice.Stretch)
  {
    stretch.push_back(OrMinusOne(value));
  }
  SetFieldVector(fieldData, "CandidateMapStretch", stretch);
  const mobius::CandidateChoice& choice = refined.Choice;
  const int kept = choice.Kept;
  const double keptScore =
    choice.ByFinishedMaps ? choice.Score[kept] * choice.Stretch[kept] : choice.Score[kept];
  const double confidence[3] = { OrMinusOne(keptScore), static_cast<double>(choice.RunnerUp),
    OrMinusOne(choice.Margin) };
  mobius::vtk::SetFieldValues(fieldData, "RefinementConfidence", confidence, 3);
  SetFieldString(fieldData, "RefinementChoice", ChoiceName(refined, candidate));
  SetFieldString(fieldData, "RefinementChoiceSummary", ChoiceSummary(refined, candidate));
  AddMapStretch(source, output);
  SetFieldValue(fieldData, "RefinementOrientationAgreement", refined.Kept.OrientationAgreement);
  SetFieldInteger(fieldData, "RefinementOrientationRepaired", refined.WrongOrientation ? 1 : 0);
  SetFieldValue(fieldData, "RefinementOrthogonalityResidual", refined.Dense.OrthogonalityResidual);
  SetFieldInteger(
    fieldData, "RefinementBasisSize", static_cast<int>(refined.Dense.FunctionalMap.cols()));
  if (stageSeconds)
  {
    mobius::vtk::SetFieldValues(fieldData, "RefinementStageSeconds", stageSeconds, 4);
  }
  const int storedBases[2] = { stored[0] ? 1 : 0, stored[1] ? 1 : 0 };
  mobius::vtk::SetFieldIntegers(fieldData, "RefinementStoredBasisUsed", storedBases, 2);
  SetFieldInteger(fieldData, "NumberOfThreadsUsed", threads);
}
}

//------------------------------------------------------------------------------
vtkCorrespondenceRefinement::vtkCorrespondenceRefinement()
{
  this->SetNumberOfInputPorts(2);
  const mobius::RegistrationParameters defaults;
  this->BasisSize = defaults.BasisSize;
  this->StartBasisSize = defaults.StartBasisSize;
  this->ScreeningBasisSize = defaults.ScreeningBasisSize;
  this->FullResolutionIterations = mobius::ZoomOutParameters().FullResolutionIterations;
  this->GeometricPolish = defaults.GeometricPolish;
  this->BothDirections = defaults.BothDirections;
  this->Candidate = defaults.Candidate;
  this->OutputGeometry = defaults.OutputGeometry;
  this->NumberOfThreads = defaults.NumberOfThreads;
}

//------------------------------------------------------------------------------
bool vtkCorrespondenceRefinement::CanRefine(vtkIdType numberOfPoints, int basisSize)
{
  return mobius::RefinementApplies(numberOfPoints, basisSize);
}

//------------------------------------------------------------------------------
int vtkCorrespondenceRefinement::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkCorrespondenceRefinement::ComputeOutput(
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
  std::string error = mobius::CheckBasisSizes(this->StartBasisSize, this->BasisSize);
  const int threads = mobius::ResolveThreadCount(this->NumberOfThreads);
  RefinementStart start;
  if (!error.empty() || !PrepareRefinement(this, inputs, this->Landmarks, threads, start, error))
  {
    if (!error.empty())
    {
      vtkErrorMacro(<< error);
    }
    return 0;
  }
  const mobius::RefinedCorrespondence refined =
    mobius::RefineCorrespondence(start.Surfaces[0], start.Surfaces[1],
      { start.Maps[0].Sphere, start.Maps[1].Sphere, start.Maps[1].Triangles, start.Locator,
        start.Starts, BestReflects(inputs[0]), start.Landmarks },
      RefinementOptions(this, threads));
  if (refined.Stopped)
  {
    return 0;
  }
  WarnAboutRefinement(this, inputs[0], refined);
  AssembleOutput(this, inputs, start.Maps, refined, output);
  const double stageSeconds[4] = { start.SurfaceSeconds, refined.CandidateSeconds,
    refined.ExtensionSeconds, refined.PolishSeconds };
  AddRefinementFieldData(refined, this->Candidate, start.Maps[0],
    this->RecordTimings ? stageSeconds : nullptr, start.Stored, threads, output);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkCorrespondenceRefinement::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BasisSize: " << this->BasisSize << "\n";
  os << indent << "RecordTimings: " << (this->RecordTimings ? "on" : "off") << "\n";
  os << indent << "StartBasisSize: " << this->StartBasisSize << "\n";
  os << indent << "BasisGrowth: " << this->BasisGrowth << "\n";
  os << indent << "ScreeningBasisSize: " << this->ScreeningBasisSize << "\n";
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "FullResolutionIterations: " << this->FullResolutionIterations << "\n";
  os << indent << "SearchCandidates: " << this->SearchCandidates << "\n";
  os << indent << "RepairOrientation: " << this->RepairOrientation << "\n";
  os << indent << "ConsistentMassShare: " << this->ConsistentMassShare << "\n";
  os << indent << "GeometricPolish: " << this->GeometricPolish << "\n";
  os << indent << "BothDirections: " << this->BothDirections << "\n";
  os << indent << "SphereAnchorWeight: " << this->SphereAnchorWeight << "\n";
  os << indent << "CandidateCriterion: " << this->CandidateCriterion << "\n";
  os << indent << "Candidate: " << this->Candidate << "\n";
  os << indent << "OutputGeometry: " << this->OutputGeometry << "\n";
}
