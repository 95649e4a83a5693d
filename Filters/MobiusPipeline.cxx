#include "MobiusPipeline.h"

#include "MobiusFilterMessages.h"
#include "LandmarkDisagreement.h"
#include "MobiusInputRows.h"
#include "MobiusSphericalMapData.h"
#include "ParallelFor.h"
#include "ParameterRules.h"
#include "RegistrationParameters.h"
#include "vtkCorrespondenceRefinement.h"
#include "vtkDenseCorrespondence.h"
#include "vtkMobiusCenter.h"
#include "vtkSO3Register.h"
#include "vtkSphericalConformalMap.h"
#include "vtkSphericalOrbifoldMap.h"
#include "vtkSymmetryDetection.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <unordered_map>
#include <utility>

namespace
{
using AbortCheck = std::function<bool()>;

// Forwards a filter's progress as `stage`'s while it lives, and stops the filter when
// `abort` says so.
class ProgressForwarder
{
public:
  ProgressForwarder(vtkAlgorithm* filter, std::string stage, const StageProgress& progress,
    const AbortCheck& abort)
    : Filter(filter)
    , Stage(std::move(stage))
    , Progress(progress)
    , Abort(abort)
  {
    this->OnProgress->SetClientData(this);
    this->OnProgress->SetCallback([](vtkObject*, unsigned long, void* self, void* data) {
      auto forwarder = static_cast<ProgressForwarder*>(self);
      if (forwarder->Progress && data)
      {
        forwarder->Progress(forwarder->Stage, *static_cast<double*>(data));
      }
      if (forwarder->Abort && forwarder->Abort())
      {
        forwarder->Filter->SetAbortExecute(1);
      }
    });
    this->Tag = filter->AddObserver(vtkCommand::ProgressEvent, this->OnProgress);
  }
  ~ProgressForwarder() { this->Filter->RemoveObserver(this->Tag); }
  ProgressForwarder(const ProgressForwarder&) = delete;
  ProgressForwarder& operator=(const ProgressForwarder&) = delete;

private:
  vtkAlgorithm* Filter;
  std::string Stage;
  StageProgress Progress;
  AbortCheck Abort;
  vtkNew<vtkCallbackCommand> OnProgress;
  unsigned long Tag;
};

// Runs `filter`, timing it as `stage`. False (with `error` set) if it failed. Messages
// start with `subject`, or with `stage` when `subject` is empty.
bool RunStage(vtkPolyDataAlgorithm* filter, const std::string& stage, const std::string& subject,
  const StageProgress& progress, PipelineResult& result, vtkSmartPointer<vtkPolyData>& output,
  std::string& error, const AbortCheck& abort = {})
{
  const std::string& prefix = subject.empty() ? stage : subject;
  mobius::vtk::FilterMessages monitor(filter);
  ProgressForwarder forwarder(filter, stage, progress, abort);
  const auto start = std::chrono::steady_clock::now();
  filter->Update();
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.Stages.push_back({ stage, seconds });
  for (const auto& warning : monitor.Warnings)
  {
    result.Warnings.push_back(prefix + ": " + warning);
  }
  output = vtkSmartPointer<vtkPolyData>::New();
  output->ShallowCopy(filter->GetOutput());
  if (!monitor.Error.empty() || output->GetNumberOfPoints() == 0)
  {
    error = prefix + ": " + (monitor.Error.empty() ? stage + " produced no output" : monitor.Error);
    return false;
  }
  return true;
}

// The conformal map stage of both jobs; a degenerate map is an error unless AllowPoorMaps.
bool MapToSphere(vtkPolyData* mesh, const std::string& name, const std::string& stage,
  const mobius::RegistrationParameters& options, const StageProgress& progress,
  PipelineResult& result, vtkSmartPointer<vtkPolyData>& map, std::string& error,
  bool linearStart = true, const AbortCheck& abort = {})
{
  vtkNew<vtkSphericalConformalMap> conformal;
  conformal->SetLinearStart(linearStart);
  conformal->SetInputData(mesh);
  conformal->SetMaximumNumberOfIterations(options.FlowIterations);
  conformal->SetConvergenceTolerance(options.FlowTolerance);
  conformal->SetCenterBetweenSteps(options.CenterBetweenSteps);
  conformal->SetRepair(options.Repair);
  conformal->SetFillHoles(options.FillHoles);
  conformal->SetKeepLargestComponent(options.KeepLargestComponent);
  if (!RunStage(conformal, stage, name, progress, result, map, error, abort))
  {
    return false;
  }
  // A degenerate map still has the right shape and would go through every later stage: a
  // wrong correspondence would be written as if it were a result.
  if (!options.AllowPoorMaps && FieldValue(map, "DegenerateMap") == 1)
  {
    auto reason =
      vtkStringArray::SafeDownCast(map->GetFieldData()->GetAbstractArray("DegenerateMapReason"));
    error = (name.empty() ? stage : name) + ": the conformal map is degenerate: " +
      (reason && reason->GetNumberOfValues() > 0 ? reason->GetValue(0) : std::string("see its field data")) +
      "; set AllowPoorMaps to write the result anyway";
    return false;
  }
  return true;
}

// The landmarks, as points of the maps, to a stage filter.
void AddLandmarkPoints(const PipelineResult& result, vtkMobiusLandmarkPolyDataAlgorithm* stage)
{
  for (size_t k = 0; k < result.SourceLandmarks.size(); ++k)
  {
    stage->AddLandmark(result.SourceLandmarks[k], result.TargetLandmarks[k]);
  }
}

// The candidates' transforms (field data CandidateTransforms of SO3 Register's output), best
// first.
std::vector<Eigen::Matrix3d> CandidateTransforms(vtkPolyData* aligned)
{
  std::vector<Eigen::Matrix3d> candidates;
  vtkDataArray* transforms = aligned->GetFieldData()->GetArray("CandidateTransforms");
  if (!transforms || transforms->GetNumberOfComponents() != 9)
  {
    return candidates;
  }
  for (vtkIdType c = 0; c < transforms->GetNumberOfTuples(); ++c)
  {
    Eigen::Matrix3d transform;
    for (int k = 0; k < 9; ++k)
    {
      transform(k / 3, k % 3) = transforms->GetComponent(c, k);
    }
    candidates.push_back(transform);
  }
  return candidates;
}

// The landmarks' points on the aligned source's sphere and on the target's.
mobius::SphereLandmarks LandmarkSpherePoints(const PipelineResult& result)
{
  const auto count = static_cast<mobius::Index>(result.SourceLandmarks.size());
  mobius::SphereLandmarks landmarks;
  landmarks.Source.resize(count, 3);
  landmarks.Target.resize(count, 3);
  for (mobius::Index k = 0; k < count; ++k)
  {
    result.Aligned->GetPoint(result.SourceLandmarks[k], landmarks.Source.row(k).data());
    result.TargetCentered->GetPoint(result.TargetLandmarks[k], landmarks.Target.row(k).data());
  }
  return landmarks;
}

// The candidate the final map starts from: the refinement's kept one, 0 for the Möbius map.
int StartingCandidate(const PipelineResult& result)
{
  const double kept = result.Correspondence == result.MobiusCorrespondence
    ? 0.0
    : FieldValue(result.Correspondence, "RefinementCandidate");
  return std::isfinite(kept) ? static_cast<int>(kept) : 0;
}

// The warning when the landmarks disagree with the final map's starting rotation
// (mobius::LandmarkDisagreement); empty when they agree.
std::string LandmarkDisagreement(const PipelineResult& result, const mobius::RegistrationParameters& options)
{
  if (result.SourceLandmarks.empty() || !result.Aligned || !result.TargetCentered)
  {
    return {};
  }
  return mobius::LandmarkDisagreement(CandidateTransforms(result.Aligned),
    StartingCandidate(result), LandmarkSpherePoints(result), options);
}

// Field data `LandmarkCount` and `LandmarkResidual` of the final map: per landmark, the
// straight-line distance between the image of its source point (MappedPoints) and its target
// point on the target surface, over sqrt(target area).
void AddLandmarkResiduals(PipelineResult& result)
{
  vtkFieldData* fields = result.Correspondence->GetFieldData();
  mobius::vtk::SetFieldInteger(
    fields, "LandmarkCount", static_cast<int>(result.SourceLandmarks.size()));
  vtkDataArray* mapped = result.Correspondence->GetPointData()->GetArray("MappedPoints");
  vtkDataArray* targetSurface = result.TargetCentered->GetPointData()->GetArray("SurfacePoints");
  vtkDataArray* targetAreas = result.TargetCentered->GetCellData()->GetArray("SurfaceArea");
  vtkNew<vtkDoubleArray> residuals;
  residuals->SetName("LandmarkResidual");
  double area = 0;
  for (vtkIdType t = 0; targetAreas && t < targetAreas->GetNumberOfTuples(); ++t)
  {
    area += targetAreas->GetComponent(t, 0);
  }
  for (size_t k = 0; mapped && targetSurface && area > 0 && k < result.SourceLandmarks.size(); ++k)
  {
    double image[3], target[3];
    mapped->GetTuple(result.SourceLandmarks[k], image);
    targetSurface->GetTuple(result.TargetLandmarks[k], target);
    residuals->InsertNextValue(
      std::sqrt(vtkMath::Distance2BetweenPoints(image, target) / area));
  }
  fields->RemoveArray("LandmarkResidual");
  fields->AddArray(residuals);
}

// Two landmarks on one point of a mapped surface (two vertices the repair merged, being
// copies of one point) would pull it two ways, and one of them would silently lose: an
// error naming both.
bool CheckDistinctLandmarkPoints(const std::vector<vtkIdType>& points, bool source,
  const mobius::RegistrationParameters& options, const std::string& name, std::string& error)
{
  std::unordered_map<vtkIdType, size_t> first;
  for (size_t k = 0; k < points.size(); ++k)
  {
    const auto [at, inserted] = first.emplace(points[k], k);
    if (!inserted)
    {
      auto vertex = [&](size_t l) {
        const mobius::Landmark& landmark = options.Landmarks[l];
        return std::to_string(source ? landmark.Source : landmark.Target);
      };
      error = name + ": " + mobius::LandmarkLabel(options, at->second) + " and " + mobius::LandmarkLabel(options, k) +
        " name " + (source ? "source" : "target") + " vertices " + vertex(at->second) + " and " +
        vertex(k) + ", which are one point of the surface (duplicates at one position, merged by "
        "the repair): give only one of them";
      return false;
    }
  }
  return true;
}

// result.InputCorrespondence: the final map on the meshes as given.
bool PutOnInputs(vtkPolyData* source, vtkPolyData* target,
  const mobius::RegistrationParameters& options, PipelineResult& result, std::string& error)
{
  result.InputCorrespondence = result.Correspondence;
  if (options.InputsAreCenteredMaps ||
    (!mobius::vtk::MapWasRepaired(result.SourceMap) && !mobius::vtk::MapWasRepaired(result.TargetMap)))
  {
    return true;
  }
  std::string problem;
  result.InputCorrespondence = mobius::vtk::CorrespondenceOnInputs(source, target, result.SourceMap,
    result.TargetMap, result.Correspondence, options.OutputGeometry == 0, problem);
  if (!result.InputCorrespondence)
  {
    error = "the map on the meshes as given: " + problem;
    return false;
  }
  return true;
}

// The target's mesh for its job when the two meshes are mapped side by side: a copy of its
// own. The meshes may share arrays (one mesh given as both inputs, or a vtkTransformFilter's
// output, which shares its input's cells), and VTK reads and builds some state inside an
// array or a mesh (a cell array's traversal cursor, a mesh's cell structures), which two
// threads must not do at once.
vtkSmartPointer<vtkPolyData> TargetForItsJob(vtkPolyData* target, bool sideBySide)
{
  vtkSmartPointer<vtkPolyData> targetCopy = target;
  if (sideBySide)
  {
    targetCopy = vtkSmartPointer<vtkPolyData>::New();
    targetCopy->DeepCopy(target);
  }
  return targetCopy;
}

// The two meshes' jobs' timings and warnings, in the order source, target.
void MergeMeshJobs(const PipelineResult parts[2], PipelineResult& result)
{
  for (int k = 0; k < 2; ++k)
  {
    result.Stages.insert(result.Stages.end(), parts[k].Stages.begin(), parts[k].Stages.end());
    result.Warnings.insert(result.Warnings.end(), parts[k].Warnings.begin(), parts[k].Warnings.end());
  }
}

// Both meshes' conformal maps and centerings (none for centered maps given). They are
// independent, and the conformal flow runs on one core: with two threads or more the
// target's runs beside the source's (on the man, 17,495 vertices: 0.5 s of a ~3 s job).
// Each job times and reports into its own result; they are merged in the order source,
// target. False with the first mesh's error.
bool MapAndCenterBoth(vtkPolyData* source, vtkPolyData* target, const std::string names[2],
  const mobius::RegistrationParameters& options, int threads, const StageProgress& progress,
  PipelineResult& result, std::string& error)
{
  const bool sideBySide = threads > 1 && !options.InputsAreCenteredMaps;
  const vtkSmartPointer<vtkPolyData> targetCopy = TargetForItsJob(target, sideBySide);
  vtkPolyData* inputs[2] = { source, targetCopy };
  vtkSmartPointer<vtkPolyData>* maps[2] = { &result.SourceMap, &result.TargetMap };
  vtkSmartPointer<vtkPolyData>* centered[2] = { &result.SourceCentered, &result.TargetCentered };
  const char* which[2] = { "source", "target" };
  std::mutex progressLock;
  const StageProgress sharedProgress = [&](const std::string& stage, double fraction) {
    if (progress)
    {
      std::lock_guard<std::mutex> guard(progressLock);
      progress(stage, fraction);
    }
  };
  PipelineResult parts[2];
  std::string errors[2];
  bool ok[2] = { false, false };
  // In turn (one thread) the target is not mapped after the source failed. ParallelFor
  // carries an exception of either job here once both are done.
  mobius::ParallelFor(2, sideBySide ? threads : 1, [&](int k, int) {
    if (k == 0 || sideBySide || ok[0])
    {
      OneMeshStages stages;
      stages.Which = std::string(" (") + which[k] + ")";
      stages.Map = stages.Center = !options.InputsAreCenteredMaps;
      ok[k] = MapAndCenter(inputs[k], names[k], options, stages, sharedProgress, parts[k],
        *maps[k], *centered[k], errors[k]);
    }
  });
  MergeMeshJobs(parts, result);
  for (int k = 0; k < 2; ++k)
  {
    if (!ok[k])
    {
      error = errors[k];
      return false;
    }
  }
  return true;
}

// The landmarks as points of the two centered maps, each named once.
bool FindLandmarksOnMaps(vtkPolyData* source, vtkPolyData* target, const std::string names[2],
  const mobius::RegistrationParameters& options, PipelineResult& result, std::string& error)
{
  return FindLandmarkPoints(source, result.SourceCentered, true, options, names[0],
           result.SourceLandmarks, error) &&
    FindLandmarkPoints(target, result.TargetCentered, false, options, names[1],
      result.TargetLandmarks, error) &&
    CheckDistinctLandmarkPoints(result.SourceLandmarks, true, options, names[0], error) &&
    CheckDistinctLandmarkPoints(result.TargetLandmarks, false, options, names[1], error);
}

// The rotational alignment of the centered maps (vtkSO3Register): result.Aligned.
bool AlignMaps(const mobius::RegistrationParameters& options, int threads,
  const std::string& pair, const StageProgress& progress, PipelineResult& result,
  std::string& error)
{
  vtkNew<vtkSO3Register> registration;
  registration->SetSourceData(result.SourceCentered);
  registration->SetTargetData(result.TargetCentered);
  registration->SetResolution(options.Resolution);
  registration->SetSmoothingTime(options.SmoothingTime);
  registration->SetTransformMode(options.TransformMode);
  registration->SetNumberOfCandidates(options.NumberOfCandidates);
  registration->SetCandidateSeparation(options.CandidateSeparation);
  registration->SetNumberOfThreads(threads);
  registration->SetLandmarkMode(options.LandmarkMode);
  AddLandmarkPoints(result, registration);
  return RunStage(
    registration, "rotational alignment", pair, progress, result, result.Aligned, error);
}

// The Möbius map (vtkDenseCorrespondence): result.MobiusCorrespondence.
bool CorrespondMaps(const mobius::RegistrationParameters& options, int threads,
  const std::string& pair, const StageProgress& progress, PipelineResult& result,
  std::string& error)
{
  vtkNew<vtkDenseCorrespondence> correspondence;
  correspondence->SetSourceData(result.Aligned);
  correspondence->SetTargetData(result.TargetCentered);
  correspondence->SetOutputGeometry(options.OutputGeometry);
  correspondence->SetNumberOfThreads(threads);
  AddLandmarkPoints(result, correspondence);
  return RunStage(correspondence, "dense correspondence", pair, progress, result,
    result.MobiusCorrespondence, error);
}

// The refinement's spectral search compares BasisSize eigenfunctions and needs about twice
// as many vertices to sample them: on a smaller mesh the Möbius map is the answer. True,
// with the warning saying so, when the refinement is skipped.
bool SkipsRefinement(
  const mobius::RegistrationParameters& options, const std::string& pair, PipelineResult& result)
{
  const vtkIdType smallest = std::min(
    result.Aligned->GetNumberOfPoints(), result.TargetCentered->GetNumberOfPoints());
  if (mobius::RefinementApplies(smallest, options.BasisSize))
  {
    return false;
  }
  result.Warnings.push_back(pair + ": refinement skipped: a map has " +
    std::to_string(smallest) + " vertices, fewer than twice the basis size " +
    std::to_string(options.BasisSize) + " (BasisSize); the result is the Moebius map");
  return true;
}

// The refined map (vtkCorrespondenceRefinement): result.Correspondence.
bool RefineMap(const mobius::RegistrationParameters& options, int threads,
  const std::string& pair, const StageProgress& progress, PipelineResult& result,
  std::string& error)
{
  vtkNew<vtkCorrespondenceRefinement> refinement;
  refinement->SetSourceData(result.Aligned);
  refinement->SetTargetData(result.TargetCentered);
  refinement->SetOutputGeometry(options.OutputGeometry);
  refinement->SetBasisSize(options.BasisSize);
  refinement->SetStartBasisSize(
    mobius::ClampToBasisSize(refinement->GetStartBasisSize(), options.BasisSize));
  refinement->SetGeometricPolish(options.GeometricPolish);
  refinement->SetBothDirections(options.BothDirections);
  refinement->SetCandidate(options.Candidate);
  refinement->SetNumberOfThreads(threads);
  AddLandmarkPoints(result, refinement);
  return RunStage(
    refinement, "refinement", pair, progress, result, result.Correspondence, error);
}

// After the final map (`succeeded`): the landmarks' residuals, the warning when they
// disagree with the map, and the map on the meshes as given; the job's wall time either way.
bool FinishRegistration(vtkPolyData* source, vtkPolyData* target,
  const mobius::RegistrationParameters& options, const std::string& pair,
  std::chrono::steady_clock::time_point started, bool succeeded, PipelineResult& result,
  std::string& error)
{
  if (succeeded)
  {
    AddLandmarkResiduals(result);
    const std::string disagreement = LandmarkDisagreement(result, options);
    if (!disagreement.empty())
    {
      result.Warnings.push_back(pair + ": " + disagreement);
    }
    succeeded = PutOnInputs(source, target, options, result, error);
  }
  result.WallSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return succeeded;
}
}

