// vtkMobiusRegistration against the stage filters chained by hand (conformal map and
// centering of each mesh, vtkSO3Register, vtkCorrespondenceRefinement or
// vtkDenseCorrespondence) on CGAL's cow and bull: the same map, bit for bit, and the
// stages' field data under their stage names. Errors name the mesh by SourceName.
#include "MobiusTestUtilities.h"
#include "vtkCenteredSphericalMap.h"
#include "vtkCorrespondenceRefinement.h"
#include "vtkDenseCorrespondence.h"
#include "vtkMobiusCenter.h"
#include "vtkMobiusRegistration.h"
#include "vtkSO3Register.h"
#include "vtkSphericalConformalMap.h"
#include "vtkSurfaceMeshReader.h"

#include "vtkCellArray.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkPoints.h"
#include "vtkStringArray.h"

#ifndef MOBIUS_MESH_DIR
#error "TestMobiusRegistration needs CGAL's meshes (MOBIUS_MESH_DIR); CMake lists it only with them"
#endif

namespace
{
vtkSmartPointer<vtkPolyData> Read(const char* path)
{
  vtkNew<vtkSurfaceMeshReader> reader;
  reader->SetFileName(path);
  reader->Update();
  return reader->GetOutput();
}

// The arrays of `name` in both outputs hold the same values, bit for bit.
int ExpectSameArray(vtkDataArray* a, vtkDataArray* b, const std::string& name)
{
  if (!a || !b || a->GetNumberOfTuples() != b->GetNumberOfTuples() ||
    a->GetNumberOfComponents() != b->GetNumberOfComponents())
  {
    std::cerr << name << ": missing or of another shape\n";
    return 1;
  }
  for (vtkIdType t = 0; t < a->GetNumberOfTuples(); ++t)
  {
    for (int c = 0; c < a->GetNumberOfComponents(); ++c)
    {
      if (a->GetComponent(t, c) != b->GetComponent(t, c))
      {
        std::cerr << name << ": differs at tuple " << t << "\n";
        return 1;
      }
    }
  }
  return 0;
}

// The filter's output and the hand-made chain's, with refinement or without.
// Port 3, the map on the target's own mesh: the target's points and triangles, and for each
// vertex a source triangle and weights at which the source placed by the map (port 0's
// MappedPoints) lies next to the vertex. The refined map's placed source covers the target
// surface (within an edge: 0.6% of the diagonal on the bull); the Moebius map's leaves gaps
// (4%).
int CheckMapOnTarget(
  vtkPolyData* onTarget, vtkPolyData* correspondence, vtkPolyData* target, bool refined)
{
  int failures = 0;
  MOBIUS_EXPECT(onTarget->GetNumberOfPoints() == target->GetNumberOfPoints());
  MOBIUS_EXPECT(onTarget->GetNumberOfPolys() == target->GetNumberOfPolys());
  vtkDataArray* cells = onTarget->GetPointData()->GetArray("SourceCellId");
  vtkDataArray* weights = onTarget->GetPointData()->GetArray("SourceBarycentric");
  vtkDataArray* mapped = correspondence->GetPointData()->GetArray("MappedPoints");
  MOBIUS_EXPECT(onTarget->GetPointData()->GetArray("SourcePoints") != nullptr);
  if (!cells || !weights || !mapped || failures > 0)
  {
    std::cerr << "port 3 lacks SourceCellId or SourceBarycentric\n";
    return failures + 1;
  }
  double sum = 0;
  for (vtkIdType i = 0; i < onTarget->GetNumberOfPoints(); ++i)
  {
    vtkNew<vtkIdList> corners;
    correspondence->GetCellPoints(static_cast<vtkIdType>(cells->GetComponent(i, 0)), corners);
    double placed[3] = { 0, 0, 0 }, point[3];
    for (int k = 0; k < 3; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        placed[c] += weights->GetComponent(i, k) * mapped->GetComponent(corners->GetId(k), c);
      }
    }
    onTarget->GetPoint(i, point);
    sum += std::sqrt(vtkMath::Distance2BetweenPoints(placed, point));
  }
  const double meanDistance = sum / onTarget->GetNumberOfPoints();
  std::cout << "map on the target: mean distance to the placed source " << meanDistance
            << " (target diagonal " << target->GetLength() << ")\n";
  MOBIUS_EXPECT(meanDistance < (refined ? 0.01 : 0.1) * target->GetLength());
  return failures;
}

