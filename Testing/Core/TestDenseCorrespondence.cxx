// The dense correspondence as vtkDenseCorrespondence runs it (DenseCorrespondence.h),
// without VTK: the points of a finer icosphere, turned, are located in a coarser one (each
// point is its triangle's corners combined with its barycentric coordinates, to 1e-12), both
// ways; a landmark puts its point on its partner's vertex itself; each message comes out as
// the filter prints it: a located map the locator refuses, a landmark naming no point or a
// point in no triangle; a stop asked by the progress is no error; the progress runs up.
#include "CoreTest.h"
#include "DenseCorrespondence.h"
#include "Icosphere.h"

#include <Eigen/Geometry>

#include <string>

using namespace mobius;

namespace
{
CorrespondenceMap Icosphere(int levels, const std::string& name, double turn = 0)
{
  CorrespondenceMap map;
  map.Name = name;
  MakeIcosphere(levels, map.Sphere, map.Triangles);
  const Eigen::Matrix3d rotation =
    Eigen::AngleAxisd(turn, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  map.Sphere = map.Sphere * rotation.transpose();
  return map;
}

// The largest distance between a query point and the point its location gives.
double LocationError(const CorrespondenceMap& query, const CorrespondenceMap& located,
  const DenseCorrespondence& correspondence)
{
  double largest = 0;
  for (Index i = 0; i < query.Sphere.rows(); ++i)
  {
    const auto corners = located.Triangles.row(correspondence.Triangle[i]);
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    for (int c = 0; c < 3; ++c)
    {
      point += correspondence.Barycentric[i][c] * located.Sphere.row(corners[c]).transpose();
    }
    largest = std::max(largest, (point.normalized() - query.Sphere.row(i).transpose()).norm());
  }
  return largest;
}

void TestBothDirections()
{
  const CorrespondenceMap maps[2] = { Icosphere(3, "Source (port 0)", 0.3),
    Icosphere(2, "Target (port 1)") };
  DenseCorrespondenceParameters parameters;
  parameters.NumberOfThreads = 2;
  double last = 0;
  bool rising = true;
  parameters.Progress = [&](double fraction) {
    rising = rising && fraction >= last;
    last = fraction;
    return true;
  };
  const DenseCorrespondence forward = CorrespondSphericalMaps(maps, parameters);
  MOBIUS_CHECK(forward.Error.empty() && !forward.Stopped);
  MOBIUS_CHECK(forward.Triangle.size() == static_cast<size_t>(maps[0].Sphere.rows()));
  MOBIUS_CHECK_NEAR(LocationError(maps[0], maps[1], forward), 0.0, 1e-12);
  MOBIUS_CHECK(forward.ClampedPoints == 0 && forward.MaximumClampDistance == 0);
  MOBIUS_CHECK(rising && last >= 0.8 - 1e-12);
  parameters.TargetToSource = true;
  const DenseCorrespondence inverse = CorrespondSphericalMaps(maps, parameters);
  MOBIUS_CHECK(inverse.Triangle.size() == static_cast<size_t>(maps[1].Sphere.rows()));
  MOBIUS_CHECK_NEAR(LocationError(maps[1], maps[0], inverse), 0.0, 1e-12);
}

void TestLandmarks()
{
  const CorrespondenceMap maps[2] = { Icosphere(3, "Source (port 0)", 0.3),
    Icosphere(2, "Target (port 1)") };
  DenseCorrespondenceParameters parameters;
  parameters.Landmarks = { { 5, 17 }, { 40, 3 } };
  const DenseCorrespondence placed = CorrespondSphericalMaps(maps, parameters);
  MOBIUS_CHECK(placed.Error.empty());
  for (const auto& [from, to] : parameters.Landmarks)
  {
    const auto corners = maps[1].Triangles.row(placed.Triangle[from]);
    double weight = 0;
    for (int c = 0; c < 3; ++c)
    {
      weight += corners[c] == to ? placed.Barycentric[from][c] : 0.0;
    }
    MOBIUS_CHECK_NEAR(weight, 1.0, 0.0);
  }
  parameters.TargetToSource = true; // the target's landmark on the source's vertex
  const DenseCorrespondence inverse = CorrespondSphericalMaps(maps, parameters);
  const auto corners = maps[0].Triangles.row(inverse.Triangle[17]);
  MOBIUS_CHECK(corners[0] == 5 || corners[1] == 5 || corners[2] == 5);
}

std::string ErrorOf(const CorrespondenceMap maps[2],
  const std::vector<std::pair<Index, Index>>& landmarks = {})
{
  DenseCorrespondenceParameters parameters;
  parameters.Landmarks = landmarks;
  return CorrespondSphericalMaps(maps, parameters).Error;
}

void TestMessages()
{
  CorrespondenceMap maps[2] = { Icosphere(2, "Source (port 0)"), Icosphere(2, "Target (port 1)") };
  MOBIUS_CHECK(ErrorOf(maps, { { 0, 0 }, { 1, 500 } }) ==
    "Cannot map: landmark 1 names point 500 of the Target (port 1), which has 162 points.");
  // A point no triangle uses, named by a landmark.
  maps[1].Sphere.conservativeResize(163, 3);
  maps[1].Sphere.row(162) = Eigen::RowVector3d(0, 0, 1);
  MOBIUS_CHECK(ErrorOf(maps, { { 3, 162 } }) ==
    "Cannot map: landmark 0 names point 162, which is in no triangle.");
  maps[1].Triangles(0, 1) = 170;
  const std::string refused = ErrorOf(maps);
  MOBIUS_CHECK(refused.rfind("Cannot map: the Target (port 1): ", 0) == 0 && refused.back() == '.');
}

void TestStop()
{
  const CorrespondenceMap maps[2] = { Icosphere(3, "Source (port 0)"),
    Icosphere(2, "Target (port 1)") };
  DenseCorrespondenceParameters parameters;
  parameters.Progress = [](double fraction) { return fraction < 0.3; };
  const DenseCorrespondence stopped = CorrespondSphericalMaps(maps, parameters);
  MOBIUS_CHECK(stopped.Stopped && stopped.Error.empty());
}
}

int main()
{
  TestBothDirections();
  TestLandmarks();
  TestMessages();
  TestStop();
  return MOBIUS_TEST_RESULT();
}
