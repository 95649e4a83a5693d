#include "vtkSymmetryDetection.h"

#include "MobiusPipeline.h"
#include "RegistrationParameters.h"
#include "ScaleFactorSignal.h"
#include "ParallelFor.h"
#include "SymmetryMeasures.h"
#include "VertexSnapping.h"
#include "MobiusCorrespondenceOutput.h"
#include "vtkCorrespondenceRefinement.h"
#include "vtkDenseCorrespondence.h"
#include "vtkSO3Register.h"
#include "MobiusSphericalMapData.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSymmetryDetection);

namespace
{
using Matrix3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

// A spherical map carries its surface in `SurfacePoints` and lies on the unit sphere; any
// other input is a surface mesh still to be mapped.
bool IsSphericalMap(vtkPolyData* input)
{
  mobius::Points points;
  return mobius::vtk::CheckSurfacePoints(input).empty() &&
    input->GetCellData()->GetArray(mobius::vtk::SurfaceAreaArrayName) &&
    mobius::vtk::ExtractPoints(input, points).empty() &&
    mobius::vtk::CheckOnUnitSphere(points).empty();
}

void AddTuples(vtkFieldData* fieldData, const char* name, int components,
  const std::vector<double>& values)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size() / components));
  for (size_t i = 0; i < values.size(); ++i)
  {
    array->SetValue(static_cast<vtkIdType>(i), values[i]);
  }
  fieldData->RemoveArray(name);
  fieldData->AddArray(array);
}

// The centered map's surface, sphere and triangles (with their surface areas) and the
// reflected map's sphere points, or why they cannot be read.
struct SymmetryGeometry
{
  mobius::Points Surface, Sphere, ReflectedSphere;
  mobius::Triangles Triangles;
  mobius::Vector Areas;
};

std::string ExtractSymmetryGeometry(
  vtkPolyData* centered, vtkPolyData* reflected, SymmetryGeometry& geometry)
{
  std::string error = mobius::vtk::ExtractSurfacePoints(centered, geometry.Surface);
  if (error.empty())
  {
    error = mobius::vtk::ExtractSphericalMap(
      centered, false, geometry.Sphere, geometry.Triangles, geometry.Areas);
  }
  if (error.empty())
  {
    error = mobius::vtk::ExtractPoints(reflected, geometry.ReflectedSphere);
  }
  return error;
}

// Where the symmetric map puts each vertex: a triangle of `triangles` and barycentric
// coordinates in it.
std::string LocationsOf(vtkPolyData* symmetric, const mobius::Triangles& triangles,
  mobius::vtk::SurfaceLocations& locations)
{
  vtkDataArray* cells = symmetric->GetPointData()->GetArray("TargetCellId");
  vtkDataArray* barycentric = symmetric->GetPointData()->GetArray("TargetBarycentric");
  if (!cells || !barycentric)
  {
    return "the symmetric map lacks TargetCellId or TargetBarycentric";
  }
  const vtkIdType n = symmetric->GetNumberOfPoints();
  locations.LocatedTriangles = &triangles;
  locations.Triangle.resize(n);
  locations.Barycentric.resize(n);
  for (vtkIdType v = 0; v < n; ++v)
  {
    locations.Triangle[v] = static_cast<mobius::Index>(cells->GetComponent(v, 0));
    barycentric->GetTuple(v, locations.Barycentric[v].data());
  }
  return std::string();
}

// The symmetric map as triangles and barycentric coordinates on the centered map, made exact
// where the spherical map is exactly symmetric (VertexSnapping.h; `snapped` vertices).
std::string LocateSymmetricMap(vtkPolyData* centered, vtkPolyData* reflected,
  vtkPolyData* symmetric, double snapTolerance, SymmetryGeometry& geometry,
  mobius::vtk::SurfaceLocations& locations, mobius::Index& snapped)
{
  std::string error = ExtractSymmetryGeometry(centered, reflected, geometry);
  if (error.empty())
  {
    error = LocationsOf(symmetric, geometry.Triangles, locations);
  }
  if (error.empty() && snapTolerance > 0)
  {
    snapped = mobius::SnapToCoincidentVertices(geometry.ReflectedSphere, geometry.Sphere,
      geometry.Triangles, snapTolerance, locations.Triangle, locations.Barycentric, error);
  }
  return error.empty() && snapped < 0 ? "the sphere cannot be searched" : error;
}