int CompareWithChain(vtkPolyData* source, vtkPolyData* target, bool refine)
{
  int failures = 0;
  const int resolution = 64;
  vtkNew<vtkMobiusRegistration> whole;
  whole->SetSourceData(source);
  whole->SetTargetData(target);
  whole->SetResolution(resolution);
  whole->SetRefine(refine);
  {
    mobius_test::MessageCatcher catcher(whole);
    whole->Update();
    if (!catcher.Error.empty() || whole->GetOutput()->GetNumberOfPoints() == 0)
    {
      std::cerr << "vtkMobiusRegistration failed: " << catcher.Error << std::endl;
      return 1;
    }
  }

  vtkNew<vtkSphericalConformalMap> sourceMap, targetMap;
  sourceMap->SetInputData(source);
  targetMap->SetInputData(target);
  vtkNew<vtkMobiusCenter> sourceCentered, targetCentered;
  sourceCentered->SetInputConnection(sourceMap->GetOutputPort());
  targetCentered->SetInputConnection(targetMap->GetOutputPort());
  vtkNew<vtkSO3Register> registration;
  registration->SetSourceConnection(sourceCentered->GetOutputPort());
  registration->SetTargetConnection(targetCentered->GetOutputPort());
  registration->SetResolution(resolution);
  vtkSmartPointer<vtkPolyDataAlgorithm> last;
  if (refine)
  {
    last = vtkSmartPointer<vtkCorrespondenceRefinement>::New();
  }
  else
  {
    last = vtkSmartPointer<vtkDenseCorrespondence>::New();
  }
  last->SetInputConnection(0, registration->GetOutputPort());
  last->SetInputConnection(1, targetCentered->GetOutputPort());
  last->Update();

  vtkPolyData* a = whole->GetOutput();
  vtkPolyData* b = last->GetOutput();
  MOBIUS_EXPECT(a->GetNumberOfPoints() == source->GetNumberOfPoints());
  MOBIUS_EXPECT(a->GetNumberOfPoints() == b->GetNumberOfPoints());
  MOBIUS_EXPECT(a->GetNumberOfCells() == b->GetNumberOfCells());
  if (!a->GetPoints() || !b->GetPoints())
  {
    std::cerr << "an output has no points" << std::endl;
    return failures + 1;
  }
  for (const char* name : { "TargetCellId", "TargetBarycentric", "MappedPoints", "InputPointId" })
  {
    failures += ExpectSameArray(a->GetPointData()->GetArray(name), b->GetPointData()->GetArray(name), name);
  }
  failures += ExpectSameArray(a->GetPoints()->GetData(), b->GetPoints()->GetData(), "points");
  // The stages' field data under their names.
  auto field = [](vtkPolyData* data, const std::string& name) {
    return data->GetFieldData()->GetArray(name.c_str());
  };
  failures += ExpectSameArray(field(a, "Registration.Rotation"),
    field(registration->GetOutput(), "Rotation"), "Registration.Rotation");
  failures += ExpectSameArray(field(a, "SourceMap.MeanQuasiConformalDistortion"),
    field(sourceMap->GetOutput(), "MeanQuasiConformalDistortion"), "SourceMap distortion");
  failures += ExpectSameArray(field(a, "TargetCentering.CenterOfMassNorm"),
    field(targetCentered->GetOutput(), "CenterOfMassNorm"), "TargetCentering.CenterOfMassNorm");
  // Flags and small counts are vtkIntArray, counts of mesh elements vtkIdTypeArray
  // (docs/data-contract.md), through the stage prefixes too.
  for (const char* name : { "SourceMap.DegenerateMap", "SourceMap.ConformalFlowIterations",
         "Registration.Determinant", "TargetCentering.CenteringDegree" })
  {
    MOBIUS_EXPECT(field(a, name) && field(a, name)->IsA("vtkIntArray"));
  }
  MOBIUS_EXPECT(field(a, "SourceMap.FlippedTriangles") &&
    field(a, "SourceMap.FlippedTriangles")->IsA("vtkIdTypeArray"));
  MOBIUS_EXPECT(field(a, "Registration.Determinant") &&
    field(a, "Registration.Determinant")->GetComponent(0, 0) == 1);
  // Ports 1 and 2: the aligned source sphere and the target sphere, the chain's.
  failures += ExpectSameArray(whole->GetOutput(1)->GetPoints()->GetData(),
    registration->GetOutput()->GetPoints()->GetData(), "port 1 points");
  failures += ExpectSameArray(whole->GetOutput(2)->GetPoints()->GetData(),
    targetCentered->GetOutput()->GetPoints()->GetData(), "port 2 points");
  failures += CheckMapOnTarget(whole->GetOutput(3), a, target, refine);
  MOBIUS_EXPECT((field(a, "MobiusCorrespondence.ClampedPoints") != nullptr) == refine);
  MOBIUS_EXPECT((field(a, "RefinementOrthogonalityResidual") != nullptr) == refine);
  // The refinement's confidence reaches the filter's output (ParaView's Information panel):
  // the sentence on the choice names the kept candidate, and the kept map's stretch is
  // measured.
  auto summary = vtkStringArray::SafeDownCast(
    a->GetFieldData()->GetAbstractArray("RefinementChoiceSummary"));
  MOBIUS_EXPECT((summary != nullptr) == refine);
  if (refine && summary && field(a, "RefinementCandidate") && field(a, "CandidateMapStretch"))
  {
    const int kept = static_cast<int>(field(a, "RefinementCandidate")->GetComponent(0, 0));
    const std::string opening = "Candidate " + std::to_string(kept) + " kept by ";
    MOBIUS_EXPECT(summary->GetValue(0).rfind(opening, 0) == 0);
    MOBIUS_EXPECT(field(a, "CandidateMapStretch")->GetComponent(kept, 0) >= 0);
    std::cout << summary->GetValue(0) << "\n";
  }
  std::cout << (refine ? "refined" : "Moebius") << " map: " << a->GetNumberOfPoints()
            << " points, " << a->GetFieldData()->GetNumberOfArrays() << " field arrays\n";
  return failures;
}

