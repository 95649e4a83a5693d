// vtkSphericalOrbifoldMap on CGAL's CC0 meshes (hand, cow, camel), checked from its
// output arrays alone:
// - the centered map of the n-fold covering (n = 2, 3, 4) is n-fold symmetric: the point of
//   copy i rotated by 2 pi / n about z is the same vertex's point in copy i + 1, to 1e-6 on
//   the unit sphere (the copies differ only by the flow's rounding; the vertex spacing on the
//   sphere is ~1e-2, so an error of the construction would show as 1e-2 or more); the cones
//   sit at the poles; no triangle is flipped;
// - the same map after an inversion (another conformal map of the covering, uncentered) is
//   not symmetric (error > 0.05);
// - one copy covers 1/n of the sphere and has the input's triangles;
// - both area distortions (orbifold and plain map) are reported;
// - bad cone ids, equal cones, neighbouring cones and n outside 2..8 fail with their reason.
#include "MobiusTestUtilities.h"
#include "MobiusCentering.h"
#include "MapDistortion.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"
#include "vtkSphericalOrbifoldMap.h"
#include "vtkSurfaceMeshReader.h"

#include <Eigen/Geometry>

#include <cmath>
#include <iostream>
#include <map>
#include <utility>

namespace
{
constexpr double Pi = 3.14159265358979323846;

double Field(vtkPolyData* data, const char* name, int component = 0)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array ? array->GetComponent(0, component) : std::nan("");
}

vtkSmartPointer<vtkPolyData> Read(const char* name)
{
  vtkNew<vtkSurfaceMeshReader> reader;
  reader->SetFileName((std::string(MOBIUS_MESH_DIR "/") + name).c_str());
  reader->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(reader->GetOutput());
  return mesh;
}

Eigen::Vector3d Point(vtkPolyData* data, vtkIdType i)
{
  double x[3];
  data->GetPoint(i, x);
  return Eigen::Vector3d(x[0], x[1], x[2]);
}

// Max over vertices of |R(2 pi / n about axis) x(v, copy i) - x(v, copy i + 1)|, the best
// of the two turning directions; vertices named by (InputPointId, Copy).
double SymmetryError(vtkPolyData* covering, const mobius::Points& x, const Eigen::Vector3d& axis, int n)
{
  vtkDataArray* ids = covering->GetPointData()->GetArray("InputPointId");
  vtkDataArray* copies = covering->GetPointData()->GetArray("Copy");
  std::map<std::pair<vtkIdType, int>, vtkIdType> index;
  for (vtkIdType i = 0; i < covering->GetNumberOfPoints(); ++i)
  {
    index[{ static_cast<vtkIdType>(ids->GetTuple1(i)), static_cast<int>(copies->GetTuple1(i)) }] = i;
  }
  double best = 1e300;
  for (const int direction : { 1, -1 })
  {
    const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(direction * 2.0 * Pi / n, axis.normalized()).toRotationMatrix();
    double worst = 0.0;
    for (const auto& entry : index)
    {
      const int copy = entry.first.second;
      const vtkIdType next = copy < 0 ? entry.second : index.at({ entry.first.first, (copy + 1) % n });
      worst = std::max(worst, (rotation * x.row(entry.second).transpose() - x.row(next).transpose()).norm());
    }
    best = std::min(best, worst);
  }
  return best;
}

mobius::Points PointsOf(vtkPolyData* data)
{
  mobius::Points x(data->GetNumberOfPoints(), 3);
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
  {
    x.row(i) = Point(data, i);
  }
  return x;
}

mobius::Triangles TrianglesOf(vtkPolyData* data)
{
  mobius::Triangles triangles(data->GetNumberOfPolys(), 3);
  auto cells = data->GetPolys()->NewIterator();
  vtkIdType t = 0;
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell(), ++t)
  {
    vtkIdType count;
    const vtkIdType* ids;
    cells->GetCurrentCell(count, ids);
    triangles.row(t) << ids[0], ids[1], ids[2];
  }
  cells->Delete();
  return triangles;
}

