// Hostile input to the filters: every filter rejects a triangle that refers to a point out
// of range with an error (reading or writing out of bounds before), and a point or cell array
// whose tuple count is not the mesh's (a short target array was read past its end and
// carried over as garbage or NaN); an exception inside a
// filter (std::bad_alloc, or one carried out of a worker thread) becomes that filter's
// error instead of ending the program.
#include "MobiusTestUtilities.h"
#include "vtkCenteredSphericalMap.h"
#include "vtkCorrespondenceRefinement.h"
#include "vtkDenseCorrespondence.h"
#include "vtkLaplaceBeltramiBasis.h"
#include "vtkMobiusCenter.h"
#include "vtkMobiusRegistration.h"
#include "vtkSO3Register.h"
#include "vtkSphericalConformalMap.h"
#include "vtkSphericalOrbifoldMap.h"
#include "vtkSphericalScaleGrid.h"
#include "vtkSymmetryDetection.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkIntArray.h"

#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using mobius_test::BumpyMesh;

// A copy of `mesh` whose polygon `cell` has its vertex `corner` replaced by `id`.
vtkSmartPointer<vtkPolyData> WithPointId(
  vtkPolyData* mesh, vtkIdType cell, int corner, vtkIdType id)
{
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->DeepCopy(mesh);
  vtkNew<vtkCellArray> polys;
  vtkIdType npts;
  const vtkIdType* ids;
  vtkIdType c = 0;
  for (mesh->GetPolys()->InitTraversal(); mesh->GetPolys()->GetNextCell(npts, ids); ++c)
  {
    std::vector<vtkIdType> copy(ids, ids + npts);
    if (c == cell)
    {
      copy[corner] = id;
    }
    polys->InsertNextCell(npts, copy.data());
  }
  result->SetPolys(polys);
  return result;
}

int TestOutOfRangeIds()
{
  int failures = 0;
  auto mesh = BumpyMesh(2);
  const vtkIdType n = mesh->GetNumberOfPoints();
  for (vtkIdType bad : { n, n + 99999, vtkIdType(-5) })
  {
    const std::string words = "refers to point " + std::to_string(bad);
    vtkNew<vtkSphericalConformalMap> map;
    map->SetInputData(WithPointId(mesh, 7, 1, bad));
    failures += ExpectError(map, words);

    // A quad must be rejected before vtkTriangleFilter splits it (reading its points).
    auto quads = WithPointId(mesh, 7, 1, bad);
    vtkNew<vtkCellArray> polys;
    polys->DeepCopy(quads->GetPolys());
    const vtkIdType quad[4] = { 0, 1, bad, 2 };
    polys->InsertNextCell(4, quad);
    quads->SetPolys(polys);
    vtkNew<vtkSphericalConformalMap> quadMap;
    quadMap->SetInputData(quads);
    failures += ExpectError(quadMap, words);

    auto good = mobius_test::MakeSphericalMap(2, mobius_test::BumpySurface);
    auto bent = WithPointId(good, 11, 2, bad);
    vtkNew<vtkMobiusCenter> center;
    center->SetInputData(bent);
    failures += ExpectError(center, words);
    vtkNew<vtkSphericalScaleGrid> grid;
    grid->SetInputData(bent);
    grid->SetResolution(16);
    failures += ExpectError(grid, words);
    vtkNew<vtkSO3Register> registration;
    registration->SetSourceData(good);
    registration->SetTargetData(bent);
    registration->SetResolution(16);
    failures += ExpectError(registration, words);
    vtkNew<vtkDenseCorrespondence> correspondence;
    correspondence->SetSourceData(good);
    correspondence->SetTargetData(bent);
    failures += ExpectError(correspondence, words);
  }
  return failures;
}

// The executive reports progress 0 and 1 around RequestData; the filters report values
// between while they work.
// A copy of `mesh` with an array of `tuples` values added to its point data (or cell data).
vtkSmartPointer<vtkPolyData> WithArray(vtkPolyData* mesh, bool pointData, vtkIdType tuples)
{
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->DeepCopy(mesh);
  vtkNew<vtkDoubleArray> array;
  array->SetName("temperature");
  array->SetNumberOfComponents(2);
  array->SetNumberOfTuples(tuples);
  array->Fill(1.5);
  (pointData ? static_cast<vtkDataSetAttributes*>(result->GetPointData())
             : static_cast<vtkDataSetAttributes*>(result->GetCellData()))
    ->AddArray(array);
  return result;
}