// vtkCenteredSphericalMap, the first stages for one mesh: the stage filters' chain bit for
// bit, both stages' field data, and the job's rules (a centering degree out of range).
int CenteredMapMatchesChain(vtkPolyData* mesh)
{
  int failures = 0;
  vtkNew<vtkCenteredSphericalMap> centered;
  centered->SetInputData(mesh);
  centered->Update();
  vtkNew<vtkSphericalConformalMap> map;
  map->SetInputData(mesh);
  vtkNew<vtkMobiusCenter> center;
  center->SetInputConnection(map->GetOutputPort());
  center->Update();
  vtkPolyData* output = centered->GetOutput();
  MOBIUS_EXPECT(output->GetNumberOfPoints() == center->GetOutput()->GetNumberOfPoints());
  if (failures > 0)
  {
    return failures;
  }
  failures += ExpectSameArray(
    output->GetPoints()->GetData(), center->GetOutput()->GetPoints()->GetData(), "centered map");
  for (const char* name : { "MeanQuasiConformalDistortion", "DegenerateMap", "CenterOfMassNorm" })
  {
    MOBIUS_EXPECT(output->GetFieldData()->GetArray(name) != nullptr);
  }
  vtkNew<vtkCenteredSphericalMap> misset;
  misset->SetInputData(mesh);
  misset->SetCenteringDegree(9);
  mobius_test::MessageCatcher catcher(misset);
  mobius_test::MessageCatcher executiveCatcher(misset->GetExecutive());
  misset->Update();
  std::cout << "centering degree 9: " << catcher.Error << "\n";
  MOBIUS_EXPECT(catcher.Error.find("CenteringDegree") != std::string::npos);
  MOBIUS_EXPECT(misset->GetOutput()->GetNumberOfPoints() == 0);
  return failures;
}

// The cow and a turned copy sharing its cell array (as a vtkTransformFilter's output does),
// mapped side by side on two threads: the same map as on one thread, every time. The two
// conformal maps read the shared cells at once; through the array's own traversal cursor
// they corrupted each other's triangles (a crash, or a wrong map, about one run in three).
int SharedCellsSideBySide(vtkPolyData* cow)
{
  int failures = 0;
  vtkNew<vtkPolyData> turned;
  turned->SetPolys(cow->GetPolys());
  vtkNew<vtkPoints> points;
  points->SetNumberOfPoints(cow->GetNumberOfPoints());
  for (vtkIdType i = 0; i < cow->GetNumberOfPoints(); ++i)
  {
    double p[3];
    cow->GetPoint(i, p);
    points->SetPoint(i, -p[1], p[0], p[2]);
  }
  turned->SetPoints(points);
  auto run = [&](int threads) {
    vtkNew<vtkMobiusRegistration> whole;
    whole->SetSourceData(cow);
    whole->SetTargetData(turned);
    whole->SetResolution(16);
    whole->SetRefine(false);
    whole->SetNumberOfThreads(threads);
    whole->Update();
    return vtkSmartPointer<vtkDataArray>(whole->GetOutput()->GetPointData()->GetArray("MappedPoints"));
  };
  auto inTurn = run(1);
  MOBIUS_EXPECT(inTurn != nullptr);
  for (int repeat = 0; repeat < 8 && inTurn; ++repeat)
  {
    failures += ExpectSameArray(run(2), inTurn, "MappedPoints (shared cells, two threads)");
  }
  return failures;
}
}

