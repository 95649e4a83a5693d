// The centering as vtkMobiusCenter runs it (MapCentering.h), without VTK: the map of an
// asymmetric surface centered to the tolerance (|mu| below 1e-10, the Lorentz matrix moving
// the input's points onto the output's), and with Degree 2 its moments of degree 1 and 2 made
// small; each message comes out as the filter prints it: an input the centering refuses, a
// point set at Degree 2, the warnings of a centering stopped by its step limit; a stop asked
// by the progress is no error.
#include "BumpySurface.h"
#include "CoreTest.h"
#include "Icosphere.h"
#include "MapCentering.h"

#include <string>

using namespace mobius;

namespace
{
struct Map
{
  Points Sphere;
  Triangles Faces;
  Vector Areas;
};

Map BumpyMap()
{
  Map map;
  MakeIcosphere(3, map.Sphere, map.Faces);
  map.Areas = BumpySurfaceAreas(map.Sphere, map.Faces);
  return map;
}

void TestMobiusCentering()
{
  Map map = BumpyMap();
  const Points input = map.Sphere;
  MapCenteringParameters parameters;
  const MapCentering centering = CenterMap(map.Sphere, map.Faces, map.Areas, parameters);
  MOBIUS_CHECK(centering.Error.empty() && centering.Warnings.empty() && !centering.Stopped);
  MOBIUS_CHECK(centering.Mobius.InitialCenterOfMassNorm > 0.01);
  MOBIUS_CHECK(centering.Mobius.CenterOfMassNorm <= 1e-10);
  MOBIUS_CHECK_NEAR(SphericalCenterOfMass(map.Sphere, map.Faces, map.Areas).norm(), 0.0, 1e-10);
  MOBIUS_CHECK(centering.Generalized.NumberOfIterations == 0);
  const Eigen::Vector3d moved =
    ApplyLorentzTransform(centering.Mobius.LorentzTransform, input.row(7).transpose());
  MOBIUS_CHECK_NEAR((moved - map.Sphere.row(7).transpose()).norm(), 0.0, 1e-9);
}

void TestGeneralizedCentering()
{
  Map map = BumpyMap();
  MapCenteringParameters parameters;
  parameters.Degree = 2;
  parameters.Generalized.Tolerance = 1e-8;
  const MapCentering centering = CenterMap(map.Sphere, map.Faces, map.Areas, parameters);
  MOBIUS_CHECK(centering.Error.empty() && centering.Warnings.empty());
  MOBIUS_CHECK(centering.Generalized.NumberOfIterations > 0);
  MOBIUS_CHECK(centering.Mobius.CenterOfMassNorm == centering.Generalized.CenterOfMassNorm);
  MOBIUS_CHECK_NEAR(SphericalHarmonicMoments(map.Sphere, map.Faces, map.Areas, 2).norm(), 0.0, 1e-8);
}

void TestMessages()
{
  Map map = BumpyMap();
  MapCenteringParameters parameters;
  parameters.Mobius.MaximumNumberOfIterations = 1;
  parameters.Mobius.Tolerance = 0;
  MapCentering centering = CenterMap(map.Sphere, map.Faces, map.Areas, parameters);
  MOBIUS_CHECK(centering.Warnings.size() == 1 &&
    centering.Warnings[0].rfind("Centering stopped after 1 iterations with |mu| = ", 0) == 0 &&
    centering.Warnings[0].find(" above the tolerance 0.") != std::string::npos);
  map = BumpyMap();
  parameters = MapCenteringParameters();
  parameters.Degree = 3;
  parameters.Generalized.MaximumNumberOfIterations = 2;
  parameters.Generalized.Tolerance = 0;
  centering = CenterMap(map.Sphere, map.Faces, map.Areas, parameters);
  MOBIUS_CHECK(centering.Warnings.size() == 1 &&
    centering.Warnings[0].rfind("Generalized centering stopped after 2 iterations", 0) == 0);
  map = BumpyMap();
  map.Sphere.row(5) *= 2;
  centering = CenterMap(map.Sphere, map.Faces, map.Areas, MapCenteringParameters());
  MOBIUS_CHECK(centering.Error.rfind("Centering failed: point 5 is not on the unit sphere", 0) == 0);
  map = BumpyMap();
  parameters = MapCenteringParameters();
  parameters.Degree = 2;
  centering = CenterMap(map.Sphere, Triangles(), Vector(), parameters);
  MOBIUS_CHECK(centering.Error ==
    "Cannot center: Degree 2 needs triangles; a point set can only be centered with Degree 1.");
}

void TestStop()
{
  Map map = BumpyMap();
  MapCenteringParameters parameters;
  parameters.Progress = [](double) { return false; };
  const MapCentering centering = CenterMap(map.Sphere, map.Faces, map.Areas, parameters);
  MOBIUS_CHECK(centering.Stopped && centering.Error.empty() && centering.Warnings.empty());
}
}

int main()
{
  TestMobiusCentering();
  TestGeneralizedCentering();
  TestMessages();
  TestStop();
  return MOBIUS_TEST_RESULT();
}
