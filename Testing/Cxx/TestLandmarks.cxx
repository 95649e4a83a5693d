// Landmarks in vtkMobiusRegistration. The mirror-symmetric creature (MirrorSymmetricMesh.h)
// mapped onto itself with rotations and reflections allowed has two exact answers, the
// identity and the mirror map: 3 landmarks must choose either one, whichever the automatic
// map would be, in both landmark modes, with every landmark landing on its target vertex.
// A landmark may name a vertex the repair merged into a duplicate. Bad landmarks (a vertex
// the mesh does not have, one the repair removed, a vertex in two landmarks, too few for
// LandmarkMode 1) are errors naming the problem.
#include "MirrorSymmetricMesh.h"
#include "MobiusTestUtilities.h"
#include "vtkDenseCorrespondence.h"
#include "vtkMobiusRegistration.h"
#include "vtkSO3Register.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkPointData.h"

#include <array>
#include <cmath>

namespace
{
using Truth = std::vector<vtkIdType>; // per source vertex, its true target vertex

double SurfaceArea(vtkPolyData* mesh)
{
  double area = 0;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    mesh->GetCellPoints(c, n, ids);
    double a[3], b[3], p[3], u[3], v[3], w[3];
    mesh->GetPoint(ids[0], a);
    mesh->GetPoint(ids[1], b);
    mesh->GetPoint(ids[2], p);
    for (int k = 0; k < 3; ++k)
    {
      u[k] = b[k] - a[k];
      v[k] = p[k] - a[k];
    }
    vtkMath::Cross(u, v, w);
    area += 0.5 * vtkMath::Norm(w);
  }
  return area;
}

// Mean distance between each source vertex's mapped point and its true image, over
// sqrt(area): straight-line, which on this smooth shape is close to geodesic for small
// errors and large for the mirror image.
double MeanError(vtkPolyData* output, vtkPolyData* target, const Truth& truth)
{
  vtkDataArray* mapped = output->GetPointData()->GetArray("MappedPoints");
  vtkDataArray* ids = output->GetPointData()->GetArray("InputPointId");
  double sum = 0;
  for (vtkIdType i = 0; i < mapped->GetNumberOfTuples(); ++i)
  {
    double image[3], expected[3];
    mapped->GetTuple(i, image);
    target->GetPoint(truth[static_cast<vtkIdType>(ids->GetComponent(i, 0))], expected);
    sum += std::sqrt(vtkMath::Distance2BetweenPoints(image, expected));
  }
  return sum / mapped->GetNumberOfTuples() / std::sqrt(SurfaceArea(target));
}

vtkSmartPointer<vtkMobiusRegistration> Registration(vtkPolyData* source, vtkPolyData* target)
{
  auto registration = vtkSmartPointer<vtkMobiusRegistration>::New();
  registration->SetSourceData(source);
  registration->SetTargetData(target);
  registration->SetResolution(64);
  registration->SetTransformMode(2); // rotations and reflections: both answers are exact
  return registration;
}

// Three vertices off the mirror plane, far apart: a front leg, a hind leg, the head's tip.
std::array<vtkIdType, 3> LandmarkVertices(vtkPolyData* mesh)
{
  std::array<vtkIdType, 3> best = { 0, 0, 0 };
  std::array<double, 3> scores = { -1e300, -1e300, -1e300 };
  for (vtkIdType v = 0; v < mesh->GetNumberOfPoints(); ++v)
  {
    double p[3];
    mesh->GetPoint(v, p);
    const double score[3] = { p[2] + p[0] - p[1], p[2] - p[0] - p[1], p[0] + p[1] + 0.5 * p[2] };
    for (int k = 0; k < 3; ++k)
    {
      if (score[k] > scores[k])
      {
        scores[k] = score[k];
        best[k] = v;
      }
    }
  }
  return best;
}