// The reflective registration's candidates (CandidateTransforms and their correlation
// coefficients), described by the core.
std::string MirrorCandidatesOf(vtkPolyData* reflected, mobius::MirrorCandidates& candidates)
{
  vtkDataArray* transforms = reflected->GetFieldData()->GetArray("CandidateTransforms");
  vtkDataArray* coefficients =
    reflected->GetFieldData()->GetArray("CandidateCorrelationCoefficients");
  std::vector<Eigen::Matrix3d> reflections;
  std::vector<double> correlations;
  for (vtkIdType c = 0; transforms && coefficients && c < transforms->GetNumberOfTuples(); ++c)
  {
    Matrix3 transform;
    transforms->GetTuple(c, transform.data());
    reflections.push_back(transform);
  }
  for (vtkIdType c = 0; transforms && coefficients && c < coefficients->GetNumberOfTuples(); ++c)
  {
    correlations.push_back(coefficients->GetComponent(c, 0));
  }
  return mobius::DescribeMirrorCandidates(reflections, correlations, candidates);
}

// The refinement's or dense correspondence's own field data (candidates, residuals), beside
// the arrays the assembly wrote.
void AddStageFields(vtkPolyData* assembled, vtkPolyData* symmetric)
{
  vtkFieldData* stageFields = symmetric->GetFieldData();
  for (int a = 0; a < stageFields->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = stageFields->GetAbstractArray(a);
    if (array->GetName() && !assembled->GetFieldData()->HasArray(array->GetName()))
    {
      assembled->GetFieldData()->AddArray(array);
    }
  }
}

mobius::Points MappedPointsOf(vtkPolyData* assembled)
{
  vtkDataArray* mapped = assembled->GetPointData()->GetArray("MappedPoints");
  const vtkIdType n = assembled->GetNumberOfPoints();
  mobius::Points mirrorPoints(n, 3);
  for (vtkIdType v = 0; v < n; ++v)
  {
    double point[3];
    mapped->GetTuple(v, point);
    mirrorPoints.row(v) << point[0], point[1], point[2];
  }
  return mirrorPoints;
}

// The symmetric map assembled again from the (snapped) locations into `output`, so that
// every output array agrees with the snapped map, with the stage's own field data. Returns
// a warning about arrays that could not be carried, or an empty string.
std::string AssembleSymmetricMap(vtkPolyData* output, vtkPolyData* reflected,
  vtkPolyData* centered, vtkPolyData* symmetric, const mobius::vtk::SurfaceLocations& locations)
{
  vtkNew<vtkPolyData> assembled;
  const std::string arrayWarning =
    mobius::vtk::AssembleCorrespondence(reflected, centered, locations, false, assembled);
  AddStageFields(assembled, symmetric);
  output->ShallowCopy(assembled);
  return arrayWarning;
}

void AddAsymmetryArray(vtkPolyData* output, const mobius::Vector& asymmetry)
{
  vtkNew<vtkDoubleArray> asymmetryArray;
  asymmetryArray->SetName("Asymmetry");
  asymmetryArray->SetNumberOfTuples(asymmetry.size());
  for (vtkIdType v = 0; v < asymmetry.size(); ++v)
  {
    asymmetryArray->SetValue(v, asymmetry(v));
  }
  output->GetPointData()->AddArray(asymmetryArray);
  output->GetPointData()->SetActiveScalars("Asymmetry");
}

// The symmetric map (AssembleSymmetricMap; a warning about arrays it could not carry) with
// its point array Asymmetry, which it returns.
mobius::Vector WriteSymmetricMap(vtkSymmetryDetection* filter, vtkPolyData* output,
  vtkPolyData* reflected, vtkPolyData* centered, vtkPolyData* symmetric,
  const SymmetryGeometry& geometry, const mobius::vtk::SurfaceLocations& locations)
{
  const std::string arrayWarning =
    AssembleSymmetricMap(output, reflected, centered, symmetric, locations);
  if (!arrayWarning.empty())
  {
    vtkWarningWithObjectMacro(filter, << arrayWarning << ".");
  }
  const mobius::Vector asymmetry = mobius::RelativeMirrorAsymmetry(geometry.Surface,
    geometry.Triangles, geometry.Areas, locations.Triangle, locations.Barycentric,
    MappedPointsOf(output));
  AddAsymmetryArray(output, asymmetry);
  return asymmetry;
}

// The distance and the plane of every candidate reflection, best first, and the asymmetry's
// mean and maximum.
void WriteSymmetryFields(vtkFieldData* fieldData, const mobius::MirrorCandidates& candidates,
  const mobius::Vector& asymmetry)
{
  const Matrix3 best = candidates.Best;
  mobius::vtk::SetFieldValue(fieldData, "SymmetryDistance", candidates.Distances[0]);
  AddTuples(fieldData, "CandidateSymmetryDistances", 1, candidates.Distances);
  mobius::vtk::SetFieldValues(fieldData, "Reflection", best.data(), 9);
  mobius::vtk::SetFieldValues(
    fieldData, "MirrorPlaneNormal", candidates.BestPlane.Normal.data(), 3);
  mobius::vtk::SetFieldValue(fieldData, "MirrorPlaneTwist", candidates.BestPlane.Twist);
  AddTuples(fieldData, "CandidateMirrorPlaneNormals", 3, candidates.Normals);
  mobius::vtk::SetFieldValue(fieldData, "MeanAsymmetry", asymmetry.mean());
  mobius::vtk::SetFieldValue(fieldData, "MaximumAsymmetry", asymmetry.maxCoeff());
}
}