int TestMobiusRegistration(int, char*[])
{
  int failures = 0;
  auto cow = Read(MOBIUS_MESH_DIR "/cow.off");
  auto bull = Read(MOBIUS_MESH_DIR "/bull.off");
  if (cow->GetNumberOfPoints() < 1000 || bull->GetNumberOfPoints() < 1000)
  {
    std::cerr << "FAILED: cannot read CGAL's cow and bull in " MOBIUS_MESH_DIR "\n";
    return EXIT_FAILURE;
  }
  failures += CompareWithChain(cow, bull, true);
  failures += CompareWithChain(cow, bull, false);
  failures += SharedCellsSideBySide(cow);
  failures += CenteredMapMatchesChain(cow);

  // An open source mesh: an error naming it and the property that closes holes.
  vtkNew<vtkPolyData> open;
  open->DeepCopy(cow);
  vtkNew<vtkCellArray> triangles; // all but the first: a hole
  for (vtkIdType t = 1; t < cow->GetNumberOfCells(); ++t)
  {
    vtkNew<vtkIdList> ids;
    cow->GetCellPoints(t, ids);
    triangles->InsertNextCell(ids);
  }
  open->SetPolys(triangles);
  vtkNew<vtkMobiusRegistration> whole;
  whole->SetSourceData(open);
  whole->SetTargetData(bull);
  whole->SetSourceName("the open cow");
  whole->SetResolution(16);
  whole->SetRefine(false);
  {
    // Strict: refused, naming the mesh and the option.
    whole->RepairOff();
    mobius_test::MessageCatcher catcher(whole);
    mobius_test::MessageCatcher executiveCatcher(whole->GetExecutive());
    whole->Update();
    std::cout << "open source mesh, strict: " << catcher.Error << "\n";
    MOBIUS_EXPECT(catcher.Error.find("the open cow: ") != std::string::npos);
    MOBIUS_EXPECT(catcher.Error.find("FillHoles") != std::string::npos);
    MOBIUS_EXPECT(whole->GetOutput()->GetNumberOfPoints() == 0);
  }
  {
    // By default repaired, with a warning, and the output has the mesh's own rows.
    whole->RepairOn();
    mobius_test::MessageCatcher catcher(whole);
    whole->Update();
    std::cout << "open source mesh: " << catcher.Warnings;
    MOBIUS_EXPECT(catcher.Error.empty());
    MOBIUS_EXPECT(catcher.Warnings.find("1 hole filled") != std::string::npos);
    MOBIUS_EXPECT(whole->GetOutput()->GetNumberOfPoints() == open->GetNumberOfPoints());
    MOBIUS_EXPECT(whole->GetOutput()->GetNumberOfCells() == open->GetNumberOfCells());
    MOBIUS_EXPECT(whole->GetOutput()->GetPointData()->GetArray("RepairedVertex") != nullptr);
    // As the target: the map on the target's own mesh (port 3) has its vertices as given.
    vtkNew<vtkMobiusRegistration> onto;
    onto->SetSourceData(bull);
    onto->SetTargetData(open);
    onto->SetResolution(16);
    onto->SetRefine(false);
    onto->Update();
    MOBIUS_EXPECT(onto->GetOutput(3)->GetNumberOfPoints() == open->GetNumberOfPoints());
    MOBIUS_EXPECT(onto->GetOutput(3)->GetNumberOfCells() == open->GetNumberOfCells());
    MOBIUS_EXPECT(onto->GetOutput()->GetNumberOfPoints() == bull->GetNumberOfPoints());
  }

  // A property out of range: not clamped, an error naming it, before any stage runs.
  vtkNew<vtkMobiusRegistration> misset;
  misset->SetSourceData(cow);
  misset->SetTargetData(bull);
  misset->SetNumberOfCandidates(65);
  {
    mobius_test::MessageCatcher catcher(misset);
    mobius_test::MessageCatcher executiveCatcher(misset->GetExecutive());
    misset->Update();
    std::cout << "65 candidates: " << catcher.Error << "\n";
    MOBIUS_EXPECT(misset->GetNumberOfCandidates() == 65);
    MOBIUS_EXPECT(catcher.Error.find("NumberOfCandidates must be an integer from 1 to 64 (it is 65)") !=
      std::string::npos);
    MOBIUS_EXPECT(misset->GetOutput()->GetNumberOfPoints() == 0);
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