// With landmarks sending each of `vertices` to its image under `truth`, the map is `truth`
// (mean error below 0.02 of sqrt(area), and far below the other answer's) and every
// landmark lands on its target vertex.
int ExpectLandmarksChoose(vtkPolyData* mesh, const std::array<vtkIdType, 3>& vertices,
  const Truth& truth, const Truth& other, int mode, const char* what)
{
  int failures = 0;
  auto registration = Registration(mesh, mesh);
  for (vtkIdType v : vertices)
  {
    registration->AddLandmark(v, truth[v]);
  }
  registration->SetLandmarkMode(mode);
  registration->Update();
  vtkPolyData* output = registration->GetOutput();
  const double error = MeanError(output, mesh, truth);
  const double otherError = MeanError(output, mesh, other);
  std::cout << what << ", LandmarkMode " << mode << ": mean error " << error
            << " (against the other answer " << otherError << ")\n";
  MOBIUS_EXPECT(error < 0.02);
  MOBIUS_EXPECT(error < 0.25 * otherError);
  MOBIUS_EXPECT(mobius_test::FieldValue(output, "LandmarkCount") == 3);
  vtkDataArray* residuals = output->GetFieldData()->GetArray("LandmarkResidual");
  MOBIUS_EXPECT(residuals && residuals->GetNumberOfTuples() == 3);
  for (vtkIdType k = 0; residuals && k < residuals->GetNumberOfTuples(); ++k)
  {
    // The refinement ends each landmark on its target vertex (docs: residual 0 up to
    // round-off when refined).
    MOBIUS_EXPECT(residuals->GetComponent(k, 0) < 1e-9);
  }
  return failures;
}

// The mesh as a triangle soup (three points of its own per triangle, which the repair merges
// back): a landmark may name any copy of a vertex, also one the merge dropped.
int ExpectMergedDuplicates(vtkPolyData* mesh, const std::array<vtkIdType, 3>& vertices)
{
  int failures = 0;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> lastCopy(static_cast<size_t>(mesh->GetNumberOfPoints()), -1);
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    mesh->GetCellPoints(c, n, ids);
    vtkIdType copies[3];
    for (int k = 0; k < 3; ++k)
    {
      copies[k] = points->InsertNextPoint(mesh->GetPoint(ids[k]));
      lastCopy[ids[k]] = copies[k];
    }
    polys->InsertNextCell(3, copies);
  }
  vtkNew<vtkPolyData> soup;
  soup->SetPoints(points);
  soup->SetPolys(polys);
  auto registration = Registration(soup, mesh);
  for (vtkIdType v : vertices)
  {
    registration->AddLandmark(lastCopy[v], v);
  }
  registration->Update();
  // The copies named are ones the merge dropped: the map has no point of theirs, and their
  // rows (the output has one per point of the soup) come through the repair, on their
  // landmark's target vertex.
  vtkPolyData* output = registration->GetOutput();
  MOBIUS_EXPECT(output->GetNumberOfPoints() == soup->GetNumberOfPoints());
  vtkDataArray* repaired = output->GetPointData()->GetArray("RepairedVertex");
  vtkDataArray* mapped = output->GetPointData()->GetArray("MappedPoints");
  MOBIUS_EXPECT(repaired && mapped);
  for (vtkIdType v : vertices)
  {
    MOBIUS_EXPECT(repaired && repaired->GetComponent(lastCopy[v], 0) == 1);
    double image[3], target[3];
    mapped->GetTuple(lastCopy[v], image);
    mesh->GetPoint(v, target);
    MOBIUS_EXPECT(std::sqrt(vtkMath::Distance2BetweenPoints(image, target)) < 1e-6);
  }
  vtkDataArray* residuals = registration->GetOutput()->GetFieldData()->GetArray("LandmarkResidual");
  MOBIUS_EXPECT(residuals && residuals->GetNumberOfTuples() == 3);
  for (vtkIdType k = 0; residuals && k < residuals->GetNumberOfTuples(); ++k)
  {
    MOBIUS_EXPECT(residuals->GetComponent(k, 0) < 1e-9);
  }
  // Two landmarks on two copies of one vertex, which the repair makes one point, with two
  // targets: one of them could not be kept; an error names both (it was accepted, and the
  // second silently missed its target by 0.4 sqrt(area)).
  std::vector<vtkIdType> copies;
  for (vtkIdType i = 0; i < soup->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    soup->GetPoint(i, p);
    mesh->GetPoint(vertices[0], q);
    if (vtkMath::Distance2BetweenPoints(p, q) == 0)
    {
      copies.push_back(i);
    }
  }
  MOBIUS_EXPECT(copies.size() >= 2);
  if (copies.size() >= 2)
  {
    auto twice = Registration(soup, mesh);
    twice->AddLandmark(copies[0], vertices[0]);
    twice->AddLandmark(copies[1], vertices[1]);
    failures += ExpectError(twice, "landmark 0 and landmark 1 name source vertices " + std::to_string(copies[0]) +
        " and " + std::to_string(copies[1]) + ", which are one point of the surface");
  }
  return failures;
}

