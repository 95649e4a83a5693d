// The rotational alignment as vtkSO3Register runs it (RotationalAlignment.h), without VTK:
// a centered map of an asymmetric surface and a turned copy of it are aligned (the kept
// transform is the turn, the source's points land on the copy's: 0.0019 and 0.0014 at
// Resolution 32 under glibc's default and its SSE2 dispatch alike, bound 0.02); 3 exact
// landmarks order the candidates (the kept one's angle about 0) and fit a Möbius
// transformation that sends them onto their targets; each message comes out as the filter
// prints it: a bad or coarse Resolution, a map that could not be read, a landmark naming no
// point, too few or coinciding landmarks for the fit; a stop asked by the progress is no
// error; the memory estimate and the largest grid that fits agree.
#include "BumpySurface.h"
#include "CoreTest.h"
#include "Icosphere.h"
#include "LandmarkAlignment.h"
#include "MobiusCentering.h"
#include "Rotation.h"
#include "RotationalAlignment.h"

#include <Eigen/Geometry>

#include <cmath>
#include <iostream>
#include <string>

using namespace mobius;

namespace
{
// The icosphere as the centered conformal map of the bumpy surface.
AlignmentMap CenteredMap(const std::string& name)
{
  AlignmentMap map;
  map.Name = name;
  MakeIcosphere(3, map.Sphere, map.Triangles);
  map.Areas = BumpySurfaceAreas(map.Sphere, map.Triangles);
  MobiusCenteringResult centering;
  MOBIUS_CHECK(CenterSphericalMap(map.Sphere, map.Triangles, map.Areas, {}, centering));
  return map;
}

RotationalAlignmentParameters Parameters(int resolution)
{
  RotationalAlignmentParameters parameters;
  parameters.Signal.Resolution = resolution;
  parameters.Signal.NumberOfThreads = 2;
  parameters.Correlation.NumberOfThreads = 2;
  return parameters;
}

// The message of aligning `source` with `target` under `parameters` and `landmarks`.
std::string ErrorOf(const AlignmentMap& source, const AlignmentMap& target,
  const RotationalAlignmentParameters& parameters,
  const std::vector<std::pair<Index, Index>>& landmarks = {})
{
  const RotationalAlignment alignment = AlignSphericalMaps(source, target, landmarks, parameters);
  if (!alignment.Error.empty())
  {
    MOBIUS_CHECK(alignment.AlignedSource.rows() == 0);
  }
  return alignment.Error;
}

void CheckMessages(const AlignmentMap& source, const AlignmentMap& target)
{
  MOBIUS_CHECK(ErrorOf(source, target, Parameters(7)) ==
    "Resolution must be even and at least 8 (it is 7): a coarser grid cannot tell the rotation.");
  const RotationalAlignment coarse = AlignSphericalMaps(source, target, {}, Parameters(16));
  MOBIUS_CHECK(coarse.Error.empty() && coarse.Warnings.size() == 1 &&
    coarse.Warnings[0] == "Resolution 16 resolves the rotation only to about 22 degrees: the map "
                          "may come back turned; 32 or more is reliable.");
  AlignmentMap unreadable = target;
  unreadable.Problem = "it has no triangles";
  MOBIUS_CHECK(ErrorOf(source, unreadable, Parameters(32)) ==
    "Cannot register: the Target: it has no triangles.");
  MOBIUS_CHECK(ErrorOf(source, target, Parameters(32), { { 0, 1 }, { 3, 642 } }) ==
    "Cannot register: landmark 1 names point 642 of the Target, which has 642 points.");
  RotationalAlignmentParameters fit = Parameters(32);
  fit.FitMobius = true;
  MOBIUS_CHECK(ErrorOf(source, target, fit, { { 0, 1 }, { 3, 4 } }) ==
    "Cannot register: LandmarkMode 1 fits a Moebius transformation to 3 landmarks, and there "
    "are 2.");
  MOBIUS_CHECK(ErrorOf(source, target, fit, { { 0, 1 }, { 0, 4 }, { 9, 9 } }) ==
    "Cannot register: two of the first 3 landmarks are at the same point of a sphere: no Moebius "
    "transformation sends them onto their targets.");
  RotationalAlignmentParameters stopped = Parameters(32);
  stopped.Progress = [](double fraction) { return fraction < 0.3; };
  const RotationalAlignment stop = AlignSphericalMaps(source, target, {}, stopped);
  MOBIUS_CHECK(stop.Stopped && stop.Error.empty() && stop.AlignedSource.rows() == 0);
}
}

