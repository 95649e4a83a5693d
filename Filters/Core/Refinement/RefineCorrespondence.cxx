#include "RefineCorrespondence.h"

#include "EdgeStretch.h"
#include "InverseAveraging.h"
#include "LandmarkConsistency.h"
#include "LandmarkAlignment.h"
#include "ParallelFor.h"
#include "SurfacePolish.h"

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <chrono>
#include <limits>
#include <sstream>

namespace mobius
{
namespace
{
// The Möbius map of the source samples under one candidate: each sample rotated by `start`
// and located on the target sphere, sent to the nearest corner of its triangle.
std::vector<Index> StartingSampleMap(const RotationMatrix& start,
  const std::vector<Index>& samples, const RegisteredSpheres& spheres)
{
  std::vector<Index> targetVertex(samples.size());
  for (size_t s = 0; s < samples.size(); ++s)
  {
    const Eigen::Vector3d p = start * spheres.Source.row(samples[s]).transpose();
    const SphericalLocation location = spheres.TargetLocator.Locate(p);
    Eigen::Index corner = 0;
    location.Barycentric.maxCoeff(&corner);
    targetVertex[s] = spheres.TargetTriangles(location.Triangle, corner);
  }
  return targetVertex;
}

// The sphere points of both surfaces' samples, the source's turned by `start`: what keeps a
// candidate's ZoomOut on the side its rotation put it (SampleAnchor).
SampleAnchor SphereAnchor(const RotationMatrix& start, const std::vector<Index>& sourceSamples,
  const std::vector<Index>& targetSamples, const RegisteredSpheres& spheres, double weight)
{
  SampleAnchor anchor;
  anchor.Weight = weight;
  anchor.Source.resize(static_cast<Eigen::Index>(sourceSamples.size()), 3);
  for (size_t s = 0; s < sourceSamples.size(); ++s)
  {
    anchor.Source.row(static_cast<Eigen::Index>(s)) =
      (start * spheres.Source.row(sourceSamples[s]).transpose()).transpose();
  }
  anchor.Target.resize(static_cast<Eigen::Index>(targetSamples.size()), 3);
  for (size_t t = 0; t < targetSamples.size(); ++t)
  {
    anchor.Target.row(static_cast<Eigen::Index>(t)) = spheres.Target.row(targetSamples[t]);
  }
  return anchor;
}

// The orientation ZoomOut should hold a map to: +1 preserved, -1 reversed, 0 either.
int ExpectedOrientation(const CorrespondenceRefinementOptions& options, bool preserve)
{
  return options.RepairOrientation ? (preserve ? 1 : -1) : 0;
}

class Stopwatch
{
public:
  /// Seconds since the last lap (or the construction).
  double Lap()
  {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - this->Start).count();
    this->Start = now;
    return seconds;
  }

private:
  std::chrono::steady_clock::time_point Start = std::chrono::steady_clock::now();
};
// Per candidate, the orientation its map should have and the anchor that holds it on its
// side of the sphere.
struct Candidates
{
  std::vector<bool> Preserve;
  std::vector<SampleAnchor> Anchors;
  /// false: the start leaves the landmarks far apart (kLandmarkAngleMargin), not kept.
  std::vector<bool> NearLandmarks;
};

// The landmarks as pins of the source's samples: (position in Samples, target vertex).
std::vector<std::pair<Index, Index>> SamplePins(
  const SpectralSurface& source, const RegisteredSpheres& spheres)
{
  std::vector<std::pair<Index, Index>> pins;
  for (const auto& landmark : spheres.Landmarks)
  {
    const auto found = std::find(source.Samples.begin(), source.Samples.end(), landmark.first);
    if (found != source.Samples.end())
    {
      pins.emplace_back(static_cast<Index>(found - source.Samples.begin()), landmark.second);
    }
  }
  return pins;
}

// Per start, whether it brings the landmarks' sphere points about as close together as the
// best start does (all of them without landmarks).
std::vector<bool> StartsNearLandmarks(const RegisteredSpheres& spheres)
{
  SphereLandmarks landmarks;
  landmarks.Source.resize(static_cast<Eigen::Index>(spheres.Landmarks.size()), 3);
  landmarks.Target.resize(landmarks.Source.rows(), 3);
  for (size_t k = 0; k < spheres.Landmarks.size(); ++k)
  {
    landmarks.Source.row(static_cast<Eigen::Index>(k)) = spheres.Source.row(spheres.Landmarks[k].first);
    landmarks.Target.row(static_cast<Eigen::Index>(k)) = spheres.Target.row(spheres.Landmarks[k].second);
  }
  std::vector<double> angles;
  for (const RotationMatrix& start : spheres.Starts)
  {
    angles.push_back(LandmarkAngle(start, landmarks));
  }
  const double best = *std::min_element(angles.begin(), angles.end());
  std::vector<bool> near;
  for (double angle : angles)
  {
    near.push_back(angle <= best + kLandmarkAngleMargin);
  }
  return near;
}

Candidates SetUpCandidates(const SpectralSurface& source, const SpectralSurface& target,
  const RegisteredSpheres& spheres, const CorrespondenceRefinementOptions& options)
{
  Candidates candidates;
  const double bestDeterminant = spheres.BestReflects ? -1.0 : 1.0;
  const std::vector<std::pair<Index, Index>> pins = SamplePins(source, spheres);
  for (const RotationMatrix& start : spheres.Starts)
  {
    candidates.Preserve.push_back(start.determinant() * bestDeterminant > 0);
    candidates.Anchors.push_back(
      SphereAnchor(start, source.Samples, target.Samples, spheres, options.SphereAnchorWeight));
    candidates.Anchors.back().Pins = pins;
  }
  candidates.NearLandmarks = StartsNearLandmarks(spheres);
  return candidates;
}

// Every candidate's map up to the screening size, each held on its side of the sphere. The
// candidates are independent and each one's sample ZoomOut is too small (1000 samples) to
// keep several threads busy: one candidate per thread.
std::vector<SampleMap> ScreenCandidates(const SpectralSurface& source,
  const SpectralSurface& target, const RegisteredSpheres& spheres,
  const Candidates& candidates, const CorrespondenceRefinementOptions& options)
{
  std::vector<SampleMap> screened(spheres.Starts.size());
  ZoomOutParameters oneThread = options.ZoomOut;
  oneThread.NumberOfThreads = 1;
  ParallelFor(static_cast<int>(screened.size()), options.ZoomOut.NumberOfThreads, [&](int c, int) {
    ZoomOutParameters own = oneThread;
    own.Orientation = ExpectedOrientation(options, candidates.Preserve[c]);
    screened[c] = ZoomOutOnSamples(source, target,
      StartingSampleMap(spheres.Starts[c], source.Samples, spheres), own, candidates.Anchors[c]);
  });
  return screened;
}

// A candidate's screened map, its orientation repaired if it is wrong, grown to the full
// basis; `parameters` ends as the growth's, which the extension goes on with.
SampleMap FinishSampleMap(const SpectralSurface& source, const SpectralSurface& target,
  const SampleMap& screened, bool wrongOrientation, bool preserve, const SampleAnchor& anchor,
  const CorrespondenceRefinementOptions& options, ZoomOutParameters& parameters)
{
  SampleMap kept = screened;
  // A map that still has the wrong orientation (no candidate reached the right one) is
  // retried from its low-frequency functional map with signs flipped.
  if (wrongOrientation && options.RepairOrientation)
  {
    kept = RepairOrientation(source, target, kept, preserve, 9, parameters, anchor);
  }
  if (parameters.FinalSize < options.BasisSize)
  {
    parameters.StartSize = NextBasisSize(parameters.FinalSize, parameters.Growth);
    parameters.FinalSize = options.BasisSize;
    parameters.Orientation = ExpectedOrientation(options, preserve);
    kept = ZoomOutOnSamples(source, target, kept.TargetVertex, parameters, anchor);
  }
  return kept;
}

// The polish's parameters for a map from `source` to `target` whose kept sample map is
// `kept`.
SurfacePolishParameters PolishParametersFor(const SpectralSurface& source,
  const SpectralSurface& target, const SampleMap& kept, int numberOfThreads,
  const std::vector<std::pair<Index, Index>>& pinned)
{
  SurfacePolishParameters polish;
  polish.NumberOfThreads = numberOfThreads;
  // A mirror image (an orientation-reversing map: a reflection's, or a symmetry's) is
  // polished as a rotation of the mirrored source.
  polish.ReverseOrientation = kept.OrientationAgreement < 0.5;
  polish.Pinned = pinned;
  polish.SourceCurvatures = source.PolishCurvatures;
  polish.TargetCurvatures = target.PolishCurvatures;
  return polish;
}

// The dense map moved on the surfaces (SurfacePolish); the error if the polish failed.
std::string PolishDenseMap(const SpectralSurface& source, const SpectralSurface& target,
  const SampleMap& kept, int numberOfThreads, const std::vector<std::pair<Index, Index>>& pinned,
  DenseMap& dense)
{
  // On the scaled surfaces the spectral bases were computed on: the polish scales the
  // source to the target's area itself, and the map is triangles and barycentrics.
  SurfacePolishInfo info;
  const bool polished = PolishSurfaceMap(source.Positions, source.Faces, target.Positions,
    target.Faces, target.Corners, dense.Triangle, dense.Barycentric,
    PolishParametersFor(source, target, kept, numberOfThreads, pinned), info);
  return polished ? std::string() : info.Error;
}

// One direction's dense map: the sample map extended to every vertex and, on request,
// polished; the extension's seconds.
struct DirectionMap
{
  DenseMap Dense;
  std::string PolishError;
  double ExtensionSeconds = 0;
};

DirectionMap ExtendAndPolish(const SpectralSurface& source, const SpectralSurface& target,
  const SampleMap& samples, ZoomOutParameters parameters,
  const std::vector<std::pair<Index, Index>>& pinned, bool polish, int numberOfThreads)
{
  Stopwatch stopwatch;
  parameters.NumberOfThreads = numberOfThreads;
  DirectionMap map;
  map.Dense = ExtendToAllVertices(source, target, samples, parameters, pinned);
  map.ExtensionSeconds = stopwatch.Lap();
  if (polish)
  {
    map.PolishError = PolishDenseMap(source, target, samples, numberOfThreads, pinned, map.Dense);
  }
  return map;
}

// The kept sample map the other way, target samples onto source vertices, read off its
// functional map transposed (the inverse of a near-orthogonal map); of the same orientation.
SampleMap ReverseSampleMap(const SpectralSurface& source, const SpectralSurface& target,
  const SampleMap& kept, int numberOfThreads)
{
  SampleMap reverse;
  reverse.FunctionalMap = kept.FunctionalMap.transpose();
  reverse.TargetVertex =
    SampleMapFromFunctionalMap(target, source, reverse.FunctionalMap, numberOfThreads);
  reverse.OrientationAgreement = kept.OrientationAgreement;
  return reverse;
}

std::vector<std::pair<Index, Index>> Swapped(const std::vector<std::pair<Index, Index>>& pairs)
{
  std::vector<std::pair<Index, Index>> swapped;
  for (const auto& pair : pairs)
  {
    swapped.emplace_back(pair.second, pair.first);
  }
  return swapped;
}

// `map` (source onto target) moved towards the inverse of `other` (target onto source).
DenseMap TowardsInverse(const SpectralSurface& source, const SpectralSurface& target,
  const DenseMap& map, const DenseMap& other,
  const std::vector<std::pair<Index, Index>>& landmarks, int threads)
{
  DenseMap averaged = map;
  AverageWithInverse(source.Positions, source.Faces, target.Positions, target.Faces,
    target.Corners, other.Triangle, other.Barycentric, kInverseWeight, landmarks, threads,
    averaged.Triangle, averaged.Barycentric);
  return averaged;
}

// Both directions' maps polished at once, each on its own thread. Every kMeetingInterval
// iterations (if `meet`) they meet: each moves towards the other's inverse and the polishes
// go on from there, their momentum kept. A direction whose polish fails keeps its error,
// the other goes on alone.
void PolishBoth(const SpectralSurface& source, const SpectralSurface& target,
  const SampleMap& forwardSamples, const SampleMap& reverseSamples,
  const std::vector<std::pair<Index, Index>>& landmarks, int threads, bool meet,
  DirectionMap& forward, DirectionMap& reverse)
{
  const int each = std::max(1, threads / 2);
  const std::array<std::vector<std::pair<Index, Index>>, 2> pinned{ landmarks,
    Swapped(landmarks) };
  const std::array<const SpectralSurface*, 2> from{ &source, &target }, onto{ &target, &source };
  const std::array<DirectionMap*, 2> maps{ &forward, &reverse };
  const std::array<SurfacePolishParameters, 2> parameters{
    PolishParametersFor(source, target, forwardSamples, each, pinned[0]),
    PolishParametersFor(target, source, reverseSamples, each, pinned[1]) };
  std::array<SurfacePolisher, 2> polishers;
  std::array<bool, 2> ok{ false, false };
  ParallelFor(2, threads, [&](int d, int) {
    ok[d] = polishers[d].Start(from[d]->Positions, from[d]->Faces, onto[d]->Positions,
      onto[d]->Faces, onto[d]->Corners, maps[d]->Dense.Triangle, maps[d]->Dense.Barycentric,
      parameters[d]);
  });
  const int iterations = parameters[0].Iterations;
  for (int done = kMeetingInterval; meet && ok[0] && ok[1] && done < iterations;
       done += kMeetingInterval)
  {
    ParallelFor(2, threads, [&](int d, int) {
      ok[d] = polishers[d].Iterate(kMeetingInterval);
      polishers[d].CurrentMap(maps[d]->Dense.Triangle, maps[d]->Dense.Barycentric);
    });
    ParallelFor(2, threads, [&](int d, int) {
      const DenseMap towards = TowardsInverse(
        *from[d], *onto[d], maps[d]->Dense, maps[1 - d]->Dense, pinned[d], each);
      polishers[d].MoveTo(towards.Triangle, towards.Barycentric);
    });
  }
  ParallelFor(2, threads, [&](int d, int) {
    if (ok[d] && polishers[d].Iterate(iterations))
    {
      polishers[d].CurrentMap(maps[d]->Dense.Triangle, maps[d]->Dense.Barycentric);
    }
    maps[d]->PolishError = polishers[d].Info().Error;
  });
}

// One candidate's map finished: its sample map (orientation repaired, grown to the full
// basis) and its dense map (extended and polished as the options ask), with the seconds
// each took.
struct FinishedMap
{
  SampleMap Samples;
  bool WrongOrientation = false;
  DenseMap Dense;
  std::string PolishError;
  double SampleSeconds = 0, ExtensionSeconds = 0, PolishSeconds = 0;
};

// The finished sample map extended to every vertex and polished as the options ask. In
// both directions, each is extended on its own thread, both are polished at once, meeting
// between iterations (PolishBoth; on surfaces of up to kMeetingMaximumVertices), and the
// forward map is averaged with the inverse of the other (InverseAveraging).
void FinishDenseMap(const SpectralSurface& source, const SpectralSurface& target,
  const std::vector<std::pair<Index, Index>>& landmarks, const ZoomOutParameters& parameters,
  const CorrespondenceRefinementOptions& options, FinishedMap& finished)
{
  const int threads = ResolveThreadCount(options.ZoomOut.NumberOfThreads);
  if (!options.GeometricPolish || !options.BothDirections)
  {
    DirectionMap forward = ExtendAndPolish(
      source, target, finished.Samples, parameters, landmarks, options.GeometricPolish, threads);
    finished.Dense = std::move(forward.Dense);
    finished.PolishError = forward.PolishError;
    finished.ExtensionSeconds = forward.ExtensionSeconds;
    return;
  }
  const SampleMap reverseSamples = ReverseSampleMap(source, target, finished.Samples, threads);
  const int each = std::max(1, threads / 2);
  DirectionMap forward, reverse;
  ParallelFor(2, threads, [&](int direction, int) {
    if (direction == 0)
    {
      forward =
        ExtendAndPolish(source, target, finished.Samples, parameters, landmarks, false, each);
    }
    else
    {
      reverse = ExtendAndPolish(
        target, source, reverseSamples, parameters, Swapped(landmarks), false, each);
    }
  });
  finished.ExtensionSeconds = std::max(forward.ExtensionSeconds, reverse.ExtensionSeconds);
  const bool meet =
    std::max(source.Positions.rows(), target.Positions.rows()) <= kMeetingMaximumVertices;
  PolishBoth(source, target, finished.Samples, reverseSamples, landmarks, threads, meet,
    forward, reverse);
  finished.PolishError = forward.PolishError;
  finished.Dense = forward.PolishError.empty() && reverse.PolishError.empty()
    ? TowardsInverse(source, target, forward.Dense, reverse.Dense, landmarks, threads)
    : std::move(forward.Dense);
}

// Candidate `c`'s screened map finished (FinishSampleMap, FinishDenseMap).
FinishedMap FinishCandidate(const SpectralSurface& source, const SpectralSurface& target,
  const RegisteredSpheres& spheres, const Candidates& candidates,
  const std::vector<SampleMap>& screened, bool oriented, int c,
  const CorrespondenceRefinementOptions& options)
{
  Stopwatch stopwatch;
  FinishedMap finished;
  finished.WrongOrientation = !oriented;
  ZoomOutParameters parameters = options.ZoomOut;
  finished.Samples = FinishSampleMap(source, target, screened[c], finished.WrongOrientation,
    candidates.Preserve[c], candidates.Anchors[c], options, parameters);
  finished.SampleSeconds = stopwatch.Lap();
  FinishDenseMap(source, target, spheres.Landmarks, parameters, options, finished);
  if (options.GeometricPolish)
  {
    finished.PolishSeconds = stopwatch.Lap() - finished.ExtensionSeconds;
  }
  return finished;
}

// The mean edge stretch of a dense map (MeanEdgeStretch of the source and its mapped points).
double DenseMapStretch(
  const SpectralSurface& source, const SpectralSurface& target, const DenseMap& dense)
{
  Points mapped(source.Positions.rows(), 3);
  for (Index i = 0; i < mapped.rows(); ++i)
  {
    const size_t v = static_cast<size_t>(i);
    mapped.row(i).setZero();
    for (int k = 0; k < 3; ++k)
    {
      mapped.row(i) +=
        dense.Barycentric[v][k] * target.Positions.row(target.Faces(dense.Triangle[v], k));
    }
  }
  return MeanEdgeStretch(source.Positions, source.Faces, mapped);
}

// Per candidate, whether it keeps the landmarks: its start brings them near their targets
// (NearLandmarks) and its screened map keeps the distances to them about as well as the
// best such map of the expected orientation does (LandmarkConsistency.h). Records each
// screened map's LandmarkDistanceDifference. All true without landmarks.
std::vector<bool> KeepingLandmarks(const SpectralSurface& source, const SpectralSurface& target,
  const RegisteredSpheres& spheres, const Candidates& candidates,
  const std::vector<bool>& oriented, RefinedCorrespondence& refined)
{
  refined.LandmarkDistanceDifferences =
    LandmarkDistanceDifferences(source, target, refined.Screened, spheres.Landmarks);
  std::vector<bool> eligible;
  for (size_t c = 0; c < refined.Screened.size(); ++c)
  {
    eligible.push_back(oriented[c] && candidates.NearLandmarks[c]);
  }
  if (std::find(eligible.begin(), eligible.end(), true) == eligible.end())
  {
    eligible = candidates.NearLandmarks;
  }
  const std::vector<bool> keeps =
    KeepsLandmarkDistances(refined.LandmarkDistanceDifferences, eligible);
  std::vector<bool> keeping;
  for (size_t c = 0; c < refined.Screened.size(); ++c)
  {
    keeping.push_back(candidates.NearLandmarks[c] && keeps[c]);
  }
  return keeping;
}

// Whether the runner-up's map is finished too and the two compared with their stretch: the
// refinement chooses, the polish is on (an unpolished map's stretch does not tell them
// apart), and the runner-up came within kFinishRunnerUpMargin.
bool FinishRunnerUp(const CandidateChoice& choice, const CorrespondenceRefinementOptions& options)
{
  return options.Candidate < 0 && options.GeometricPolish && choice.RunnerUp >= 0 &&
    choice.Margin < kFinishRunnerUpMargin;
}
}