int CheckMesh(const char* name, int n)
{
  int failures = 0;
  vtkSmartPointer<vtkPolyData> mesh = Read(name);
  MOBIUS_EXPECT(mesh->GetNumberOfPoints() > 0);
  vtkNew<vtkSphericalOrbifoldMap> filter;
  filter->SetInputData(mesh);
  filter->SetNumberOfCopies(n);
  filter->OutputCoveringOn();
  filter->Update();
  vtkPolyData* covering = filter->GetOutput();
  MOBIUS_EXPECT(covering->GetNumberOfPoints() == n * (mesh->GetNumberOfPoints() - 2) + 2);
  MOBIUS_EXPECT(covering->GetNumberOfPolys() == n * mesh->GetNumberOfPolys());
  if (covering->GetNumberOfPoints() == 0)
  {
    return failures + 1;
  }
  const mobius::Points x = PointsOf(covering);
  const mobius::Triangles triangles = TrianglesOf(covering);

  const double error = SymmetryError(covering, x, Eigen::Vector3d::UnitZ(), n);
  mobius::Points uncentered = x;
  mobius::ApplyInversion(Eigen::Vector3d(0.3, -0.2, 0.25), uncentered);
  vtkDataArray* copies = covering->GetPointData()->GetArray("Copy");
  std::vector<vtkIdType> cones;
  for (vtkIdType i = 0; i < covering->GetNumberOfPoints(); ++i)
  {
    if (copies->GetTuple1(i) < 0)
    {
      cones.push_back(i);
    }
  }
  MOBIUS_EXPECT(cones.size() == 2);
  if (cones.size() != 2)
  {
    return failures;
  }
  const double uncenteredError = SymmetryError(covering, uncentered,
    uncentered.row(cones[1]) - uncentered.row(cones[0]), n);
  mobius::Index flipped = 0;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    flipped += mobius::SignedVolume(x.row(triangles(t, 0)), x.row(triangles(t, 1)),
                 x.row(triangles(t, 2))) <= 0.0;
  }
  const double area = Field(covering, "StdLogAreaRatio");
  const double plainArea = Field(covering, "PlainStdLogAreaRatio");
  std::cout << name << ", n = " << n << ": symmetry error " << error << " (filter: "
            << Field(covering, "SymmetryError") << "), uncentered " << uncenteredError
            << ", flipped " << flipped << ", std log area ratio " << area << " (plain map "
            << plainArea << "), flow steps " << Field(covering, "ConformalFlowIterations")
            << ", cones " << Field(covering, "ConeIds", 0) << " " << Field(covering, "ConeIds", 1)
            << std::endl;
  MOBIUS_EXPECT(error < 1e-6);
  MOBIUS_EXPECT(Field(covering, "SymmetryError") < 1e-6);
  MOBIUS_EXPECT(uncenteredError > 0.05);
  MOBIUS_EXPECT(flipped == 0);
  MOBIUS_EXPECT(std::abs(std::abs(x(cones[0], 2)) - 1.0) < 1e-6);
  MOBIUS_EXPECT(std::abs(x(cones[0], 2) + x(cones[1], 2)) < 1e-6);
  // Lower only on shapes whose extremities are the two cones (see the README's table).
  MOBIUS_EXPECT(area > 0.0 && area < 100.0 && plainArea > 0.0 && plainArea < 100.0);
  MOBIUS_EXPECT(Field(covering, "NumberOfCopies") == n);

  // One copy: the input's triangles over 1/n of the sphere.
  filter->OutputCoveringOff();
  filter->Update();
  vtkPolyData* copy = filter->GetOutput();
  MOBIUS_EXPECT(copy->GetNumberOfPolys() == mesh->GetNumberOfPolys());
  const mobius::Points y = PointsOf(copy);
  const mobius::Triangles copyTriangles = TrianglesOf(copy);
  double sphereArea = 0.0;
  for (Eigen::Index t = 0; t < copyTriangles.rows(); ++t)
  {
    const Eigen::Vector3d a = y.row(copyTriangles(t, 0)), b = y.row(copyTriangles(t, 1)),
                          c = y.row(copyTriangles(t, 2));
    sphereArea += 0.5 * (b - a).cross(c - a).norm();
  }
  std::cout << "  one copy: " << copy->GetNumberOfPoints() << " points, chordal area "
            << sphereArea << " of " << 4.0 * Pi / n << std::endl;
  // Flat chord triangles have slightly less area than the sphere they cover.
  MOBIUS_EXPECT(sphereArea < 4.0 * Pi / n && sphereArea > 0.97 * 4.0 * Pi / n);
  return failures;
}

int CheckErrors()
{
  int failures = 0;
  vtkSmartPointer<vtkPolyData> hand = Read("hand.off");
  auto make = [&](int n, vtkIdType a, vtkIdType b) {
    auto filter = vtkSmartPointer<vtkSphericalOrbifoldMap>::New();
    filter->SetInputData(hand);
    filter->SetNumberOfCopies(n);
    filter->SetConeIds(a, b);
    return filter;
  };
  failures += ExpectError(make(1, -1, -1), "between 2 and 8, not 1");
  failures += ExpectError(make(9, -1, -1), "between 2 and 8, not 9");
  failures += ExpectError(make(3, 0, hand->GetNumberOfPoints()), "does not exist");
  failures += ExpectError(make(3, -5, 3), "does not exist");
  failures += ExpectError(make(3, 12, 12), "same vertex");
  // Neighbours: the two first corners of the first triangle.
  vtkIdType count;
  const vtkIdType* ids;
  hand->GetPolys()->GetCellAtId(0, count, ids);
  failures += ExpectError(make(3, ids[0], ids[1]), "neighbours");
  return failures;
}
}

int TestSphericalOrbifoldMap(int, char*[])
{
  int failures = 0;
  for (int n = 2; n <= 4; ++n)
  {
    failures += CheckMesh("hand.off", n);
  }
  failures += CheckMesh("cow.off", 3);
  failures += CheckMesh("camel.off", 2);
  failures += CheckErrors();
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
