// vtkDenseCorrespondence: a map against a rotated copy of itself, with the rotation undone,
// sends every vertex to itself; data transfer interpolates floating-point arrays and copies
// the nearest vertex's categories; both directions and both output geometries; errors.
#include "MobiusTestUtilities.h"
#include "vtkDenseCorrespondence.h"
#include "vtkMobiusCenter.h"
#include "vtkSO3Register.h"

#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"

#include <Eigen/Dense>

namespace
{
vtkSmartPointer<vtkPolyData> CenteredBumpyMap(int levels)
{
  auto map = mobius_test::MakeSphericalMap(levels, mobius_test::BumpySurface, { 0.2, -0.1, 0.3 });
  vtkNew<vtkMobiusCenter> center;
  center->SetInputData(map);
  center->Update();
  auto centered = vtkSmartPointer<vtkPolyData>::New();
  centered->DeepCopy(center->GetOutput());
  return centered;
}

void Rotate(vtkPolyData* map, const Eigen::Matrix3d& rotation)
{
  for (vtkIdType i = 0; i < map->GetNumberOfPoints(); ++i)
  {
    double p[3];
    map->GetPoint(i, p);
    const Eigen::Vector3d q = rotation * Eigen::Vector3d(p[0], p[1], p[2]);
    map->GetPoints()->SetPoint(i, q.data());
  }
}

double TotalArea(vtkPolyData* map)
{
  double total = 0;
  vtkDataArray* areas = map->GetCellData()->GetArray("SurfaceArea");
  for (vtkIdType t = 0; t < areas->GetNumberOfTuples(); ++t)
  {
    total += areas->GetTuple1(t);
  }
  return total;
}

// Mean and max |MappedPoints - SurfacePoints| / sqrt(area) over the output's points.
std::pair<double, double> SelfMapError(vtkPolyData* out, double area)
{
  vtkDataArray* mapped = out->GetPointData()->GetArray("MappedPoints");
  vtkDataArray* own = out->GetPointData()->GetArray("SurfacePoints");
  double sum = 0, largest = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    mapped->GetTuple(i, a);
    own->GetTuple(i, b);
    const double e = std::sqrt(vtkMath::Distance2BetweenPoints(a, b) / area);
    sum += e;
    largest = std::max(largest, e);
  }
  return { sum / out->GetNumberOfPoints(), largest };
}

int TestSelfMapWithKnownRotation()
{
  int failures = 0;
  auto target = CenteredBumpyMap(4);
  const double area = TotalArea(target);
  vtkNew<vtkFloatArray> height;
  height->SetName("Height");
  vtkNew<vtkIntArray> label;
  label->SetName("Label");
  for (vtkIdType i = 0; i < target->GetNumberOfPoints(); ++i)
  {
    double p[3];
    target->GetPointData()->GetArray("SurfacePoints")->GetTuple(i, p);
    height->InsertNextValue(static_cast<float>(p[2]));
    label->InsertNextValue(static_cast<int>(i % 5));
  }
  target->GetPointData()->AddArray(height);
  target->GetPointData()->AddArray(label);

  // The source: the same map rotated by R, then with R supplied (undone).
  const Eigen::Matrix3d rotation =
    Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  auto source = vtkSmartPointer<vtkPolyData>::New();
  source->DeepCopy(target);
  source->GetPointData()->RemoveArray("Height");
  Rotate(source, rotation);
  Rotate(source, rotation.transpose());

  vtkNew<vtkDenseCorrespondence> correspondence;
  correspondence->SetSourceData(source);
  correspondence->SetTargetData(target);
  correspondence->Update();
  vtkPolyData* out = correspondence->GetOutput();
  const auto error = SelfMapError(out, area);
  std::cout << "self map with the rotation supplied: max error " << error.second << " sqrt(area)\n";
  MOBIUS_EXPECT(error.second <= 1e-9);
  MOBIUS_EXPECT(out->GetNumberOfPoints() == source->GetNumberOfPoints());
  MOBIUS_EXPECT(out->GetNumberOfPolys() == source->GetNumberOfPolys());
  MOBIUS_EXPECT(mobius_test::FieldValue(out, "ClampedPoints") == 0);
  // Output points are the mapped positions (OutputGeometry = TARGET).
  double p[3], q[3];
  out->GetPoint(10, p);
  target->GetPointData()->GetArray("SurfacePoints")->GetTuple(10, q);
  MOBIUS_EXPECT(std::sqrt(vtkMath::Distance2BetweenPoints(p, q)) < 1e-9);
  // Data transfer: Height interpolated (float stays float), Label (an int) from the
  // nearest vertex; Label clashes with the source's own Label.
  auto transferredHeight = vtkFloatArray::SafeDownCast(out->GetPointData()->GetArray("Height"));
  auto transferredLabel = vtkIntArray::SafeDownCast(out->GetPointData()->GetArray("Label_Target"));
  MOBIUS_EXPECT(transferredHeight && transferredLabel);
  MOBIUS_EXPECT(out->GetPointData()->GetArray("Label") != nullptr);
  for (vtkIdType i = 0; transferredHeight && transferredLabel && i < out->GetNumberOfPoints(); ++i)
  {
    MOBIUS_EXPECT(std::abs(transferredHeight->GetValue(i) - height->GetValue(i)) < 1e-6);
    MOBIUS_EXPECT(transferredLabel->GetValue(i) == label->GetValue(i));
  }
  auto cellIds = vtkIdTypeArray::SafeDownCast(out->GetPointData()->GetArray("TargetCellId"));
  MOBIUS_EXPECT(cellIds && out->GetPointData()->GetArray("TargetBarycentric"));

  // OutputGeometry = SOURCE puts the points on the source surface.
  correspondence->SetOutputGeometryToSource();
  correspondence->Update();
  out = correspondence->GetOutput();
  out->GetPoint(10, p);
  source->GetPointData()->GetArray("SurfacePoints")->GetTuple(10, q);
  MOBIUS_EXPECT(vtkMath::Distance2BetweenPoints(p, q) == 0);

  // The inverse direction maps the target's vertices onto the source: here, to themselves.
  correspondence->SetDirectionToTargetToSource();
  correspondence->SetOutputGeometryToTarget();
  correspondence->Update();
  out = correspondence->GetOutput();
  MOBIUS_EXPECT(out->GetNumberOfPoints() == target->GetNumberOfPoints());
  MOBIUS_EXPECT(SelfMapError(out, area).second <= 1e-9);
  return failures;
}