bool MapAndCenter(vtkPolyData* mesh, const std::string& name,
  const mobius::RegistrationParameters& options, const OneMeshStages& stages,
  const StageProgress& progress, PipelineResult& result, vtkSmartPointer<vtkPolyData>& map,
  vtkSmartPointer<vtkPolyData>& centered, std::string& error)
{
  if (!stages.Map)
  {
    map = mesh;
  }
  else if (!MapToSphere(mesh, name, "conformal map" + stages.Which, options, progress, result, map,
             error, stages.LinearStart, stages.Abort))
  {
    return false;
  }
  if (!stages.Center)
  {
    centered = map;
    return true;
  }
  vtkNew<vtkMobiusCenter> center;
  center->SetInputData(map);
  center->SetTolerance(options.CenteringTolerance);
  center->SetDegree(options.CenteringDegree);
  return RunStage(
    center, "centering" + stages.Which, name, progress, result, centered, error, stages.Abort);
}

bool FindLandmarkPoints(vtkPolyData* mesh, vtkPolyData* map, bool source,
  const mobius::RegistrationParameters& options, const std::string& name,
  std::vector<vtkIdType>& points, std::string& error)
{
  points.clear();
  if (options.Landmarks.empty())
  {
    return true;
  }
  vtkDataArray* inputIds = map->GetPointData()->GetArray("InputPointId");
  vtkDataArray* surface = map->GetPointData()->GetArray("SurfacePoints");
  std::unordered_map<vtkIdType, vtkIdType> pointOf;
  for (vtkIdType i = 0; inputIds && i < inputIds->GetNumberOfTuples(); ++i)
  {
    pointOf.emplace(static_cast<vtkIdType>(inputIds->GetComponent(i, 0)), i);
  }
  for (size_t k = 0; k < options.Landmarks.size(); ++k)
  {
    const vtkIdType vertex =
      static_cast<vtkIdType>(source ? options.Landmarks[k].Source : options.Landmarks[k].Target);
    const auto found = pointOf.find(vertex);
    vtkIdType point = found != pointOf.end() ? found->second : -1;
    // A duplicate the repair merged: the point kept is at the same place on the surface.
    if (point < 0 && mesh != map && surface && vertex >= 0 && vertex < mesh->GetNumberOfPoints())
    {
      double position[3], candidate[3];
      mesh->GetPoint(vertex, position);
      for (vtkIdType i = 0; i < surface->GetNumberOfTuples() && point < 0; ++i)
      {
        surface->GetTuple(i, candidate);
        if (candidate[0] == position[0] && candidate[1] == position[1] &&
          candidate[2] == position[2])
        {
          point = i;
        }
      }
    }
    if (point < 0)
    {
      error = name + ": " + mobius::LandmarkLabel(options, k) + ": " +
        (source ? "source" : "target") + " vertex " + std::to_string(vertex) +
        " is not on the mapped surface: the mesh's repair removed it (a vertex no triangle "
        "uses, or one outside the largest component); choose another vertex";
      return false;
    }
    points.push_back(point);
  }
  return true;
}