int main()
{
  const AlignmentMap source = CenteredMap("Source");
  AlignmentMap target = CenteredMap("Target");
  const Eigen::Matrix3d turn = EulerZYZToMatrix(0.4, 1.1, -0.7);
  target.Sphere = (source.Sphere * turn.transpose()).eval();

  // The turn comes back, and the source's points land on the copy's.
  const RotationalAlignment aligned = AlignSphericalMaps(source, target, {}, Parameters(32));
  MOBIUS_CHECK(aligned.Error.empty() && aligned.Warnings.empty() && !aligned.Stopped);
  MOBIUS_CHECK(aligned.Correlation.Candidates.size() >= 1 && aligned.LandmarkAngles.empty());
  const double turnError = (aligned.Correlation.Transform - turn).norm();
  const double pointError = (aligned.AlignedSource - target.Sphere).rowwise().norm().maxCoeff();
  std::cout << "turn recovered to " << turnError << " (Frobenius), points to " << pointError
            << "\n";
  MOBIUS_CHECK(turnError < 0.02);
  MOBIUS_CHECK(pointError < 0.02);
  MOBIUS_CHECK(aligned.Mirroring.ChosenError >= 0 && !aligned.Mirroring.OtherFitsFarBetter);

  // Exact landmarks: the kept candidate brings them together; their Möbius fit sends them
  // onto their targets exactly.
  const std::vector<std::pair<Index, Index>> landmarks = { { 0, 0 }, { 200, 200 }, { 500, 500 } };
  const RotationalAlignment chosen = AlignSphericalMaps(source, target, landmarks, Parameters(32));
  MOBIUS_CHECK(chosen.LandmarkAngles.size() == chosen.Correlation.Candidates.size());
  MOBIUS_CHECK(!chosen.LandmarkAngles.empty() && chosen.LandmarkAngles[0] < 0.02);
  std::cout << "kept candidate's landmark angle " << chosen.LandmarkAngles[0] << "\n";
  RotationalAlignmentParameters fit = Parameters(32);
  fit.FitMobius = true;
  const RotationalAlignment fitted = AlignSphericalMaps(source, target, landmarks, fit);
  MOBIUS_CHECK(fitted.Error.empty() && fitted.Correlation.Candidates.size() == 1);
  MOBIUS_CHECK(fitted.LandmarkAngles.empty());
  for (const auto& landmark : landmarks)
  {
    MOBIUS_CHECK((fitted.AlignedSource.row(landmark.first) - target.Sphere.row(landmark.second))
                   .norm() < 1e-9);
  }

  CheckMessages(source, target);
  const Index counts[2] = { 5, 7 };
  const std::string names[2] = { "Source (port 0)", "Target (port 1)" };
  MOBIUS_CHECK(CheckLandmarkIds({ { 4, 6 } }, counts, names).empty());
  MOBIUS_CHECK(CheckLandmarkIds({ { 4, 6 }, { -1, 0 } }, counts, names) ==
    "landmark 1 names point -1 of the Source (port 0), which has 5 points");
  MOBIUS_CHECK(AlignmentMemoryEstimate(LargestAlignmentResolution(1e9)) <= 1e9);
  MOBIUS_CHECK(AlignmentMemoryEstimate(LargestAlignmentResolution(1e9) + 2) > 1e9);
  MOBIUS_CHECK(LargestAlignmentResolution(1e6) == 4);
  return MOBIUS_TEST_RESULT();
}
