// vtkMobiusCenter: centering, pass-through of arrays, the returned Möbius transformation,
// point sets, and a clear error for each kind of bad input.
#include "MobiusTestUtilities.h"
#include "vtkMobiusCenter.h"

#include "GeneralizedCentering.h"

#include "vtkExecutive.h"
#include "vtkIntArray.h"

#include <limits>

namespace
{
int TestCentersAndPassesData()
{
  int failures = 0;
  auto map = mobius_test::MakeSphericalMap(4, mobius_test::BumpySurface, { 0.5, -0.3, 0.4 });
  vtkNew<vtkIntArray> label;
  label->SetName("Label");
  for (vtkIdType i = 0; i < map->GetNumberOfPoints(); ++i)
  {
    label->InsertNextValue(static_cast<int>(i % 7));
  }
  map->GetPointData()->AddArray(label);
  vtkNew<vtkDoubleArray> note;
  note->SetName("UserNote");
  note->InsertNextValue(42.0);
  map->GetFieldData()->AddArray(note);
  vtkNew<vtkPoints> before;
  before->SetDataTypeToDouble();
  before->DeepCopy(map->GetPoints());

  vtkNew<vtkMobiusCenter> center;
  center->SetInputData(map);
  center->Update();
  vtkPolyData* out = center->GetOutput();

  MOBIUS_EXPECT(out->GetNumberOfPoints() == map->GetNumberOfPoints());
  MOBIUS_EXPECT(out->GetNumberOfPolys() == map->GetNumberOfPolys());
  MOBIUS_EXPECT(mobius_test::FieldValue(out, "CenterOfMassNorm") <= 1e-10);
  MOBIUS_EXPECT(mobius_test::FieldValue(out, "InitialCenterOfMassNorm") > 0.3);
  const double iterations = mobius_test::FieldValue(out, "CenteringIterations");
  MOBIUS_EXPECT(iterations >= 1 && iterations <= 10);
  MOBIUS_EXPECT(out->GetFieldData()->GetArray("InversionCenters")->GetNumberOfTuples() ==
    static_cast<vtkIdType>(iterations));
  MOBIUS_EXPECT(mobius_test::FieldValue(out, "UserNote") == 42.0);
  MOBIUS_EXPECT(out->GetPointData()->GetArray("Label") != nullptr);
  MOBIUS_EXPECT(out->GetPointData()->GetArray("SurfacePoints") != nullptr);
  MOBIUS_EXPECT(out->GetCellData()->GetArray("SurfaceArea") != nullptr);

  // The input is untouched and keeps its field data as it was.
  double maxInputChange = 0;
  for (vtkIdType i = 0; i < map->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    map->GetPoint(i, a);
    before->GetPoint(i, b);
    maxInputChange = std::max(maxInputChange, std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]));
  }
  MOBIUS_EXPECT(maxInputChange == 0);
  MOBIUS_EXPECT(map->GetFieldData()->GetArray("CenterOfMassNorm") == nullptr);

  // Applying MobiusTransform to the input points gives the output points, and the output
  // lies on the unit sphere.
  vtkDataArray* transform = out->GetFieldData()->GetArray("MobiusTransform");
  MOBIUS_EXPECT(transform && transform->GetNumberOfComponents() == 16);
  Eigen::Matrix4d lorentz;
  for (int k = 0; k < 16; ++k)
  {
    lorentz(k / 4, k % 4) = transform->GetComponent(0, k);
  }
  double maxError = 0, maxRadiusError = 0;
  for (vtkIdType i = 0; i < map->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    map->GetPoint(i, p);
    out->GetPoint(i, q);
    const Eigen::Vector3d image = mobius::ApplyLorentzTransform(lorentz, Eigen::Vector3d(p[0], p[1], p[2]));
    maxError = std::max(maxError, (image - Eigen::Vector3d(q[0], q[1], q[2])).norm());
    maxRadiusError = std::max(maxRadiusError, std::abs(Eigen::Vector3d(q[0], q[1], q[2]).norm() - 1));
  }
  MOBIUS_EXPECT(maxError < 1e-9);
  MOBIUS_EXPECT(maxRadiusError < 1e-12);
  return failures;
}