RefinedCorrespondence RefineCorrespondence(const SpectralSurface& source,
  const SpectralSurface& target, const RegisteredSpheres& spheres,
  const CorrespondenceRefinementOptions& options)
{
  Stopwatch stopwatch;
  RefinedCorrespondence refined;
  const Candidates candidates = SetUpCandidates(source, target, spheres, options);
  refined.Screened = ScreenCandidates(source, target, spheres, candidates, options);
  if (options.Progress && !options.Progress(0.7))
  {
    refined.Stopped = true;
    return refined;
  }
  // The one of the expected orientation that keeps the landmarks (its start near them, its
  // map keeping the distances to them) and the curvature best goes on.
  std::vector<bool> oriented;
  for (size_t c = 0; c < refined.Screened.size(); ++c)
  {
    oriented.push_back(HasOrientation(refined.Screened[c], candidates.Preserve[c]));
  }
  const std::vector<bool> withLandmarks =
    KeepingLandmarks(source, target, spheres, candidates, oriented, refined);
  std::vector<bool> rightSide;
  for (size_t c = 0; c < refined.Screened.size(); ++c)
  {
    rightSide.push_back(oriented[c] && withLandmarks[c]);
  }
  if (std::find(rightSide.begin(), rightSide.end(), true) == rightSide.end())
  {
    rightSide = withLandmarks; // none of both: keeping the landmarks, repaired below
  }
  refined.Choice = ChooseCandidate(refined.Screened, rightSide, target, options.Criterion);
  if (options.Candidate >= 0)
  {
    refined.Choice.Kept = options.Candidate;
  }
  double candidateSeconds = stopwatch.Lap();
  if (options.Progress)
  {
    options.Progress(0.85); // the finishing is not stopped
  }
  FinishedMap kept = FinishCandidate(source, target, spheres, candidates, refined.Screened,
    oriented[refined.Choice.Kept], refined.Choice.Kept, options);
  refined.Choice.Stretch.assign(refined.Screened.size(), std::numeric_limits<double>::quiet_NaN());
  refined.Choice.Stretch[refined.Choice.Kept] = DenseMapStretch(source, target, kept.Dense);
  if (FinishRunnerUp(refined.Choice, options) && kept.PolishError.empty())
  {
    FinishedMap other = FinishCandidate(source, target, spheres, candidates, refined.Screened,
      oriented[refined.Choice.RunnerUp], refined.Choice.RunnerUp, options);
    if (other.PolishError.empty())
    {
      const int before = refined.Choice.Kept;
      ChooseByFinishedMaps(refined.Choice, refined.Screened.size(),
        refined.Choice.Stretch[refined.Choice.Kept], DenseMapStretch(source, target, other.Dense));
      if (refined.Choice.Kept != before)
      {
        std::swap(kept, other);
      }
    }
    // The map not kept was part of the choice.
    candidateSeconds += other.SampleSeconds + other.ExtensionSeconds + other.PolishSeconds;
  }
  refined.Kept = std::move(kept.Samples);
  refined.WrongOrientation = kept.WrongOrientation;
  refined.Dense = std::move(kept.Dense);
  refined.PolishError = kept.PolishError;
  refined.CandidateSeconds = candidateSeconds + kept.SampleSeconds;
  refined.ExtensionSeconds = kept.ExtensionSeconds;
  refined.PolishSeconds = kept.PolishSeconds;
  return refined;
}

std::string CheckBasisSizes(int startBasisSize, int basisSize)
{
  if (startBasisSize <= basisSize)
  {
    return std::string();
  }
  std::ostringstream message;
  message << "StartBasisSize (" << startBasisSize << ") must not exceed BasisSize (" << basisSize
          << ").";
  return message.str();
}

std::vector<RotationMatrix> CandidateStarts(
  const RotationMatrix& best, const std::vector<RotationMatrix>& candidates)
{
  std::vector<RotationMatrix> starts{ RotationMatrix::Identity() };
  for (const RotationMatrix& transform : candidates)
  {
    if (!transform.allFinite() || (transform - best).norm() < 1e-9)
    {
      continue; // the best one is already first
    }
    starts.emplace_back(transform * best.transpose());
  }
  return starts;
}

std::string CheckCandidate(int candidate, size_t count)
{
  if (candidate < static_cast<int>(count))
  {
    return std::string();
  }
  std::ostringstream message;
  message << "Candidate " << candidate << " does not exist: the registration has " << count
          << " candidate" << (count == 1 ? "" : "s") << " (0.." << count - 1 << ").";
  return message.str();
}
}
