// vtkSphericalScaleGrid: area conservation through the filter, the grid's layout and
// orientation, the rotation-invariant degree energies, the displaced picture, and clear
// errors.
#include "MobiusTestUtilities.h"
#include "vtkMobiusCenter.h"
#include "vtkSphericalScaleGrid.h"

#include "vtkExecutive.h"
#include "vtkPolygon.h"

namespace
{
vtkSmartPointer<vtkPolyData> CenteredBumpyMap()
{
  auto map = mobius_test::MakeSphericalMap(4, mobius_test::BumpySurface, { 0.3, 0.1, -0.2 });
  vtkNew<vtkMobiusCenter> center;
  center->SetInputData(map);
  center->Update();
  return center->GetOutput();
}

double SurfaceAreaOf(vtkPolyData* map)
{
  double total = 0;
  vtkDataArray* areas = map->GetCellData()->GetArray("SurfaceArea");
  for (vtkIdType t = 0; t < areas->GetNumberOfTuples(); ++t)
  {
    total += areas->GetTuple1(t);
  }
  return total;
}

// Exact spherical area of grid row j of an N x N grid.
double CellArea(int N, int j)
{
  return 2 * vtkMath::Pi() / N *
    (std::cos(vtkMath::Pi() * j / N) - std::cos(vtkMath::Pi() * (j + 1) / N));
}

int TestConservationAndLayout()
{
  int failures = 0;
  auto map = CenteredBumpyMap();
  const double area = SurfaceAreaOf(map);
  const int N = 64;
  for (int mode : { vtkSphericalScaleGrid::AREA_RATIO, vtkSphericalScaleGrid::SQUARE_ROOT_AREA_RATIO })
  {
    vtkNew<vtkSphericalScaleGrid> grid;
    grid->SetInputData(map);
    grid->SetResolution(N);
    grid->SetValueMode(mode);
    grid->Update();
    vtkPolyData* out = grid->GetOutput();
    MOBIUS_EXPECT(out->GetNumberOfCells() == N * N);
    MOBIUS_EXPECT(out->GetNumberOfPoints() == (N - 1) * N + 2);
    vtkDataArray* values = out->GetCellData()->GetArray("ConformalFactor");
    vtkDataArray* smoothed = out->GetCellData()->GetArray("ConformalFactorSmoothed");
    MOBIUS_EXPECT(values && smoothed);
    // sum lambda * cell area = surface area (sqrt mode: the squares).
    double total = 0;
    for (int j = 0; j < N; ++j)
    {
      for (int i = 0; i < N; ++i)
      {
        const double v = values->GetTuple1(j * N + i);
        total += (mode == vtkSphericalScaleGrid::AREA_RATIO ? v : v * v) * CellArea(N, j);
      }
    }
    MOBIUS_EXPECT(std::abs(total - area) <= 1e-9 * area);
    MOBIUS_EXPECT(std::abs(mobius_test::FieldValue(out, "TotalArea") - area) <= 1e-9 * area);
    MOBIUS_EXPECT(mobius_test::FieldValue(out, "Bandwidth") == N / 2);
    MOBIUS_EXPECT(mobius_test::FieldValue(out, "ValueMode") == mode);

    // Every cell faces outward, and cell j*N + i is centered at theta_j, phi_i.
    int inward = 0;
    double maxCenterError = 0;
    for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
    {
      vtkIdType npts;
      const vtkIdType* ids;
      out->GetCellPoints(c, npts, ids);
      double normal[3], centroid[3] = { 0, 0, 0 };
      vtkPolygon::ComputeNormal(out->GetPoints(), static_cast<int>(npts), ids, normal);
      for (vtkIdType k = 0; k < npts; ++k)
      {
        double p[3];
        out->GetPoint(ids[k], p);
        for (int d = 0; d < 3; ++d)
        {
          centroid[d] += p[d] / npts;
        }
      }
      inward += vtkMath::Dot(normal, centroid) <= 0;
      const int j = static_cast<int>(c / N), i = static_cast<int>(c % N);
      const double phi = std::atan2(centroid[1], centroid[0]);
      const double expectedPhi = 2 * vtkMath::Pi() * (i + 0.5) / N;
      maxCenterError = std::max(maxCenterError,
        std::abs(std::remainder(phi - expectedPhi, 2 * vtkMath::Pi())));
      const double theta = std::acos(centroid[2] / vtkMath::Norm(centroid));
      MOBIUS_EXPECT(theta >= vtkMath::Pi() * j / N && theta <= vtkMath::Pi() * (j + 1) / N);
    }
    MOBIUS_EXPECT(inward == 0);
    MOBIUS_EXPECT(maxCenterError < 1e-9);
  }
  return failures;
}

vtkSmartPointer<vtkDoubleArray> DegreeEnergiesOf(vtkPolyData* map, int resolution)
{
  vtkNew<vtkSphericalScaleGrid> grid;
  grid->SetInputData(map);
  grid->SetResolution(resolution);
  grid->Update();
  auto energies = vtkDoubleArray::SafeDownCast(grid->GetOutput()->GetFieldData()->GetArray("DegreeEnergies"));
  return energies;
}

// E_0 is the squared mean term, (integral of f)^2 / (4 pi), which smoothing leaves alone; a
// rotated or mirrored copy of the map has the same energies (up to the grid's sampling of a
// different position); a flattened ellipsoid differs 40 times more.
int TestDegreeEnergies()
{
  int failures = 0;
  auto map = CenteredBumpyMap();
  const int N = 64;
  auto energies = DegreeEnergiesOf(map, N);
  MOBIUS_EXPECT(energies && energies->GetNumberOfValues() == N / 2);
  if (!energies)
  {
    return failures;
  }
  vtkNew<vtkSphericalScaleGrid> grid;
  grid->SetInputData(map);
  grid->SetResolution(N);
  grid->Update();
  vtkDataArray* values = grid->GetOutput()->GetCellData()->GetArray("ConformalFactor");
  double integral = 0;
  for (int j = 0; j < N; ++j)
  {
    for (int i = 0; i < N; ++i)
    {
      integral += values->GetTuple1(j * N + i) * CellArea(N, j);
    }
  }
  const double e0 = integral * integral / (4 * vtkMath::Pi());
  // The transform's quadrature treats cell means as center samples: 2e-5 apart at N = 64.
  MOBIUS_EXPECT(std::abs(energies->GetValue(0) - e0) <= 1e-4 * e0);

  // The map turned by a rotation about a tilted axis, then also mirrored (x -> -x).
  const Eigen::Matrix3d rotation =
    Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  for (bool mirror : { false, true })
  {
    auto turned = vtkSmartPointer<vtkPolyData>::New();
    turned->DeepCopy(map);
    for (vtkIdType p = 0; p < turned->GetNumberOfPoints(); ++p)
    {
      double x[3];
      turned->GetPoint(p, x);
      Eigen::Vector3d y = rotation * Eigen::Vector3d(x[0], x[1], x[2]);
      if (mirror)
      {
        y.x() = -y.x();
      }
      turned->GetPoints()->SetPoint(p, y.data());
    }
    auto turnedEnergies = DegreeEnergiesOf(turned, N);
    double worst = 0;
    for (int l = 0; l < 8; ++l)
    {
      worst = std::max(worst, std::abs(turnedEnergies->GetValue(l) - energies->GetValue(l)) / e0);
    }
    MOBIUS_EXPECT(worst < 2e-4); // 5e-5 measured
  }

  // A differently shaped surface has clearly different energies beyond degree 0.
  auto other = mobius_test::MakeSphericalMap(4, [](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(1.8 * x.x(), x.y(), 0.6 * x.z());
  }, { 0, 0, 0 });
  vtkNew<vtkMobiusCenter> center;
  center->SetInputData(other);
  center->Update();
  auto otherEnergies = DegreeEnergiesOf(center->GetOutput(), N);
  double difference = 0;
  for (int l = 1; l < 8; ++l)
  {
    difference = std::max(difference, std::abs(otherEnergies->GetValue(l) - energies->GetValue(l)) / e0);
  }
  MOBIUS_EXPECT(difference > 2e-3); // 8e-3 measured
  return failures;
}

int TestDisplacement()
{
  int failures = 0;
  vtkNew<vtkSphericalScaleGrid> grid;
  grid->SetInputData(CenteredBumpyMap());
  grid->SetResolution(32);
  grid->DisplaceByValueOn();
  grid->Update();
  double largest = 0, smallest = 2;
  for (vtkIdType i = 0; i < grid->GetOutput()->GetNumberOfPoints(); ++i)
  {
    double p[3];
    grid->GetOutput()->GetPoint(i, p);
    largest = std::max(largest, vtkMath::Norm(p));
    smallest = std::min(smallest, vtkMath::Norm(p));
  }
  MOBIUS_EXPECT(std::abs(largest - 1) < 1e-12);
  MOBIUS_EXPECT(smallest < 0.9); // the bumpy blob's factors vary
  return failures;
}

int ExpectError(vtkPolyData* input, int resolution, const std::string& words)
{
  int failures = 0;
  vtkNew<vtkSphericalScaleGrid> grid;
  mobius_test::MessageCatcher catcher(grid);
  mobius_test::MessageCatcher executiveCatcher(grid->GetExecutive());
  grid->SetInputData(input);
  grid->SetResolution(resolution);
  grid->Update();
  if (catcher.Error.find(words) == std::string::npos)
  {
    std::cerr << "expected an error containing '" << words << "', got '" << catcher.Error << "'\n";
    ++failures;
  }
  MOBIUS_EXPECT(grid->GetOutput()->GetNumberOfCells() == 0);
  return failures;
}

int TestBadInputs()
{
  int failures = 0;
  auto map = CenteredBumpyMap();
  failures += ExpectError(map, 63, "even and at least 4");
  failures += ExpectError(map, 2, "even and at least 4");
  auto offSphere = mobius_test::MakeSphericalMap(2, mobius_test::BumpySurface);
  offSphere->GetPoints()->SetPoint(0, 0.5, 0, 0);
  failures += ExpectError(offSphere, 16, "not on the unit sphere");
  auto noArea = mobius_test::MakeSphericalMap(2, mobius_test::BumpySurface);
  noArea->GetCellData()->RemoveArray("SurfaceArea");
  failures += ExpectError(noArea, 16, "SurfaceArea");
  // An empty input gives an empty output, not an error: TestEmptyInputs.
  return failures;
}
}

int TestSphericalScaleGrid(int, char*[])
{
  int failures = TestConservationAndLayout();
  failures += TestDegreeEnergies();
  failures += TestDisplacement();
  failures += TestBadInputs();
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