double FieldValue(vtkPolyData* data, const char* name, int component)
{
  vtkDataArray* array = data ? data->GetFieldData()->GetArray(name) : nullptr;
  return array && component < array->GetNumberOfComponents() ? array->GetComponent(0, component)
                                                             : std::nan("");
}

bool RunRegistrationPipeline(vtkPolyData* source, vtkPolyData* target,
  const std::string& sourceName, const std::string& targetName,
  const mobius::RegistrationParameters& options, PipelineResult& result, std::string& error,
  const StageProgress& progress)
{
  const auto started = std::chrono::steady_clock::now();
  const int threads = mobius::ResolveThreadCount(options.NumberOfThreads);
  const std::string names[2] = { sourceName, targetName };
  const std::string pair = sourceName + " -> " + targetName;
  if (!MapAndCenterBoth(source, target, names, options, threads, progress, result, error) ||
    !FindLandmarksOnMaps(source, target, names, options, result, error) ||
    !AlignMaps(options, threads, pair, progress, result, error) ||
    !CorrespondMaps(options, threads, pair, progress, result, error))
  {
    return false;
  }
  result.Correspondence = result.MobiusCorrespondence;
  const bool succeeded = !options.Refine || SkipsRefinement(options, pair, result) ||
    RefineMap(options, threads, pair, progress, result, error);
  return FinishRegistration(source, target, options, pair, started, succeeded, result, error);
}

