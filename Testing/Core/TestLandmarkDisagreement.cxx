// The registration's check that the landmarks agree with the final map (LandmarkDisagreement.h),
// without VTK: five landmarks on the sphere that the kept candidate's rotation brings onto
// their targets agree (no warning); two targets swapped, a mirrored target searched by
// rotations only, and a Candidate asked for against them each get the warning as the filter
// prints it, naming the far landmarks (by number, or by file and line) and the fix; a Möbius
// fit (LandmarkMode 1) is not checked.
#include "CoreTest.h"
#include "LandmarkDisagreement.h"

#include <Eigen/Geometry>

#include <string>

using namespace mobius;

namespace
{
const Eigen::Matrix3d Turn =
  Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
const Eigen::Matrix3d OtherTurn =
  Eigen::AngleAxisd(2.5, Eigen::Vector3d(0.3, 1, 1).normalized()).toRotationMatrix();

// Five landmarks far apart; Source on the aligned source's sphere (the kept candidate, Turn,
// applied), Target where Turn brings them.
SphereLandmarks AgreeingLandmarks()
{
  Points directions(5, 3);
  directions << 1, 0.1, 0, -0.2, 1, 0.1, 0.1, -0.3, 1, -1, -0.5, -0.2, 0.3, -1, -0.6;
  SphereLandmarks landmarks;
  landmarks.Source = directions.rowwise().normalized() * Turn.transpose();
  landmarks.Target = landmarks.Source;
  return landmarks;
}

RegistrationParameters FiveLandmarks()
{
  RegistrationParameters options;
  options.Landmarks.resize(5);
  return options;
}

bool Contains(const std::string& text, const std::string& part)
{
  const bool found = text.find(part) != std::string::npos;
  if (!found)
  {
    std::cerr << "expected '" << part << "' in '" << text << "'\n";
  }
  return found;
}

void TestAgreeing()
{
  const std::vector<Eigen::Matrix3d> candidates = { Turn, OtherTurn };
  MOBIUS_CHECK(LandmarkDisagreement(candidates, 0, AgreeingLandmarks(), FiveLandmarks()).empty());
  // Candidate 1 starts from OtherTurn Turn^T: the landmarks disagree, with Candidate 0 as the fix.
  RegistrationParameters options = FiveLandmarks();
  options.Candidate = 1;
  const std::string warning = LandmarkDisagreement(candidates, 1, AgreeingLandmarks(), options);
  MOBIUS_CHECK(Contains(warning, "The landmarks disagree with the map: candidate 1's transform"));
  MOBIUS_CHECK(Contains(warning, "; Candidate 1 was asked for, and candidate 0 brings every "
                                 "landmark within 60 degrees: keep it with Candidate = 0 "
                                 "(mobius-register --candidate 0), or let the refinement choose."));
}

void TestSwapped()
{
  SphereLandmarks landmarks = AgreeingLandmarks();
  landmarks.Target.row(0).swap(landmarks.Target.row(1));
  RegistrationParameters options = FiveLandmarks();
  options.LandmarksFile = "marks.csv";
  for (int k = 0; k < 5; ++k)
  {
    options.Landmarks[k].Line = k + 3;
  }
  const std::string warning = LandmarkDisagreement({ Turn }, 0, landmarks, options);
  MOBIUS_CHECK(Contains(warning, "leaves marks.csv line 3 ("));
  MOBIUS_CHECK(Contains(warning, "), marks.csv line 4 ("));
  MOBIUS_CHECK(Contains(warning, " degrees) more than 60 degrees from their targets on the "
                                 "centered spheres, and the map is bent to meet them. Check "
                                 "them (two swapped, the other side, another vertex numbering)."));
  options.LandmarkMode = static_cast<int>(LandmarkMode::FitMobius);
  MOBIUS_CHECK(LandmarkDisagreement({ Turn }, 0, landmarks, options).empty());
}

void TestMirrored()
{
  SphereLandmarks landmarks = AgreeingLandmarks();
  landmarks.Target.col(2) *= -1;
  RegistrationParameters options = FiveLandmarks();
  const std::string warning = LandmarkDisagreement({ Turn }, 0, landmarks, options);
  MOBIUS_CHECK(Contains(warning, "leaves landmark "));
  MOBIUS_CHECK(Contains(warning, "; a reflection brings every landmark within 60 degrees: if the "
                                 "shapes are mirror images of each other, set TransformMode to "
                                 "ROTATIONS_AND_REFLECTIONS to search both kinds."));
  options.TransformMode = 2; // both kinds searched: no fix to offer
  MOBIUS_CHECK(Contains(LandmarkDisagreement({ Turn }, 0, landmarks, options),
    "another vertex numbering)."));
}
}

int main()
{
  TestAgreeing();
  TestSwapped();
  TestMirrored();
  return MOBIUS_TEST_RESULT();
}