int TestMismatchedArrays()
{
  int failures = 0;
  auto mesh = BumpyMesh(2);
  auto map = mobius_test::MakeSphericalMap(2, mobius_test::BumpySurface);
  // Every filter with inputs, each input given a mesh (the conformal map's kind of input) or
  // a spherical map (the others').
  struct Case
  {
    vtkSmartPointer<vtkPolyDataAlgorithm> Filter;
    bool TakesMesh;
  };
  const auto cases = [] {
    std::vector<Case> list = {
      { vtkSmartPointer<vtkSphericalConformalMap>::New(), true },
      { vtkSmartPointer<vtkCenteredSphericalMap>::New(), true },
      { vtkSmartPointer<vtkSymmetryDetection>::New(), false },
      { vtkSmartPointer<vtkSphericalOrbifoldMap>::New(), false },
      { vtkSmartPointer<vtkMobiusCenter>::New(), false },
      { vtkSmartPointer<vtkSphericalScaleGrid>::New(), false },
      { vtkSmartPointer<vtkLaplaceBeltramiBasis>::New(), false },
      { vtkSmartPointer<vtkSO3Register>::New(), false },
      { vtkSmartPointer<vtkDenseCorrespondence>::New(), false },
      { vtkSmartPointer<vtkCorrespondenceRefinement>::New(), false },
      { vtkSmartPointer<vtkMobiusRegistration>::New(), true },
    };
    return list;
  };
  for (const bool pointData : { true, false })
  {
    for (const int change : { -1, 1, -1000 })
    {
      for (const Case& c : cases())
      {
        vtkPolyData* base = c.TakesMesh ? mesh.Get() : map.Get();
        const vtkIdType count = pointData ? base->GetNumberOfPoints() : base->GetNumberOfCells();
        const vtkIdType tuples = std::max<vtkIdType>(0, count + change);
        const auto bad = WithArray(base, pointData, tuples);
        const int ports = c.Filter->GetNumberOfInputPorts();
        // The bad array on the last input (a two-input filter's Target).
        for (int port = 0; port < ports; ++port)
        {
          c.Filter->SetInputDataObject(port, port + 1 == ports ? bad.Get() : base);
        }
        const std::string input = ports == 2 ? "Target: " : "Input: ";
        failures += ExpectError(c.Filter, input + "the " + (pointData ? "point" : "cell") +
            " array 'temperature' has " + std::to_string(tuples) + " values (tuples) for " +
            std::to_string(count));
      }
    }
  }
  return failures;
}

bool InsideRequestData(void* progress)
{
  const double fraction = *static_cast<double*>(progress);
  return fraction > 0 && fraction < 1;
}

// An exception thrown while a filter runs (here by a progress observer, standing in for
// std::bad_alloc in a worker thread) is reported as the filter's error; nothing escapes.
int TestExceptionsBecomeErrors()
{
  int failures = 0;
  // VTK's InvokeEvent holds a reference to the command while it runs and does not give it
  // back when the command throws: each command counts its throws, and the references they
  // kept are given back at the end (AddressSanitizer's leak check found them).
  struct ThrowingCommand
  {
    vtkNew<vtkCallbackCommand> Command;
    int Throws = 0;
    ~ThrowingCommand()
    {
      for (; this->Throws > 0; --this->Throws)
      {
        this->Command->UnRegister(nullptr);
      }
    }
  };
  ThrowingCommand outOfMemory;
  outOfMemory.Command->SetClientData(&outOfMemory.Throws);
  outOfMemory.Command->SetCallback([](vtkObject*, unsigned long, void* throws, void* progress) {
    if (InsideRequestData(progress))
    {
      ++*static_cast<int*>(throws);
      throw std::bad_alloc();
    }
  });
  ThrowingCommand failing;
  failing.Command->SetClientData(&failing.Throws);
  failing.Command->SetCallback([](vtkObject*, unsigned long, void* throws, void* progress) {
    if (InsideRequestData(progress))
    {
      ++*static_cast<int*>(throws);
      throw std::runtime_error("observer failed");
    }
  });

  auto map = mobius_test::MakeSphericalMap(2, mobius_test::BumpySurface);
  vtkNew<vtkSphericalConformalMap> conformal;
  conformal->SetInputData(BumpyMesh(2));
  conformal->AddObserver(vtkCommand::ProgressEvent, outOfMemory.Command);
  failures += ExpectError(conformal, "out of memory");
  vtkNew<vtkMobiusCenter> center;
  center->SetInputData(map);
  center->AddObserver(vtkCommand::ProgressEvent, failing.Command);
  failures += ExpectError(center, "observer failed");
  vtkNew<vtkSphericalScaleGrid> grid;
  grid->SetInputData(map);
  grid->SetResolution(16);
  grid->AddObserver(vtkCommand::ProgressEvent, outOfMemory.Command);
  failures += ExpectError(grid, "out of memory");
  vtkNew<vtkSO3Register> registration;
  registration->SetSourceData(map);
  registration->SetTargetData(map);
  registration->SetResolution(16);
  registration->AddObserver(vtkCommand::ProgressEvent, outOfMemory.Command);
  failures += ExpectError(registration, "out of memory");
  vtkNew<vtkDenseCorrespondence> correspondence;
  correspondence->SetSourceData(map);
  correspondence->SetTargetData(map);
  correspondence->AddObserver(vtkCommand::ProgressEvent, failing.Command);
  failures += ExpectError(correspondence, "observer failed");
  return failures;
}