int TestGeneralizedCentering()
{
  int failures = 0;
  auto map = mobius_test::MakeSphericalMap(4, mobius_test::BumpySurface, { 0.3, -0.2, 0.1 });
  vtkNew<vtkMobiusCenter> center;
  center->SetInputData(map);
  center->SetDegree(3);
  center->Update();
  vtkPolyData* out = center->GetOutput();
  MOBIUS_EXPECT(mobius_test::FieldValue(out, "CenteringDegree") == 3);
  MOBIUS_EXPECT(mobius_test::FieldValue(out, "GeneralizedCenteringIterations") >= 1);
  MOBIUS_EXPECT(mobius_test::FieldValue(out, "CenterOfMassNorm") <= 1e-10);
  // The moments of degree 1..3, recomputed from the output, vanish.
  mobius::Points points(out->GetNumberOfPoints(), 3);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    points.row(i) << p[0], p[1], p[2];
  }
  mobius::Triangles triangles(out->GetNumberOfPolys(), 3);
  mobius::Vector areas(out->GetNumberOfPolys());
  for (vtkIdType t = 0; t < out->GetNumberOfPolys(); ++t)
  {
    vtkIdType npts;
    const vtkIdType* ids;
    out->GetCellPoints(t, npts, ids);
    triangles.row(t) << ids[0], ids[1], ids[2];
    areas[t] = out->GetCellData()->GetArray("SurfaceArea")->GetTuple1(t);
  }
  MOBIUS_EXPECT(mobius::SphericalHarmonicMoments(points, triangles, areas, 3).norm() <= 1e-10);

  // Degrees 4 to 8, with their own tolerance and iteration cap: the moments up to the degree
  // vanish to that tolerance and no triangle flips (every triangle still faces outward).
  for (int degree = 4; degree <= 8; ++degree)
  {
    vtkNew<vtkMobiusCenter> high;
    high->SetInputData(map);
    high->SetDegree(degree);
    high->SetGeneralizedTolerance(1e-9);
    high->SetGeneralizedMaximumNumberOfIterations(400);
    high->Update();
    vtkPolyData* centered = high->GetOutput();
    for (vtkIdType i = 0; i < centered->GetNumberOfPoints(); ++i)
    {
      double p[3];
      centered->GetPoint(i, p);
      points.row(i) << p[0], p[1], p[2];
    }
    int flipped = 0;
    for (Eigen::Index t = 0; t < triangles.rows(); ++t)
    {
      const Eigen::Vector3d a = points.row(triangles(t, 0)), b = points.row(triangles(t, 1)),
                            c = points.row(triangles(t, 2));
      flipped += (b - a).cross(c - a).dot(a + b + c) <= 0 ? 1 : 0;
    }
    const double moments = mobius::SphericalHarmonicMoments(points, triangles, areas, degree).norm();
    std::cout << "degree " << degree << ": |mu| " << moments << " after "
              << mobius_test::FieldValue(centered, "GeneralizedCenteringIterations")
              << " steps, flipped triangles " << flipped << std::endl;
    MOBIUS_EXPECT(moments <= 1e-9);
    MOBIUS_EXPECT(flipped == 0);
    MOBIUS_EXPECT(mobius_test::FieldValue(centered, "GeneralizedCenteringIterations") <= 400);
  }
  // The iteration cap is the generalized one: one step cannot center degree 8.
  vtkNew<vtkMobiusCenter> capped;
  mobius_test::MessageCatcher cappedCatcher(capped);
  capped->SetInputData(map);
  capped->SetDegree(8);
  capped->SetGeneralizedMaximumNumberOfIterations(1);
  capped->Update();
  MOBIUS_EXPECT(mobius_test::FieldValue(capped->GetOutput(), "GeneralizedCenteringIterations") == 1);
  MOBIUS_EXPECT(cappedCatcher.Warning.find("Generalized centering stopped after 1") != std::string::npos);

  // A point set can only be Möbius-centered.
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(map->GetPoints());
  vtkNew<vtkMobiusCenter> pointCenter;
  mobius_test::MessageCatcher catcher(pointCenter);
  mobius_test::MessageCatcher executiveCatcher(pointCenter->GetExecutive());
  pointCenter->SetInputData(cloud);
  pointCenter->SetDegree(2);
  pointCenter->Update();
  MOBIUS_EXPECT(catcher.Error.find("needs triangles") != std::string::npos);
  return failures;
}

