#include "vtkCorrespondenceRefinement.h"

#include "RegistrationParameters.h"
#include "CandidateChoice.h"
#include "CotangentLaplacian.h"
#include "EdgeStretch.h"
#include "ParallelFor.h"
#include "SphericalPointLocator.h"
#include "SurfacePolish.h"
#include "ZoomOut.h"
#include "MobiusCorrespondenceOutput.h"
#include "MobiusLaplaceBeltramiBasisData.h"
#include "MobiusSphericalMapData.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkPointData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <Eigen/Core>
#include <Eigen/LU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <utility>

vtkStandardNewMacro(vtkCorrespondenceRefinement);

namespace
{
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

using Matrix3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

// The transforms to start from, as rotations of the already aligned source: the aligned
// points are T_best x, so candidate T_j is reached by T_j T_best^-1 (T orthogonal).
std::vector<Matrix3> CandidateStarts(vtkPolyData* aligned, bool searchCandidates)
{
  std::vector<Matrix3> starts{ Matrix3::Identity() };
  vtkDataArray* best = aligned->GetFieldData()->GetArray("Rotation");
  vtkDataArray* candidates = aligned->GetFieldData()->GetArray("CandidateTransforms");
  if (!searchCandidates || !best || !candidates || best->GetNumberOfComponents() != 9 ||
    candidates->GetNumberOfComponents() != 9)
  {
    return starts;
  }
  Matrix3 bestTransform;
  best->GetTuple(0, bestTransform.data());
  for (vtkIdType c = 0; c < candidates->GetNumberOfTuples(); ++c)
  {
    Matrix3 transform;
    candidates->GetTuple(c, transform.data());
    if (!transform.allFinite() || (transform - bestTransform).norm() < 1e-9)
    {
      continue; // the best one is already first
    }
    starts.emplace_back(transform * bestTransform.transpose());
  }
  return starts;
}

// The Möbius map of the source samples under one candidate: each sample rotated by `start`
// and located on the target sphere, sent to the nearest corner of its triangle.
std::vector<mobius::Index> StartingSampleMap(const Matrix3& start, const mobius::Points& sourceSphere,
  const std::vector<mobius::Index>& samples, const mobius::SphericalPointLocator& targetLocator,
  const mobius::Triangles& targetTriangles)
{
  std::vector<mobius::Index> targetVertex(samples.size());
  for (size_t s = 0; s < samples.size(); ++s)
  {
    const Eigen::Vector3d p = start * sourceSphere.row(samples[s]).transpose();
    const mobius::SphericalLocation location = targetLocator.Locate(p);
    Eigen::Index corner = 0;
    location.Barycentric.maxCoeff(&corner);
    targetVertex[s] = targetTriangles(location.Triangle, corner);
  }
  return targetVertex;
}

// The sphere points of both surfaces' samples, the source's turned by `start`: what keeps a
// candidate's ZoomOut on the side its rotation put it (mobius::SampleAnchor).
mobius::SampleAnchor SphereAnchor(const Matrix3& start, const mobius::Points& sourceSphere,
  const std::vector<mobius::Index>& sourceSamples, const mobius::Points& targetSphere,
  const std::vector<mobius::Index>& targetSamples, double weight)
{
  mobius::SampleAnchor anchor;
  anchor.Weight = weight;
  anchor.Source.resize(static_cast<Eigen::Index>(sourceSamples.size()), 3);
  for (size_t s = 0; s < sourceSamples.size(); ++s)
  {
    anchor.Source.row(static_cast<Eigen::Index>(s)) =
      (start * sourceSphere.row(sourceSamples[s]).transpose()).transpose();
  }
  anchor.Target.resize(static_cast<Eigen::Index>(targetSamples.size()), 3);
  for (size_t t = 0; t < targetSamples.size(); ++t)
  {
    anchor.Target.row(static_cast<Eigen::Index>(t)) = targetSphere.row(targetSamples[t]);
  }
  return anchor;
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
}

//------------------------------------------------------------------------------
vtkCorrespondenceRefinement::vtkCorrespondenceRefinement()
{
  this->SetNumberOfInputPorts(2);
  const mobius::RegistrationParameters defaults;
  this->BasisSize = defaults.BasisSize;
  this->StartBasisSize = defaults.StartBasisSize;
  this->ScreeningBasisSize = defaults.ScreeningBasisSize;
  this->GeometricPolish = defaults.GeometricPolish;
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
  if (this->StartBasisSize > this->BasisSize)
  {
    vtkErrorMacro(<< "StartBasisSize (" << this->StartBasisSize
                  << ") must not exceed BasisSize (" << this->BasisSize << ").");
    return 0;
  }
  const char* names[2] = { "Source (port 0)", "Target (port 1)" };
  MapInput maps[2];
  for (int k = 0; k < 2; ++k)
  {
    const std::string error = ExtractMapInput(inputs[k], this->BasisSize, maps[k]);
    if (!error.empty())
    {
      vtkErrorMacro(<< "Cannot refine: the " << names[k] << ": " << error << ".");
      return 0;
    }
  }

  {
    using Clock = std::chrono::steady_clock;
    auto lapStart = Clock::now();
    auto lap = [&lapStart]() {
      const auto now = Clock::now();
      const double seconds = std::chrono::duration<double>(now - lapStart).count();
      lapStart = now;
      return seconds;
    };
    const int threads = mobius::ResolveThreadCount(this->NumberOfThreads);
    // A basis stored on an input (vtkLaplaceBeltramiBasis) is used when it is this
    // surface's, of BasisSize functions; one of another size is ignored, one of another
    // surface refused.
    mobius::SpectralSurface surfaces[2];
    std::string errors[2];
    bool prepared[2] = { false, false };
    bool stored[2] = { false, false };
    mobius::LaplaceBeltramiBasis bases[2];
    for (int k = 0; k < 2; ++k)
    {
      const mobius::vtk::StoredBasis found = mobius::vtk::ReadBasisArrays(inputs[k],
        this->BasisSize, mobius::vtk::SurfaceFingerprint(maps[k].Surface, maps[k].Triangles),
        bases[k], errors[k]);
      if (!errors[k].empty())
      {
        vtkErrorMacro(<< "Cannot refine: the " << names[k] << ": " << errors[k] << ".");
        return 0;
      }
      // A stored basis is built with the lumped mass; a blended mass needs its own basis.
      stored[k] = found == mobius::vtk::StoredBasis::Found && this->ConsistentMassShare == 0.0;
    }
    // After the stored bases were matched: their fingerprints are of the surfaces as stored.
    for (MapInput& map : maps)
    {
      mobius::vtk::CenterSurface(map.Surface);
    }
    // The two surfaces are independent (each eigensolve runs on one core): side by side
    // when there are two threads.
    mobius::ParallelFor(2, threads, [&](int k, int) {
      if (!stored[k])
      {
        prepared[k] = mobius::PrepareSpectralSurface(maps[k].Surface, maps[k].Triangles,
          this->BasisSize, this->NumberOfSamples, surfaces[k], errors[k], this->ConsistentMassShare);
      }
      // The mass is cheap to rebuild, and rebuilt exactly as the eigensolver built it.
      else if (mobius::BuildUnitAreaMassMatrix(
                 maps[k].Surface, maps[k].Triangles, 0.0, bases[k].Mass, errors[k]))
      {
        mobius::PrepareSpectralSurface(maps[k].Surface, maps[k].Triangles, std::move(bases[k]),
          this->NumberOfSamples, surfaces[k]);
        prepared[k] = true;
      }
    });
    for (int k = 0; k < 2; ++k)
    {
      if (!prepared[k])
      {
        vtkErrorMacro(<< "Cannot refine: the " << names[k] << ": " << errors[k] << ".");
        return 0;
      }
    }
    const double basisSeconds = lap();
    this->UpdateProgress(0.5);
    if (this->GetAbortExecute())
    {
      return 0;
    }

    mobius::SphericalPointLocator locator;
    std::string error;
    if (!locator.Build(maps[1].Sphere, maps[1].Triangles, error))
    {
      vtkErrorMacro(<< "Cannot refine: the " << names[1] << ": " << error << ".");
      return 0;
    }
    mobius::ZoomOutParameters parameters;
    parameters.StartSize = this->StartBasisSize;
    parameters.Growth = this->BasisGrowth;
    parameters.FinalSize = mobius::ClampToBasisSize(this->ScreeningBasisSize, this->BasisSize);
    parameters.FullResolutionIterations = this->FullResolutionIterations;
    parameters.NumberOfThreads = threads;

    // Every candidate up to the screening size, each held on its side of the sphere; the
    // one of the expected orientation that keeps the curvature best goes on
    // (mobius::ChooseCandidate).
    const std::vector<Matrix3> starts = CandidateStarts(inputs[0], this->SearchCandidates);
    if (this->Candidate >= static_cast<int>(starts.size()))
    {
      vtkErrorMacro(<< "Candidate " << this->Candidate << " does not exist: the registration has "
                    << starts.size() << " candidate" << (starts.size() == 1 ? "" : "s")
                    << " (0.." << starts.size() - 1 << ").");
      return 0;
    }
    vtkDataArray* determinantArray = inputs[0]->GetFieldData()->GetArray("Determinant");
    const double bestDeterminant =
      determinantArray && determinantArray->GetComponent(0, 0) < 0 ? -1.0 : 1.0;
    const std::vector<mobius::Index>& samples = surfaces[0].Samples;
    std::vector<bool> preserves;
    std::vector<mobius::SampleAnchor> anchors;
    for (const Matrix3& start : starts)
    {
      preserves.push_back(start.determinant() * bestDeterminant > 0);
      anchors.push_back(SphereAnchor(start, maps[0].Sphere, samples, maps[1].Sphere,
        surfaces[1].Samples, this->SphereAnchorWeight));
    }
    // The candidates are independent and each one's sample ZoomOut is too small (1000
    // samples) to keep several threads busy: one candidate per thread.
    std::vector<mobius::SampleMap> screened(starts.size());
    mobius::ZoomOutParameters oneThread = parameters;
    oneThread.NumberOfThreads = 1;
    mobius::ParallelFor(static_cast<int>(starts.size()), threads, [&](int c, int) {
        mobius::ZoomOutParameters own = oneThread;
        own.Orientation = this->RepairOrientation ? (preserves[c] ? 1 : -1) : 0;
        screened[c] = mobius::ZoomOutOnSamples(surfaces[0], surfaces[1],
          StartingSampleMap(starts[c], maps[0].Sphere, samples, locator, maps[1].Triangles),
          own, anchors[c]);
      });
    this->UpdateProgress(0.7);
    if (this->GetAbortExecute())
    {
      return 0;
    }
    std::vector<bool> rightSide;
    for (size_t c = 0; c < starts.size(); ++c)
    {
      rightSide.push_back(mobius::HasOrientation(screened[c], preserves[c]));
    }
    mobius::CandidateChoice choice = mobius::ChooseCandidate(screened, rightSide, surfaces[1],
      this->CandidateCriterion == ORTHOGONALITY ? mobius::CandidateCriterion::Orthogonality
                                                : mobius::CandidateCriterion::Curvature);
    if (this->Candidate >= 0)
    {
      choice.Kept = this->Candidate;
    }
    else if (choice.RunnerUp >= 0 && choice.Margin < mobius::kNearEqualMargin)
    {
      vtkWarningMacro(<< "Candidates " << choice.Kept << " (kept) and " << choice.RunnerUp
                      << " give different maps that keep the surfaces' curvature almost "
                         "equally well (margin "
                      << 100 * choice.Margin
                      << "%): the map may be the wrong one of two, such as a body turned half a "
                         "turn. Check it, and keep the other with Candidate = "
                      << choice.RunnerUp << " (mobius-register --candidate " << choice.RunnerUp
                      << ").");
    }
    const int bestCandidate = choice.Kept;
    mobius::SampleMap best = screened[bestCandidate];
    // A map that still has the wrong orientation (no candidate reached the right one) is
    // retried from its low-frequency functional map with signs flipped.
    const bool preserve = preserves[bestCandidate];
    const bool reversed = !rightSide[bestCandidate];
    if (reversed && this->RepairOrientation)
    {
      best = mobius::RepairOrientation(
        surfaces[0], surfaces[1], best, preserve, 9, parameters, anchors[bestCandidate]);
    }
    if (parameters.FinalSize < this->BasisSize)
    {
      parameters.StartSize = mobius::NextBasisSize(parameters.FinalSize, parameters.Growth);
      parameters.FinalSize = this->BasisSize;
      parameters.Orientation = this->RepairOrientation ? (preserve ? 1 : -1) : 0;
      best = mobius::ZoomOutOnSamples(
        surfaces[0], surfaces[1], best.TargetVertex, parameters, anchors[bestCandidate]);
    }
    const double candidateSeconds = lap();
    this->UpdateProgress(0.85);

    const mobius::DenseMap dense =
      mobius::ExtendToAllVertices(surfaces[0], surfaces[1], best, parameters);
    const double extensionSeconds = lap();
    mobius::vtk::SurfaceLocations locations;
    locations.LocatedTriangles = &maps[1].Triangles;
    locations.Triangle = dense.Triangle;
    locations.Barycentric = dense.Barycentric;
    double polishSeconds = 0.0;
    if (this->GeometricPolish)
    {
      // On the scaled surfaces the spectral bases were computed on: the polish scales the
      // source to the target's area itself, and the map is triangles and barycentrics.
      mobius::SurfacePolishParameters polish;
      polish.NumberOfThreads = threads;
      // A mirror image (an orientation-reversing map: a reflection's, or a symmetry's) is
      // polished as a rotation of the mirrored source.
      polish.ReverseOrientation = best.OrientationAgreement < 0.5;
      mobius::SurfacePolishInfo polishInfo;
      if (!mobius::PolishSurfaceMap(surfaces[0].Positions, surfaces[0].Faces,
            surfaces[1].Positions, surfaces[1].Faces, surfaces[1].Corners, locations.Triangle,
            locations.Barycentric, polish, polishInfo))
      {
        vtkWarningMacro(<< "The geometric polish failed (" << polishInfo.Error
                        << "); the spectral map is kept.");
      }
      polishSeconds = lap();
    }
    const std::string arrayWarning = mobius::vtk::AssembleCorrespondence(
      inputs[0], inputs[1], locations, this->OutputGeometry == TARGET, output);
    if (!arrayWarning.empty())
    {
      vtkWarningMacro(<< "Target: " << arrayWarning << ".");
    }
    mobius::vtk::RemoveBasisArrays(output);

    vtkFieldData* fieldData = output->GetFieldData();
    mobius::vtk::SetFieldInteger(fieldData, "RefinementCandidate", bestCandidate);
    std::vector<double> residuals, coverage, orientation, curvature;
    for (const mobius::SampleMap& map : screened)
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
    const double confidence[3] = { OrMinusOne(screened[bestCandidate].CurvatureDifference),
      static_cast<double>(choice.RunnerUp), OrMinusOne(choice.Margin) };
    mobius::vtk::SetFieldValues(fieldData, "RefinementConfidence", confidence, 3);
    AddMapStretch(maps[0], output);
    mobius::vtk::SetFieldValue(fieldData, "RefinementOrientationAgreement", best.OrientationAgreement);
    mobius::vtk::SetFieldInteger(fieldData, "RefinementOrientationRepaired", reversed ? 1 : 0);
    mobius::vtk::SetFieldValue(
      fieldData, "RefinementOrthogonalityResidual", dense.OrthogonalityResidual);
    mobius::vtk::SetFieldInteger(
      fieldData, "RefinementBasisSize", static_cast<int>(dense.FunctionalMap.cols()));
    if (this->RecordTimings)
    {
      const double seconds[4] = { basisSeconds, candidateSeconds, extensionSeconds, polishSeconds };
      mobius::vtk::SetFieldValues(fieldData, "RefinementStageSeconds", seconds, 4);
    }
    const double storedBases[2] = { stored[0] ? 1.0 : 0.0, stored[1] ? 1.0 : 0.0 };
    mobius::vtk::SetFieldValues(fieldData, "RefinementStoredBasisUsed", storedBases, 2);
    mobius::vtk::SetFieldInteger(fieldData, "NumberOfThreadsUsed", threads);
  }
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
  os << indent << "SphereAnchorWeight: " << this->SphereAnchorWeight << "\n";
  os << indent << "CandidateCriterion: " << this->CandidateCriterion << "\n";
  os << indent << "Candidate: " << this->Candidate << "\n";
  os << indent << "OutputGeometry: " << this->OutputGeometry << "\n";
}