int TestSelfMapThroughRegistration()
{
  int failures = 0;
  auto target = CenteredBumpyMap(4);
  const double area = TotalArea(target);
  auto source = vtkSmartPointer<vtkPolyData>::New();
  source->DeepCopy(target);
  Rotate(source, Eigen::AngleAxisd(0.7, Eigen::Vector3d(-2, 1, 0.5).normalized()).toRotationMatrix());
  vtkNew<vtkSO3Register> registration;
  registration->SetSourceData(source);
  registration->SetTargetData(target);
  registration->SetResolution(128);
  vtkNew<vtkDenseCorrespondence> correspondence;
  correspondence->SetSourceConnection(registration->GetOutputPort());
  correspondence->SetTargetData(target);
  correspondence->Update();
  const auto error = SelfMapError(correspondence->GetOutput(), area);
  std::cout << "self map through vtkSO3Register: mean error " << error.first << " sqrt(area)\n";
  MOBIUS_EXPECT(error.first <= 0.005);
  return failures;
}

int ExpectError(vtkPolyData* source, vtkPolyData* target, const std::string& words)
{
  int failures = 0;
  vtkNew<vtkDenseCorrespondence> correspondence;
  mobius_test::MessageCatcher catcher(correspondence);
  mobius_test::MessageCatcher executiveCatcher(correspondence->GetExecutive());
  correspondence->SetSourceData(source);
  correspondence->SetTargetData(target);
  correspondence->Update();
  if (catcher.Error.find(words) == std::string::npos)
  {
    std::cerr << "expected an error containing '" << words << "', got '" << catcher.Error << "'\n";
    ++failures;
  }
  MOBIUS_EXPECT(correspondence->GetOutput()->GetNumberOfPoints() == 0);
  return failures;
}

int TestBadInputs()
{
  int failures = 0;
  auto map = CenteredBumpyMap(2);
  auto noSurface = vtkSmartPointer<vtkPolyData>::New();
  noSurface->DeepCopy(map);
  noSurface->GetPointData()->RemoveArray("SurfacePoints");
  failures += ExpectError(map, noSurface, "Target (port 1): it has no 3-component point array 'SurfacePoints'");
  // An empty Target gives an empty output, not an error: TestEmptyInputs.
  auto offSphere = vtkSmartPointer<vtkPolyData>::New();
  offSphere->DeepCopy(map);
  offSphere->GetPoints()->SetPoint(1, 0, 0, 3);
  failures += ExpectError(offSphere, map, "not on the unit sphere");
  return failures;
}
}

int TestDenseCorrespondence(int, char*[])
{
  int failures = TestSelfMapWithKnownRotation();
  failures += TestSelfMapThroughRegistration();
  failures += TestBadInputs();
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