int TestPointSet()
{
  int failures = 0;
  vtkNew<vtkPolyData> cloud;
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 400; ++i)
  {
    // A spiral crowded toward the north pole.
    const double z = 1.0 - 1.2 * (i + 0.5) / 400.0;
    const double r = std::sqrt(1 - z * z), phi = 2.4 * i;
    points->InsertNextPoint(r * std::cos(phi), r * std::sin(phi), z);
  }
  cloud->SetPoints(points);
  vtkNew<vtkMobiusCenter> center;
  center->SetInputData(cloud);
  center->Update();
  vtkPolyData* out = center->GetOutput();
  MOBIUS_EXPECT(out->GetNumberOfPoints() == 400);
  MOBIUS_EXPECT(mobius_test::FieldValue(out, "InitialCenterOfMassNorm") > 0.1);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    mean += Eigen::Vector3d(p[0], p[1], p[2]) / 400.0;
  }
  MOBIUS_EXPECT(mean.norm() <= 1e-10);
  return failures;
}

// Runs the filter on `input` and checks that it fails with an error containing `words`
// and produces no output.
int ExpectError(vtkPolyData* input, const std::string& words)
{
  int failures = 0;
  vtkNew<vtkMobiusCenter> center;
  mobius_test::MessageCatcher catcher(center);
  // The executive reports the failed request too; keep that out of the test log.
  mobius_test::MessageCatcher executiveCatcher(center->GetExecutive());
  center->SetInputData(input);
  center->Update();
  if (catcher.Error.find(words) == std::string::npos)
  {
    std::cerr << "expected an error containing '" << words << "', got '" << catcher.Error << "'\n";
    ++failures;
  }
  MOBIUS_EXPECT(center->GetOutput()->GetNumberOfPoints() == 0);
  return failures;
}

int TestBadInputs()
{
  int failures = 0;
  // An empty input gives an empty output, not an error: TestEmptyInputs.

  auto offSphere = mobius_test::MakeSphericalMap(2, mobius_test::BumpySurface);
  offSphere->GetPoints()->SetPoint(5, 0.0, 0.0, 1.1);
  failures += ExpectError(offSphere, "not on the unit sphere");

  auto withNaN = mobius_test::MakeSphericalMap(2, mobius_test::BumpySurface);
  withNaN->GetPoints()->SetPoint(3, std::nan(""), 0.0, 1.0);
  failures += ExpectError(withNaN, "NaN");

  auto quad = mobius_test::MakeSphericalMap(2, mobius_test::BumpySurface);
  const vtkIdType quadIds[4] = { 0, 1, 2, 3 };
  quad->GetPolys()->InsertNextCell(4, quadIds);
  quad->GetCellData()->GetArray("SurfaceArea")->InsertNextTuple1(1.0);
  failures += ExpectError(quad, "only triangles");

  auto withLine = mobius_test::MakeSphericalMap(2, mobius_test::BumpySurface);
  vtkNew<vtkCellArray> lines;
  const vtkIdType lineIds[2] = { 0, 1 };
  lines->InsertNextCell(2, lineIds);
  withLine->SetLines(lines);
  failures += ExpectError(withLine, "line");

  auto noArea = mobius_test::MakeSphericalMap(2, mobius_test::BumpySurface);
  noArea->GetCellData()->RemoveArray("SurfaceArea");
  failures += ExpectError(noArea, "SurfaceArea");

  for (double bad : { -1.0, std::numeric_limits<double>::infinity(), std::nan("") })
  {
    auto badArea = mobius_test::MakeSphericalMap(2, mobius_test::BumpySurface);
    badArea->GetCellData()->GetArray("SurfaceArea")->SetTuple1(7, bad);
    failures += ExpectError(badArea, "invalid value");
  }
  // A triangle of three points on a line has no area; it weighs nothing, and is no error.
  auto zeroArea = mobius_test::MakeSphericalMap(2, mobius_test::BumpySurface);
  zeroArea->GetCellData()->GetArray("SurfaceArea")->SetTuple1(7, 0.0);
  vtkNew<vtkMobiusCenter> center;
  mobius_test::MessageCatcher catcher(center);
  center->SetInputData(zeroArea);
  center->Update();
  MOBIUS_EXPECT(catcher.Error.empty());
  MOBIUS_EXPECT(center->GetOutput()->GetNumberOfPoints() == zeroArea->GetNumberOfPoints());
  return failures;
}
}

int TestMobiusCenter(int, char*[])
{
  int failures = TestCentersAndPassesData();
  failures += TestPointSet();
  failures += TestGeneralizedCentering();
  failures += TestBadInputs();
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