// A face listed twice (either way round) is named as a duplicate, not only through the three
// non-manifold edges it makes; so is the two-triangle "pillow" FillHoles makes of a single
// triangle, which has no inside to map (its flow's distortion was infinite).
int TestDuplicateTriangles()
{
  int failures = 0;
  auto mesh = BumpyMesh(2);
  for (bool reversed : { false, true })
  {
    auto doubled = vtkSmartPointer<vtkPolyData>::New();
    doubled->DeepCopy(mesh);
    vtkIdType npts;
    const vtkIdType* ids;
    doubled->GetPolys()->GetCellAtId(5, npts, ids);
    const vtkIdType copy[3] = { ids[0], reversed ? ids[2] : ids[1], reversed ? ids[1] : ids[2] };
    doubled->GetPolys()->InsertNextCell(3, copy);
    vtkNew<vtkSphericalConformalMap> map;
    map->SetInputData(doubled);
    map->RepairOff();
    failures += ExpectError(map, "1 duplicate triangle");
  }
  vtkNew<vtkPolyData> triangle;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  triangle->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  const vtkIdType corners[3] = { 0, 1, 2 };
  polys->InsertNextCell(3, corners);
  triangle->SetPolys(polys);
  vtkNew<vtkSphericalConformalMap> pillow;
  pillow->SetInputData(triangle);
  pillow->RepairOff();
  pillow->FillHolesOn();
  failures += ExpectError(pillow, "1 duplicate triangle");
  return failures;
}

// A closed, manifold surface with no orientation (the projective plane in 6 vertices) says so.
int TestNonOrientable()
{
  int failures = 0;
  vtkNew<vtkPoints> points;
  const double positions[6][3] = { { 0.1, 0.2, 0.9 }, { 0.8, 0.1, 0.3 }, { 0.4, 0.9, 0.2 },
    { 0.7, 0.6, 0.9 }, { 0.2, 0.8, 0.6 }, { 0.9, 0.4, 0.5 } };
  for (const auto& p : positions)
  {
    points->InsertNextPoint(p);
  }
  vtkNew<vtkCellArray> polys;
  const vtkIdType faces[10][3] = { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 3, 4 }, { 0, 4, 5 }, { 0, 5, 1 },
    { 1, 2, 4 }, { 2, 3, 5 }, { 3, 4, 1 }, { 4, 5, 2 }, { 5, 1, 3 } };
  for (const auto& face : faces)
  {
    polys->InsertNextCell(3, face);
  }
  vtkNew<vtkPolyData> plane;
  plane->SetPoints(points);
  plane->SetPolys(polys);
  vtkNew<vtkSphericalConformalMap> map;
  map->SetInputData(plane);
  map->RepairOff();
  failures += ExpectError(map, "the surface is not orientable");
  return failures;
}
}

// Scale does not matter where the areas are double-precision numbers (coordinates of 1e-100
// had "zero-area triangles", 1e100 "no area"); beyond, the error says so.
int TestExtremeScales()
{
  int failures = 0;
  auto mesh = BumpyMesh(2);
  for (const double scale : { 1e-100, 1e100, 1e200 })
  {
    auto scaled = vtkSmartPointer<vtkPolyData>::New();
    scaled->DeepCopy(mesh);
    for (vtkIdType i = 0; i < scaled->GetNumberOfPoints(); ++i)
    {
      double p[3];
      mesh->GetPoint(i, p);
      scaled->GetPoints()->SetPoint(i, scale * p[0], scale * p[1], scale * p[2]);
    }
    vtkNew<vtkSphericalConformalMap> map;
    map->SetInputData(scaled);
    if (scale > 1e150) // areas of 1e400
    {
      failures += ExpectError(map, "beyond what double precision represents");
      continue;
    }
    map->Update();
    vtkPolyData* output = map->GetOutput();
    MOBIUS_EXPECT(output->GetNumberOfPoints() == scaled->GetNumberOfPoints());
    vtkDataArray* degenerate = output->GetFieldData()->GetArray("DegenerateMap");
    MOBIUS_EXPECT(degenerate && degenerate->GetTuple1(0) == 0);
    // The original positions come back exactly.
    vtkDataArray* surface = output->GetPointData()->GetArray("SurfacePoints");
    vtkDataArray* ids = output->GetPointData()->GetArray("InputPointId");
    MOBIUS_EXPECT(surface && ids &&
      surface->GetComponent(7, 1) == scaled->GetPoint(static_cast<vtkIdType>(ids->GetTuple1(7)))[1]);
  }
  return failures;
}

int TestFilterErrors(int, char*[])
{
  int failures = 0;
  failures += TestOutOfRangeIds();
  failures += TestMismatchedArrays();
  failures += TestExceptionsBecomeErrors();
  failures += TestDuplicateTriangles();
  failures += TestNonOrientable();
  failures += TestExtremeScales();
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