//------------------------------------------------------------------------------
vtkSymmetryDetection::vtkSymmetryDetection()
{
  const mobius::RegistrationParameters defaults;
  this->Centering = defaults.Centering;
  this->Resolution = defaults.Resolution;
  this->SmoothingTime = defaults.SmoothingTime;
  this->NumberOfCandidates = defaults.NumberOfCandidates;
  this->Refine = defaults.Refine;
  this->BasisSize = defaults.BasisSize;
  this->GeometricPolish = defaults.GeometricPolish;
  this->NumberOfThreads = defaults.NumberOfThreads;
}

//------------------------------------------------------------------------------
int vtkSymmetryDetection::ComputeOutput(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = nullptr;
  vtkPolyData* output = nullptr;
  if (!this->GetInputAndOutput(inputVector, outputVector, input, output, "detect symmetry"))
  {
    return 0;
  }
  const std::string badResolution =
    mobius::CheckGridResolution(this->Resolution, mobius::MinimumResolution);
  if (!badResolution.empty())
  {
    vtkErrorMacro(<< badResolution << ".");
    return 0;
  }
  vtkSmartPointer<vtkPolyData> centered = this->CenteredMapOf(input);
  // Resolved once, so that every stage runs with the same count.
  const int threads = mobius::ResolveThreadCount(this->NumberOfThreads);
  vtkSmartPointer<vtkPolyData> reflected =
    centered ? this->SelfRegister(centered, threads) : nullptr;
  const bool refine = reflected && this->RefinementApplies(centered);
  vtkSmartPointer<vtkPolyData> symmetric =
    reflected ? this->SymmetricMap(reflected, centered, threads, refine) : nullptr;
  if (!symmetric)
  {
    return 0;
  }
  SymmetryGeometry geometry;
  mobius::vtk::SurfaceLocations locations;
  mobius::MirrorCandidates candidates;
  mobius::Index snapped = 0;
  std::string error = LocateSymmetricMap(
    centered, reflected, symmetric, this->SnapTolerance, geometry, locations, snapped);
  if (!error.empty() || !(error = MirrorCandidatesOf(reflected, candidates)).empty())
  {
    vtkErrorMacro(<< "Cannot detect symmetry: " << error << ".");
    return 0;
  }
  const mobius::Vector asymmetry =
    WriteSymmetricMap(this, output, reflected, centered, symmetric, geometry, locations);
  vtkFieldData* fieldData = output->GetFieldData();
  WriteSymmetryFields(fieldData, candidates, asymmetry);
  mobius::vtk::SetFieldInteger(fieldData, "SymmetryCentered", this->Centering ? 1 : 0);
  mobius::vtk::SetFieldInteger(fieldData, "SymmetryRefined", refine ? 1 : 0);
  mobius::vtk::SetFieldCount(fieldData, "SnappedVertices", static_cast<vtkIdType>(snapped));
  mobius::vtk::SetFieldInteger(fieldData, "NumberOfThreadsUsed", threads);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkSymmetryDetection::RunStage(
  vtkPolyDataAlgorithm* filter, const char* stage, double begin, double end)
{
  std::string error;
  std::vector<std::string> warnings;
  vtkSmartPointer<vtkPolyData> result = this->RunInternalFilter(filter, begin, end, error, warnings);
  for (const auto& warning : warnings)
  {
    vtkWarningMacro(<< stage << ": " << warning);
  }
  if (!result && !this->GetAbortExecute())
  {
    vtkErrorMacro(<< "Cannot detect symmetry: " << stage << ": "
                  << (error.empty() ? "the stage produced no output" : error));
  }
  return this->GetAbortExecute() ? nullptr : result;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkSymmetryDetection::CenteredMapOf(vtkPolyData* input)
{
  // The map and its centering as every job makes them (MobiusPipeline.h), on a copy: the
  // pipeline's input object stays out of the internal pipeline.
  vtkSmartPointer<vtkPolyData> copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(input);
  mobius::RegistrationParameters options; // the stages' defaults
  options.AllowPoorMaps = true;           // a poor map is reported in its field data
  // Centering between flow steps is centering too: off for the uncentered comparison.
  options.CenterBetweenSteps = this->Centering;
  OneMeshStages stages;
  stages.Map = !IsSphericalMap(input);
  stages.Center = this->Centering;
  // The flow from the surface: each of its steps commutes with a mirror symmetry of the
  // surface, so an exactly symmetric mesh gets an exactly symmetric map in the surface's
  // own orientation (TestSymmetryDetection: the mirror to 1e-6, every image on its partner
  // vertex). The linear start's pole sits in one triangle: its map is symmetric only to
  // the flow's tolerance.
  stages.LinearStart = false;
  stages.Abort = [this] { return this->GetAbortExecute() != 0; };
  const StageProgress progress = [this](const std::string& stage, double fraction) {
    // The conformal map takes most of the time before the registration.
    this->UpdateProgress(stage == "centering" ? 0.3 + 0.05 * fraction : 0.3 * fraction);
  };
  PipelineResult stageResult;
  vtkSmartPointer<vtkPolyData> map, centered;
  std::string stageError; // names its stage (MapAndCenter without a mesh name)
  const bool ready =
    MapAndCenter(copy, "", options, stages, progress, stageResult, map, centered, stageError);
  for (const auto& warning : stageResult.Warnings)
  {
    vtkWarningMacro(<< warning);
  }
  if (!ready && !this->GetAbortExecute())
  {
    vtkErrorMacro(<< "Cannot detect symmetry: " << stageError);
  }
  return ready && !this->GetAbortExecute() ? centered : nullptr;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkSymmetryDetection::SelfRegister(vtkPolyData* centered, int threads)
{
  // The map against itself, orientation-reversing transforms only: the mirror symmetries.
  vtkNew<vtkSO3Register> registration;
  registration->SetSourceData(centered);
  registration->SetTargetData(centered);
  registration->SetResolution(this->Resolution);
  registration->SetSmoothingTime(this->SmoothingTime);
  registration->SetNumberOfCandidates(this->NumberOfCandidates);
  registration->SetTransformModeToReflections();
  registration->CheckMirroringOff(); // the mesh against itself: the identity always fits best
  registration->SetNumberOfThreads(threads);
  return this->RunStage(registration, "reflective registration", 0.35, 0.5);
}

//------------------------------------------------------------------------------
bool vtkSymmetryDetection::RefinementApplies(vtkPolyData* centered)
{
  // The refinement samples BasisSize eigenfunctions on about twice as many vertices.
  const bool refine =
    this->Refine && mobius::RefinementApplies(centered->GetNumberOfPoints(), this->BasisSize);
  if (this->Refine && !refine)
  {
    vtkWarningMacro(<< "Refinement skipped: the mesh has " << centered->GetNumberOfPoints()
                    << " vertices, fewer than twice the BasisSize (" << this->BasisSize
                    << "); the symmetric map is the Moebius map.");
  }
  return refine;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkSymmetryDetection::SymmetricMap(
  vtkPolyData* reflected, vtkPolyData* centered, int threads, bool refine)
{
  if (!refine)
  {
    vtkNew<vtkDenseCorrespondence> correspondence;
    correspondence->SetSourceData(reflected);
    correspondence->SetTargetData(centered);
    correspondence->SetOutputGeometryToSource();
    correspondence->SetNumberOfThreads(threads);
    return this->RunStage(correspondence, "dense correspondence", 0.5, 0.95);
  }
  // The transforms are reflections, so the refinement expects an orientation-reversing
  // map and repairs one that comes out orientation-preserving (e.g. the identity).
  vtkNew<vtkCorrespondenceRefinement> refinement;
  refinement->SetSourceData(reflected);
  refinement->SetTargetData(centered);
  refinement->SetBasisSize(this->BasisSize);
  refinement->SetStartBasisSize(
    mobius::ClampToBasisSize(refinement->GetStartBasisSize(), this->BasisSize));
  refinement->SetGeometricPolish(this->GeometricPolish);
  refinement->SetOutputGeometryToSource();
  refinement->SetCandidateCriterionToOrthogonality();
  refinement->SetNumberOfThreads(threads);
  return this->RunStage(refinement, "refinement", 0.5, 0.95);
}

//------------------------------------------------------------------------------
void vtkSymmetryDetection::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Centering: " << this->Centering << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "SmoothingTime: " << this->SmoothingTime << "\n";
  os << indent << "NumberOfCandidates: " << this->NumberOfCandidates << "\n";
  os << indent << "Refine: " << this->Refine << "\n";
  os << indent << "BasisSize: " << this->BasisSize << "\n";
  os << indent << "GeometricPolish: " << this->GeometricPolish << "\n";
  os << indent << "SnapTolerance: " << this->SnapTolerance << "\n";
}