int ExpectBadLandmarks(vtkPolyData* mesh)
{
  int failures = 0;
  const vtkIdType n = mesh->GetNumberOfPoints();
  {
    auto registration = Registration(mesh, mesh);
    registration->AddLandmark(0, 0);
    registration->AddLandmark(1, n);
    failures += ExpectError(registration, "landmark 1 names target vertex " + std::to_string(n) +
        ", which does not exist: the target mesh has " + std::to_string(n) + " vertices");
    MOBIUS_EXPECT(registration->CheckParameters(vtkMobiusRegistration::PYTHON_NAMES)
                    .find("landmarks[1] names target vertex") == 0);
  }
  {
    auto registration = Registration(mesh, mesh);
    registration->AddLandmark(5, 0);
    registration->AddLandmark(5, 1);
    failures += ExpectError(registration, "source vertex 5 in landmark 0 and landmark 1");
  }
  {
    auto registration = Registration(mesh, mesh);
    registration->AddLandmark(0, 0);
    registration->AddLandmark(1, 1);
    registration->SetLandmarkMode(1);
    failures += ExpectError(registration, "LandmarkMode must be 0");
    MOBIUS_EXPECT(registration->CheckParameters(vtkMobiusRegistration::COMMAND_LINE_NAMES)
                    .find("--landmark-mode needs") == 0);
  }
  {
    // The stage filters take the maps' point ids, and refuse one a map does not have.
    const auto map = mobius_test::MakeSphericalMap(2, mobius_test::BumpySurface);
    vtkNew<vtkSO3Register> alignment;
    alignment->SetSourceData(map);
    alignment->SetTargetData(map);
    alignment->SetResolution(16);
    alignment->AddLandmark(0, map->GetNumberOfPoints());
    failures += ExpectError(alignment, "landmark 0 names point " +
        std::to_string(map->GetNumberOfPoints()) + " of the Target (port 1), which has");
    vtkNew<vtkDenseCorrespondence> dense;
    dense->SetSourceData(map);
    dense->SetTargetData(map);
    dense->AddLandmark(-1, 0);
    failures += ExpectError(dense, "landmark 0 names point -1 of the Source (port 0)");
  }
  {
    // A vertex no triangle uses: the repair drops it, and a landmark cannot name it.
    vtkNew<vtkPolyData> withUnused;
    withUnused->DeepCopy(mesh);
    const vtkIdType unused = withUnused->GetPoints()->InsertNextPoint(9, 9, 9);
    auto registration = Registration(withUnused, mesh);
    registration->AddLandmark(unused, 0);
    failures += ExpectError(registration, "the mesh's repair removed it");
  }
  return failures;
}
}

int TestLandmarks(int, char*[])
{
  int failures = 0;
  const mobius_test::MirrorSymmetricMesh creature = mobius_test::MakeMirrorSymmetricCreature(4);
  vtkPolyData* mesh = creature.Mesh;
  Truth identity(static_cast<size_t>(mesh->GetNumberOfPoints()));
  for (vtkIdType v = 0; v < mesh->GetNumberOfPoints(); ++v)
  {
    identity[v] = v;
  }
  const Truth& mirror = creature.Partner;
  const std::array<vtkIdType, 3> vertices = LandmarkVertices(mesh);
  for (vtkIdType v : vertices)
  {
    MOBIUS_EXPECT(mirror[v] != v); // off the mirror plane: the two answers differ there
  }
  {
    auto automatic = Registration(mesh, mesh);
    automatic->Update();
    std::cout << "without landmarks: mean error " << MeanError(automatic->GetOutput(), mesh, identity)
              << " against the identity, " << MeanError(automatic->GetOutput(), mesh, mirror)
              << " against the mirror map\n";
  }
  for (int mode : { 0, 1 })
  {
    failures += ExpectLandmarksChoose(mesh, vertices, identity, mirror, mode, "identity");
    failures += ExpectLandmarksChoose(mesh, vertices, mirror, identity, mode, "mirror map");
  }
  failures += ExpectMergedDuplicates(mesh, vertices);
  failures += ExpectBadLandmarks(mesh);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
