// Vertex numbering through the filters: vtkSphericalConformalMap's InputPointId names the
// input point each output point came from, through the repairs (an unused point dropped,
// a hole filled with a new point, -1), and vtkMobiusCenter, vtkSO3Register and
// vtkDenseCorrespondence carry it on, so a map can be read in both inputs' numbering.
#include "MobiusTestUtilities.h"
#include "vtkDenseCorrespondence.h"
#include "vtkMobiusCenter.h"
#include "vtkSO3Register.h"
#include "vtkSphericalConformalMap.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace
{
using mobius_test::BumpyMesh;

// `mesh` with its points renumbered: new point k is old point order[k]; an entry -1 adds a
// point no polygon uses; polygons in `skip` are left out.
vtkSmartPointer<vtkPolyData> Renumbered(
  vtkPolyData* mesh, const std::vector<vtkIdType>& order, const std::vector<vtkIdType>& skip = {})
{
  std::vector<vtkIdType> newId(mesh->GetNumberOfPoints(), -1);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (size_t k = 0; k < order.size(); ++k)
  {
    double p[3] = { 50.0 + k, 50, 50 };
    if (order[k] >= 0)
    {
      mesh->GetPoint(order[k], p);
      newId[order[k]] = static_cast<vtkIdType>(k);
    }
    points->InsertNextPoint(p);
  }
  vtkNew<vtkCellArray> polys;
  vtkIdType npts;
  const vtkIdType* ids;
  vtkIdType c = 0;
  for (mesh->GetPolys()->InitTraversal(); mesh->GetPolys()->GetNextCell(npts, ids); ++c)
  {
    if (std::find(skip.begin(), skip.end(), c) != skip.end())
    {
      continue;
    }
    std::vector<vtkIdType> renumbered(ids, ids + npts);
    for (auto& id : renumbered)
    {
      id = newId[id];
    }
    polys->InsertNextCell(npts, renumbered.data());
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->SetPoints(points);
  result->SetPolys(polys);
  return result;
}

// The source has an unused point in front (all its numbers are one more than the target's),
// the target its points in reverse order: after mapping both and registering the source
// with the target (the same shape), each source point's nearest target point must be the
// same surface point, which the input numbers must say.
int TestNumberingThroughThePipeline()
{
  int failures = 0;
  auto mesh = BumpyMesh(3);
  const vtkIdType n = mesh->GetNumberOfPoints();
  std::vector<vtkIdType> shifted(n + 1), reversed(n);
  shifted[0] = -1;
  std::iota(shifted.begin() + 1, shifted.end(), 0);
  for (vtkIdType k = 0; k < n; ++k)
  {
    reversed[k] = n - 1 - k;
  }
  vtkSmartPointer<vtkPolyData> centered[2];
  vtkSmartPointer<vtkPolyData> inputs[2] = { Renumbered(mesh, shifted),
    Renumbered(mesh, reversed) };
  for (int k = 0; k < 2; ++k)
  {
    vtkNew<vtkSphericalConformalMap> map;
    map->SetInputData(inputs[k]);
    vtkNew<vtkMobiusCenter> center;
    center->SetInputConnection(map->GetOutputPort());
    center->Update();
    centered[k] = center->GetOutput();
    // InputPointId names the input point the output point came from.
    vtkDataArray* ids = centered[k]->GetPointData()->GetArray("InputPointId");
    vtkDataArray* surface = centered[k]->GetPointData()->GetArray("SurfacePoints");
    MOBIUS_EXPECT(ids && surface && centered[k]->GetNumberOfPoints() == n);
    for (vtkIdType i = 0; ids && surface && i < centered[k]->GetNumberOfPoints(); ++i)
    {
      const auto id = static_cast<vtkIdType>(ids->GetComponent(i, 0));
      double p[3], q[3];
      surface->GetTuple(i, p);
      inputs[k]->GetPoint(id, q);
      MOBIUS_EXPECT(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]);
    }
  }
  vtkNew<vtkSO3Register> registration;
  registration->SetSourceData(centered[0]);
  registration->SetTargetData(centered[1]);
  registration->SetResolution(64);
  vtkNew<vtkDenseCorrespondence> correspondence;
  correspondence->SetInputConnection(0, registration->GetOutputPort());
  correspondence->SetTargetData(centered[1]);
  correspondence->Update();
  vtkPointData* data = correspondence->GetOutput()->GetPointData();
  vtkDataArray* sourceIds = data->GetArray("InputPointId");
  vtkDataArray* nearestIds = data->GetArray("InputPointId_Target");
  vtkDataArray* cornerIds = data->GetArray("TargetInputPointIds");
  MOBIUS_EXPECT(sourceIds && nearestIds && cornerIds && cornerIds->GetNumberOfComponents() == 3);
  vtkIdType matched = 0, total = correspondence->GetOutput()->GetNumberOfPoints();
  for (vtkIdType i = 0; sourceIds && nearestIds && cornerIds && i < total; ++i)
  {
    // Source input point s is mesh point s - 1, which is target input point n - s.
    const auto expected = n - static_cast<vtkIdType>(sourceIds->GetComponent(i, 0));
    const auto nearest = static_cast<vtkIdType>(nearestIds->GetComponent(i, 0));
    matched += nearest == expected ? 1 : 0;
    bool corner = false;
    for (int k = 0; k < 3; ++k)
    {
      corner = corner || static_cast<vtkIdType>(cornerIds->GetComponent(i, k)) == nearest;
    }
    MOBIUS_EXPECT(corner);
  }
  if (matched < 0.99 * total || total != n)
  {
    std::cerr << matched << " of " << total << " points (mesh: " << n
              << ") map to their own input number\n";
    ++failures;
  }
  return failures;
}

// FillHoles creates a point: its InputPointId is -1, the others keep their numbers.
int TestCreatedPoint()
{
  int failures = 0;
  auto mesh = BumpyMesh(2);
  std::vector<vtkIdType> same(mesh->GetNumberOfPoints());
  std::iota(same.begin(), same.end(), 0);
  // Two triangles sharing an edge: a hole bounded by four edges, filled with a fan around a
  // new point.
  vtkIdType npts;
  const vtkIdType* ids;
  mesh->GetPolys()->GetCellAtId(0, npts, ids);
  const std::vector<vtkIdType> first(ids, ids + 3);
  vtkIdType neighbour = -1;
  for (vtkIdType c = 1; c < mesh->GetNumberOfPolys() && neighbour < 0; ++c)
  {
    mesh->GetPolys()->GetCellAtId(c, npts, ids);
    int shared = 0;
    for (int k = 0; k < 3; ++k)
    {
      shared += std::count(first.begin(), first.end(), ids[k]) ? 1 : 0;
    }
    neighbour = shared == 2 ? c : -1;
  }
  vtkNew<vtkSphericalConformalMap> map;
  map->SetInputData(Renumbered(mesh, same, { 0, neighbour }));
  map->FillHolesOn();
  map->Update();
  vtkDataArray* inputIds = map->GetOutput()->GetPointData()->GetArray("InputPointId");
  MOBIUS_EXPECT(inputIds && map->GetOutput()->GetNumberOfPoints() == mesh->GetNumberOfPoints() + 1);
  vtkIdType created = 0;
  for (vtkIdType i = 0; inputIds && i < inputIds->GetNumberOfTuples(); ++i)
  {
    const auto id = static_cast<vtkIdType>(inputIds->GetComponent(i, 0));
    created += id == -1 ? 1 : 0;
    MOBIUS_EXPECT(id == -1 || id == i);
  }
  MOBIUS_EXPECT(created == 1);
  return failures;
}

}

int TestInputPointIds(int, char*[])
{
  int failures = 0;
  failures += TestNumberingThroughThePipeline();
  failures += TestCreatedPoint();
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
