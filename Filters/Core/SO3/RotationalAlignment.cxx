#include "RotationalAlignment.h"

#include "LandmarkAlignment.h"
#include "RegistrationParameters.h"
#include "StopWatchingProgress.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <unistd.h>

namespace mobius
{
namespace
{
// The grid size's problem, if it has one: odd, too coarse, or more than the machine's
// memory; a warning when it is coarse enough to turn the map.
std::string CheckResolution(int resolution, std::vector<std::string>& warnings)
{
  const std::string tooCoarse = CheckGridResolution(resolution, MinimumResolution);
  if (!tooCoarse.empty())
  {
    return tooCoarse + ": a coarser grid cannot tell the rotation.";
  }
  if (resolution < ReliableResolution)
  {
    std::ostringstream warning;
    warning << "Resolution " << resolution << " resolves the rotation only to about "
            << 360 / resolution << " degrees: the map may come back turned; "
            << ReliableResolution << " or more is reliable.";
    warnings.push_back(warning.str());
  }
  const double memory = PhysicalMemoryBytes();
  std::ostringstream message;
  if (memory > 0 && AlignmentMemoryEstimate(resolution) > memory)
  {
    message << "Resolution " << resolution << " needs about "
            << AlignmentMemoryEstimate(resolution) / 1e9 << " GB, more than this machine's "
            << memory / 1e9 << " GB; Resolution " << LargestAlignmentResolution(memory)
            << " would fit.";
  }
  return message.str();
}

// Both maps' scale-factor signals (progress: the first half of the alignment); false if one
// cannot be computed (the message names its map) or the computation was stopped.
bool ComputeSignals(const AlignmentMap* maps[2], const ScaleFactorSignalParameters& parameters,
  StopWatchingProgress& report, ScaleFactorSignal signals[2], RotationalAlignment& alignment)
{
  for (int k = 0; k < 2; ++k)
  {
    std::string error = maps[k]->Problem;
    auto progress = [&report, k](double fraction) { return report(0.25 * (k + fraction)); };
    if (error.empty() &&
      !ComputeScaleFactorSignal(maps[k]->Sphere, maps[k]->Triangles, maps[k]->Areas, parameters,
        false, signals[k], error, progress) &&
      report.StopAsked)
    {
      alignment.Stopped = true;
      return false;
    }
    if (!error.empty())
    {
      alignment.Error = "Cannot register: the " + maps[k]->Name + ": " + error + ".";
      return false;
    }
  }
  return true;
}

// The landmarks' points on the two spheres; the message if one names no point of its map or,
// for the Möbius fit, there are too few.
std::string GatherLandmarks(const std::vector<std::pair<Index, Index>>& ids,
  const AlignmentMap& source, const AlignmentMap& target, bool fitMobius,
  SphereLandmarks& landmarks)
{
  const Index counts[2] = { source.Sphere.rows(), target.Sphere.rows() };
  const std::string names[2] = { source.Name, target.Name };
  const std::string error = CheckLandmarkIds(ids, counts, names);
  if (!error.empty())
  {
    return "Cannot register: " + error + ".";
  }
  landmarks.Source.resize(static_cast<Eigen::Index>(ids.size()), 3);
  landmarks.Target.resize(static_cast<Eigen::Index>(ids.size()), 3);
  for (size_t k = 0; k < ids.size(); ++k)
  {
    landmarks.Source.row(static_cast<Eigen::Index>(k)) = source.Sphere.row(ids[k].first);
    landmarks.Target.row(static_cast<Eigen::Index>(k)) = target.Sphere.row(ids[k].second);
  }
  if (fitMobius && landmarks.Source.rows() < FittedLandmarkCount)
  {
    std::ostringstream message;
    message << "Cannot register: LandmarkMode 1 fits a Moebius transformation to "
            << FittedLandmarkCount << " landmarks, and there are " << landmarks.Source.rows()
            << ".";
    return message.str();
  }
  return std::string();
}

// The Möbius transformation that sends the first landmarks onto their targets takes the
// rotation's place: of the rotation only its kind (a reflection or not) is kept, and the one
// candidate is that kind's. False if no Möbius transformation does it.
bool FitLandmarkMobius(const SphereLandmarks& landmarks, const ScaleFactorSignal signals[2],
  SO3ReflectionMode mode, int threads, RotationalAlignment& alignment)
{
  const bool reflect = mode == SO3ReflectionMode::ReflectionsOnly ||
    (mode == SO3ReflectionMode::Both && LandmarksReverseOrientation(landmarks));
  if (!MoveByLandmarkMobius(landmarks, reflect, alignment.AlignedSource))
  {
    return false;
  }
  const Eigen::Matrix3d kind = Eigen::Vector3d(1.0, reflect ? -1.0 : 1.0, 1.0).asDiagonal();
  alignment.Correlation.Candidates = { ScoreTransform(
    signals[0].Coefficients, signals[1].Coefficients, kind, threads) };
  TakeFirstCandidate(alignment.Correlation);
  return true;
}

// Puts first the candidate that brings the landmarks closest together, and keeps it.
void ChooseByLandmarks(const SphereLandmarks& landmarks, const ScaleFactorSignal signals[2],
  const SO3CorrelationOptions& options, RotationalAlignment& alignment)
{
  alignment.LandmarkAngles = OrderCandidatesByLandmarks(alignment.Correlation.Candidates,
    landmarks, options.Reflections, [&](const Eigen::Matrix3d& transform) {
      return ScoreTransform(signals[0].Coefficients, signals[1].Coefficients, transform,
        options.NumberOfThreads);
    });
  TakeFirstCandidate(alignment.Correlation);
}

// The warning when the other kind of transform aligns the shapes far better.
std::string MirrorWarning(const MirrorCheck& mirroring, SO3ReflectionMode mode)
{
  if (!mirroring.OtherFitsFarBetter)
  {
    return std::string();
  }
  std::ostringstream warning;
  warning << (mode == SO3ReflectionMode::RotationsOnly
                 ? "The shapes look mirrored: a reflection aligns them far better ("
                 : "The shapes look the same way round: a rotation aligns them far better (")
          << "registration error " << std::max(0.0, mirroring.OtherError) << " against "
          << mirroring.ChosenError
          << " in a coarse search); set TransformMode to ROTATIONS_AND_REFLECTIONS to "
             "search both kinds.";
  return warning.str();
}

// The correlation over SO(3) (`options` report progress from 0.5 to 0.95 of the
// alignment); false if it was stopped or found no peak (then with the message).
bool Correlate(const ScaleFactorSignal signals[2], const SO3CorrelationOptions& options,
  StopWatchingProgress& report, RotationalAlignment& alignment)
{
  alignment.Correlation =
    CorrelateOverRotations(signals[0].Coefficients, signals[1].Coefficients, options);
  if (alignment.Correlation.Aborted || report.StopAsked)
  {
    alignment.Stopped = true;
    return false;
  }
  report(0.95);
  if (alignment.Correlation.Candidates.empty() || !alignment.Correlation.Transform.allFinite())
  {
    alignment.Error = "Cannot register: the correlation found no peak (are both signals zero?).";
    return false;
  }
  return true;
}

// The landmarks' part: their Möbius fit, or the choice among the candidates; false with the
// message if no Möbius transformation fits them.
bool ApplyLandmarks(const SphereLandmarks& landmarks, const ScaleFactorSignal signals[2],
  bool fitMobius, const SO3CorrelationOptions& options, RotationalAlignment& alignment)
{
  if (fitMobius &&
    !FitLandmarkMobius(landmarks, signals, options.Reflections, options.NumberOfThreads, alignment))
  {
    std::ostringstream message;
    message << "Cannot register: two of the first " << FittedLandmarkCount
            << " landmarks are at the same point of a sphere: no Moebius transformation "
               "sends them onto their targets.";
    alignment.Error = message.str();
    return false;
  }
  if (!fitMobius && landmarks.Source.rows() > 0)
  {
    ChooseByLandmarks(landmarks, signals, options, alignment);
  }
  return true;
}

// The other kind of transform's coarse fit, and the warning when it is far better.
void CheckForMirroring(const ScaleFactorSignal signals[2], const SO3CorrelationOptions& options,
  RotationalAlignment& alignment)
{
  alignment.Mirroring = CheckMirroring(signals[0].Coefficients, signals[1].Coefficients, options);
  const std::string warning = MirrorWarning(alignment.Mirroring, options.Reflections);
  if (!warning.empty())
  {
    alignment.Warnings.push_back(warning);
  }
}

void TransformPoints(const Eigen::Matrix3d& transform, Points& points)
{
  for (Eigen::Index i = 0; i < points.rows(); ++i)
  {
    points.row(i) = (transform * points.row(i).transpose()).transpose();
  }
}
}

double AlignmentMemoryEstimate(int resolution)
{
  const double n = resolution;
  return 160.0 * n * n + 50e6;
}

int LargestAlignmentResolution(double bytes)
{
  if (bytes <= 0)
  {
    bytes = PhysicalMemoryBytes();
  }
  if (bytes <= 50e6)
  {
    return 4;
  }
  const double n = std::sqrt((bytes - 50e6) / 160.0);
  const int even = 2 * static_cast<int>(std::min(n, 1e9) / 2);
  return std::max(4, even);
}

double PhysicalMemoryBytes()
{
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? static_cast<double>(pages) * static_cast<double>(pageSize) : 0;
}

RotationalAlignment AlignSphericalMaps(AlignmentMap source, const AlignmentMap& target,
  const std::vector<std::pair<Index, Index>>& landmarks,
  const RotationalAlignmentParameters& parameters)
{
  RotationalAlignment alignment;
  alignment.Error = CheckResolution(parameters.Signal.Resolution, alignment.Warnings);
  StopWatchingProgress report{ parameters.Progress };
  ScaleFactorSignal signals[2];
  const AlignmentMap* maps[2] = { &source, &target };
  if (!alignment.Error.empty() ||
    !ComputeSignals(maps, parameters.Signal, report, signals, alignment))
  {
    return alignment;
  }
  SphereLandmarks sphereLandmarks;
  alignment.Error =
    GatherLandmarks(landmarks, source, target, parameters.FitMobius, sphereLandmarks);
  // The correlation (grid search and Newton refinement) is half the work or more at high
  // Resolution: it reports progress and hears the abort button too, as does the mirror
  // check after it.
  SO3CorrelationOptions options = parameters.Correlation;
  options.Progress = [&report](double fraction) { return report(0.5 + 0.45 * fraction); };
  if (!alignment.Error.empty() || !Correlate(signals, options, report, alignment))
  {
    return alignment;
  }
  alignment.AlignedSource.swap(source.Sphere); // the Möbius fit moves them
  if (!ApplyLandmarks(sphereLandmarks, signals, parameters.FitMobius, options, alignment))
  {
    alignment.AlignedSource.resize(0, 3);
    return alignment;
  }
  if (parameters.CheckMirroring)
  {
    CheckForMirroring(signals, options, alignment);
  }
  if (!parameters.FitMobius)
  {
    TransformPoints(alignment.Correlation.Transform, alignment.AlignedSource);
  }
  return alignment;
}
}