bool RunSymmetryPipeline(vtkPolyData* mesh, const std::string& name,
  const mobius::RegistrationParameters& options, PipelineResult& result, std::string& error,
  const StageProgress& progress)
{
  // The uncentered comparison leaves out the centering between flow steps too.
  mobius::RegistrationParameters mapOptions = options;
  mapOptions.CenterBetweenSteps = options.CenterBetweenSteps && options.Centering;
  if (!MapToSphere(mesh, name, "conformal map", mapOptions, progress, result, result.SourceMap, error))
  {
    return false;
  }
  if (options.Refine &&
    !mobius::RefinementApplies(result.SourceMap->GetNumberOfPoints(), options.BasisSize))
  {
    result.Warnings.push_back(name + ": refinement skipped: the map has " +
      std::to_string(result.SourceMap->GetNumberOfPoints()) +
      " vertices, fewer than twice the basis size " + std::to_string(options.BasisSize) +
      " (BasisSize); the symmetric map is the Moebius map");
  }
  vtkNew<vtkSymmetryDetection> detection;
  detection->SetInputData(result.SourceMap);
  detection->SetCentering(options.Centering);
  detection->SetResolution(options.Resolution);
  detection->SetSmoothingTime(options.SmoothingTime);
  detection->SetNumberOfCandidates(options.NumberOfCandidates);
  detection->SetRefine(options.Refine);
  detection->SetBasisSize(options.BasisSize);
  detection->SetGeometricPolish(options.GeometricPolish);
  detection->SetNumberOfThreads(options.NumberOfThreads);
  const size_t warnings = result.Warnings.size();
  if (!RunStage(detection, "symmetry detection", name, progress, result, result.Correspondence, error))
  {
    return false;
  }
  // The filter's own "refinement skipped" warning repeats the one above.
  result.Warnings.erase(std::remove_if(result.Warnings.begin() + warnings, result.Warnings.end(),
                          [](const std::string& warning) {
                            return warning.find("Refinement skipped") != std::string::npos;
                          }),
    result.Warnings.end());
  return true;
}

bool RunOrbifoldPipeline(vtkPolyData* mesh, const std::string& name,
  const mobius::RegistrationParameters& options, int copies, const long long cones[2],
  bool covering, PipelineResult& result, std::string& error, const StageProgress& progress)
{
  if (!MapToSphere(mesh, name, "conformal map", options, progress, result, result.SourceMap, error))
  {
    return false;
  }
  vtkNew<vtkSphericalOrbifoldMap> orbifold;
  orbifold->SetInputData(result.SourceMap); // cones: its InputPointId, the file's numbering
  orbifold->SetNumberOfCopies(copies);
  orbifold->SetConeIds(static_cast<vtkIdType>(cones[0]), static_cast<vtkIdType>(cones[1]));
  orbifold->SetOutputCovering(covering);
  return RunStage(orbifold, "orbifold map", name, progress, result, result.Correspondence, error);
}
