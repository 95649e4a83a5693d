#include "LandmarkDisagreement.h"

#include "ParameterRules.h"

#include <cmath>

namespace mobius
{
namespace
{
// Degrees from radians, as VTK computes them (vtkMath::DegreesFromRadians).
double Degrees(double radians)
{
  return radians * 57.29577951308232;
}

const std::string DisagreementDegrees =
  std::to_string(std::lround(Degrees(kLandmarkDisagreementAngle)));

// Candidate `c`'s transform, the identity when there is no such candidate.
Eigen::Matrix3d CandidateTransform(const std::vector<Eigen::Matrix3d>& candidates, int c)
{
  return c >= 0 && c < static_cast<int>(candidates.size()) ? candidates[c]
                                                            : Eigen::Matrix3d::Identity();
}

// The turn of the aligned source (candidate 0 applied) that candidate `c` starts from:
// T_c T_0^T.
Eigen::Matrix3d CandidateStart(const std::vector<Eigen::Matrix3d>& candidates, int c)
{
  return CandidateTransform(candidates, c) * CandidateTransform(candidates, 0).transpose();
}

// "line 3 (112 degrees), line 5 (95 degrees)": the landmarks `which` with their angles.
std::string AnglesOf(const RegistrationParameters& options, const std::vector<size_t>& which,
  const std::vector<double>& angles)
{
  std::string list;
  for (size_t k : which)
  {
    list += (list.empty() ? "" : ", ") + LandmarkLabel(options, k) + " (" +
      std::to_string(static_cast<int>(std::lround(Degrees(angles[k])))) + " degrees)";
  }
  return list;
}

// The landmarks `transform` leaves more than kLandmarkDisagreementAngle from their targets;
// `angles` gets every landmark's angle.
std::vector<size_t> FarLandmarks(
  const Eigen::Matrix3d& transform, const SphereLandmarks& landmarks, std::vector<double>& angles)
{
  angles = LandmarkAngles(transform, landmarks);
  std::vector<size_t> far;
  for (size_t k = 0; k < angles.size(); ++k)
  {
    if (angles[k] > kLandmarkDisagreementAngle)
    {
      far.push_back(k);
    }
  }
  return far;
}

bool AllNear(const Eigen::Matrix3d& transform, const SphereLandmarks& landmarks)
{
  std::vector<double> angles;
  return FarLandmarks(transform, landmarks, angles).empty();
}

// What agrees with every landmark where candidate `kept` does not, as the fix: the candidate
// to keep instead of one asked for, or, from 3 landmarks on (they fix an orthogonal
// transform), a transform of the kind not searched (a reflection, searching rotations). Only
// "if the shapes are mirror images": two landmarks swapped fit a reflection so on 4 of 28
// wrong sets measured (CGAL's meshes against stretched copies), mirror images on 14 of 14.
std::string DisagreementFix(const std::vector<Eigen::Matrix3d>& candidates, int kept,
  const SphereLandmarks& landmarks, const RegistrationParameters& options)
{
  const int count = candidates.empty() ? 1 : static_cast<int>(candidates.size());
  for (int other = 0; options.Candidate >= 0 && other < count; ++other)
  {
    if (other != kept && AllNear(CandidateStart(candidates, other), landmarks))
    {
      const std::string number = std::to_string(other);
      return "; Candidate " + std::to_string(kept) + " was asked for, and candidate " + number +
        " brings every landmark within " + DisagreementDegrees +
        " degrees: keep it with Candidate = " + number + " (mobius-register --candidate " +
        number + "), or let the refinement choose";
    }
  }
  if (options.TransformMode == 2 ||
    landmarks.Source.rows() < static_cast<Index>(FittedTransformLandmarks))
  {
    return {};
  }
  const bool reflection = options.TransformMode == 0; // the kind not searched
  if (!AllNear(FitLandmarkTransform(landmarks, reflection ? -1.0 : 1.0), landmarks))
  {
    return {};
  }
  return std::string("; a ") + (reflection ? "reflection" : "rotation") +
    " brings every landmark within " + DisagreementDegrees + " degrees: if the shapes are " +
    (reflection ? "mirror images of each other" : "the same way round") +
    ", set TransformMode to ROTATIONS_AND_REFLECTIONS to search both kinds";
}
}

std::string LandmarkDisagreement(const std::vector<Eigen::Matrix3d>& candidates, int kept,
  const SphereLandmarks& landmarks, const RegistrationParameters& options)
{
  // LandmarkMode 1's Möbius transformation meets the first 3 by construction and moves the
  // sphere's area so much that the others' angles say nothing (a right fourth landmark of
  // CGAL's man against its stretched copy: 92 degrees).
  if (landmarks.Source.rows() == 0 ||
    options.LandmarkMode == static_cast<int>(LandmarkMode::FitMobius))
  {
    return {};
  }
  std::vector<double> angles;
  const std::vector<size_t> far =
    FarLandmarks(CandidateStart(candidates, kept), landmarks, angles);
  if (far.empty())
  {
    return {};
  }
  return "The landmarks disagree with the map: candidate " + std::to_string(kept) +
    "'s transform, which the map starts from, leaves " + AnglesOf(options, far, angles) +
    " more than " + DisagreementDegrees + " degrees from " +
    (far.size() == 1 ? "its target" : "their targets") +
    " on the centered spheres, and the map is bent to meet them. Check them (two swapped, the "
    "other side, another vertex numbering)" +
    DisagreementFix(candidates, kept, landmarks, options) + ".";
}
}
