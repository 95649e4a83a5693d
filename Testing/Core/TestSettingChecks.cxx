// The checks of settings that the filters report word for word (vtkSphericalScaleGrid and
// vtkSymmetryDetection: the grid resolution; vtkCorrespondenceRefinement: the basis sizes and
// the candidate), and the rotations the refinement's candidates start from.
#include "CoreTest.h"
#include "RefineCorrespondence.h"
#include "ScaleFactorSignal.h"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace mobius;

namespace
{
void TestGridResolution()
{
  MOBIUS_CHECK(CheckGridResolution(4).empty());
  MOBIUS_CHECK(CheckGridResolution(256).empty());
  MOBIUS_CHECK(CheckGridResolution(3) == "Resolution must be even and at least 4 (it is 3)");
  MOBIUS_CHECK(CheckGridResolution(2) == "Resolution must be even and at least 4 (it is 2)");
  MOBIUS_CHECK(CheckGridResolution(-4) == "Resolution must be even and at least 4 (it is -4)");
  // A caller that needs a finer grid (the alignment) gives its own minimum.
  MOBIUS_CHECK(CheckGridResolution(8, 8).empty());
  MOBIUS_CHECK(CheckGridResolution(6, 8) == "Resolution must be even and at least 8 (it is 6)");
  MOBIUS_CHECK(CheckGridResolution(9, 8) == "Resolution must be even and at least 8 (it is 9)");
}

void TestBasisSizes()
{
  MOBIUS_CHECK(CheckBasisSizes(20, 20).empty());
  MOBIUS_CHECK(CheckBasisSizes(1, 500).empty());
  MOBIUS_CHECK(CheckBasisSizes(21, 20) == "StartBasisSize (21) must not exceed BasisSize (20).");
}

void TestCandidate()
{
  MOBIUS_CHECK(CheckCandidate(-1, 1).empty()); // none given
  MOBIUS_CHECK(CheckCandidate(3, 4).empty());
  MOBIUS_CHECK(CheckCandidate(4, 4) ==
    "Candidate 4 does not exist: the registration has 4 candidates (0..3).");
  MOBIUS_CHECK(CheckCandidate(1, 1) ==
    "Candidate 1 does not exist: the registration has 1 candidate (0..0).");
}

RotationMatrix Turn(double angle, const Eigen::Vector3d& axis)
{
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

// The aligned source is the best transform's image: each start, applied to it, gives the
// candidate's own image, and the best one is the identity, first and once.
void TestCandidateStarts()
{
  const RotationMatrix best = Turn(0.7, { 1, 2, 3 });
  RotationMatrix mirror = Turn(2.0, { 0, 1, 1 });
  mirror.col(0) *= -1; // a reflection: starts reach reflections too
  RotationMatrix notFinite = Turn(1.0, { 1, 0, 0 });
  notFinite(1, 1) = std::numeric_limits<double>::quiet_NaN();
  const std::vector<RotationMatrix> candidates = { best, Turn(1.5, { 0, 0, 1 }), notFinite,
    mirror };
  const std::vector<RotationMatrix> starts = CandidateStarts(best, candidates);
  MOBIUS_CHECK(starts.size() == 3);
  if (starts.size() != 3)
  {
    return;
  }
  MOBIUS_CHECK((starts[0] - RotationMatrix::Identity()).norm() == 0.0);
  const Eigen::Vector3d x(0.3, -0.5, 0.8);
  MOBIUS_CHECK_NEAR((starts[1] * (best * x) - candidates[1] * x).norm(), 0.0, 1e-12);
  MOBIUS_CHECK_NEAR((starts[2] * (best * x) - mirror * x).norm(), 0.0, 1e-12);
  MOBIUS_CHECK(CandidateStarts(best, {}).size() == 1);
}
}

int main()
{
  TestGridResolution();
  TestBasisSizes();
  TestCandidate();
  TestCandidateStarts();
  return MOBIUS_TEST_RESULT();
}
