// vtkLaplaceBeltramiBasis and its use by vtkCorrespondenceRefinement: the refined map is the
// same, bit for bit, with bases stored on the inputs and without; a stored basis of another
// size is ignored, one of another surface (or incomplete) refused with an error.
#include "MobiusTestUtilities.h"
#include "vtkCorrespondenceRefinement.h"
#include "vtkLaplaceBeltramiBasis.h"
#include "vtkMobiusCenter.h"
#include "vtkSO3Register.h"
#include "vtkSphericalConformalMap.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkStringArray.h"

#include <Eigen/Geometry>

#include <set>

namespace
{
// The centered spherical map of a surface mesh.
vtkSmartPointer<vtkPolyData> CenteredMap(vtkPolyData* mesh)
{
  vtkNew<vtkSphericalConformalMap> map;
  map->SetInputData(mesh);
  vtkNew<vtkMobiusCenter> center;
  center->SetInputConnection(map->GetOutputPort());
  center->Update();
  return center->GetOutput();
}

vtkSmartPointer<vtkPolyData> WithBasis(vtkPolyData* input, int size)
{
  vtkNew<vtkLaplaceBeltramiBasis> basis;
  basis->SetInputData(input);
  basis->SetBasisSize(size);
  basis->Update();
  return basis->GetOutput();
}

// Registration and refinement of source onto target, as the collection driver runs them.
vtkSmartPointer<vtkPolyData> Refine(vtkPolyData* source, vtkPolyData* target,
  vtkCorrespondenceRefinement* refinement)
{
  vtkNew<vtkSO3Register> registration;
  registration->SetSourceData(source);
  registration->SetTargetData(target);
  registration->SetResolution(32);
  refinement->SetSourceConnection(registration->GetOutputPort());
  refinement->SetTargetData(target);
  refinement->Update();
  return refinement->GetOutput();
}

vtkSmartPointer<vtkPolyData> Refine(vtkPolyData* source, vtkPolyData* target)
{
  vtkNew<vtkCorrespondenceRefinement> refinement;
  refinement->RecordTimingsOn(); // printed below: how much a stored basis saves
  return Refine(source, target, refinement);
}

bool SameValues(vtkDataArray* a, vtkDataArray* b)
{
  if (!a || !b || a->GetNumberOfComponents() != b->GetNumberOfComponents() ||
    a->GetNumberOfTuples() != b->GetNumberOfTuples())
  {
    return false;
  }
  for (vtkIdType v = 0; v < a->GetNumberOfValues(); ++v)
  {
    const int c = a->GetNumberOfComponents();
    if (a->GetComponent(v / c, static_cast<int>(v % c)) != b->GetComponent(v / c, static_cast<int>(v % c)))
    {
      return false;
    }
  }
  return true;
}

// Counts the differences between two outputs: points, triangles, every point array and
// every numeric field array except the timings and which bases were stored.
int Differences(vtkPolyData* a, vtkPolyData* b)
{
  int differences = 0;
  auto differ = [&](const std::string& what) {
    std::cerr << "differs: " << what << "\n";
    ++differences;
  };
  if (a->GetNumberOfPoints() == 0 || !SameValues(a->GetPoints()->GetData(), b->GetPoints()->GetData()))
  {
    differ("points");
  }
  if (!SameValues(a->GetPolys()->GetConnectivityArray(), b->GetPolys()->GetConnectivityArray()))
  {
    differ("triangles");
  }
  if (a->GetPointData()->GetNumberOfArrays() != b->GetPointData()->GetNumberOfArrays())
  {
    differ("number of point arrays");
  }
  for (int i = 0; i < a->GetPointData()->GetNumberOfArrays(); ++i)
  {
    const char* name = a->GetPointData()->GetArrayName(i);
    if (!SameValues(a->GetPointData()->GetArray(i), b->GetPointData()->GetArray(name)))
    {
      differ(std::string("point array ") + name);
    }
  }
  const std::set<std::string> varying = { "RefinementStageSeconds", "RefinementStoredBasisUsed" };
  int compared = 0;
  for (int i = 0; i < a->GetFieldData()->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = a->GetFieldData()->GetArray(i);
    if (array && !varying.count(array->GetName()))
    {
      ++compared;
      if (!SameValues(array, b->GetFieldData()->GetArray(array->GetName())))
      {
        differ(std::string("field array ") + array->GetName());
      }
    }
  }
  if (compared < 10)
  {
    differ("too few field arrays compared");
  }
  return differences;
}

double StoredBasisUsed(vtkPolyData* output, int k)
{
  vtkDataArray* used = output->GetFieldData()->GetArray("RefinementStoredBasisUsed");
  return used && used->GetNumberOfComponents() == 2 ? used->GetComponent(0, k) : -1;
}
}

int TestLaplaceBeltramiBasis(int, char*[])
{
  int failures = 0;
  // Two surfaces of the same connectivity (2562 vertices): the bumpy blob, and the blob
  // bent, rotated and scaled by a factor that is not a power of two.
  auto sourceMesh = mobius_test::BumpyMesh(4);
  auto targetMesh = vtkSmartPointer<vtkPolyData>::New();
  targetMesh->DeepCopy(sourceMesh);
  const Eigen::Matrix3d rotation =
    Eigen::AngleAxisd(1.1, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  for (vtkIdType i = 0; i < targetMesh->GetNumberOfPoints(); ++i)
  {
    Eigen::Vector3d p;
    targetMesh->GetPoint(i, p.data());
    p.z() += 0.3 * p.x() * p.x();
    p = 3.7 * (rotation * p);
    targetMesh->GetPoints()->SetPoint(i, p.data());
  }
  auto source = CenteredMap(sourceMesh);
  auto target = CenteredMap(targetMesh);

  // The filter: the arrays, eigenvalues ascending from ~0, the input passed through.
  auto sourceBasis = WithBasis(source, 80);
  auto targetBasis = WithBasis(target, 80);
  vtkDataArray* functions = sourceBasis->GetPointData()->GetArray("LaplaceBeltramiBasis");
  vtkDataArray* eigenvalues = sourceBasis->GetFieldData()->GetArray("LaplaceBeltramiEigenvalues");
  MOBIUS_EXPECT(functions && functions->GetNumberOfComponents() == 80 &&
    functions->GetNumberOfTuples() == source->GetNumberOfPoints());
  MOBIUS_EXPECT(eigenvalues && eigenvalues->GetNumberOfValues() == 80);
  if (!functions || !eigenvalues || eigenvalues->GetNumberOfValues() != 80)
  {
    return EXIT_FAILURE;
  }
  MOBIUS_EXPECT(std::abs(eigenvalues->GetComponent(0, 0)) < 1e-6);
  MOBIUS_EXPECT(eigenvalues->GetComponent(1, 0) > 1.0); // unit area: the first is ~8 pi / ...
  for (int j = 1; j < 80; ++j)
  {
    MOBIUS_EXPECT(eigenvalues->GetComponent(j, 0) >= eigenvalues->GetComponent(j - 1, 0));
  }
  MOBIUS_EXPECT(sourceBasis->GetPointData()->GetArray("SurfacePoints") != nullptr);
  MOBIUS_EXPECT(sourceBasis->GetFieldData()->GetAbstractArray("LaplaceBeltramiBasisMesh") != nullptr);
  // On a plain surface (its points) the same surface gives the same basis.
  auto meshBasis = WithBasis(sourceMesh, 80);
  MOBIUS_EXPECT(SameValues(functions, meshBasis->GetPointData()->GetArray("LaplaceBeltramiBasis")));

  // The refined map with both bases stored, with one, and without: identical.
  auto computed = Refine(source, target);
  auto stored = Refine(sourceBasis, targetBasis);
  auto storedTarget = Refine(source, targetBasis);
  MOBIUS_EXPECT(StoredBasisUsed(computed, 0) == 0 && StoredBasisUsed(computed, 1) == 0);
  MOBIUS_EXPECT(StoredBasisUsed(stored, 0) == 1 && StoredBasisUsed(stored, 1) == 1);
  MOBIUS_EXPECT(StoredBasisUsed(storedTarget, 0) == 0 && StoredBasisUsed(storedTarget, 1) == 1);
  MOBIUS_EXPECT(Differences(computed, stored) == 0);
  MOBIUS_EXPECT(Differences(computed, storedTarget) == 0);
  // Not passed on: the output's arrays are the same as without bases (checked above), and
  // none of the basis arrays is there.
  MOBIUS_EXPECT(!stored->GetPointData()->GetArray("LaplaceBeltramiBasis") &&
    !stored->GetPointData()->GetArray("LaplaceBeltramiBasis_Target") &&
    !stored->GetFieldData()->GetAbstractArray("LaplaceBeltramiBasisMesh"));
  std::cout << "eigenbasis stage seconds: stored "
            << stored->GetFieldData()->GetArray("RefinementStageSeconds")->GetComponent(0, 0)
            << ", computed " << computed->GetFieldData()->GetArray("RefinementStageSeconds")->GetComponent(0, 0)
            << "\n";

  // A basis of another size is ignored: computed anew, the same map.
  auto smallBasis = Refine(WithBasis(source, 40), WithBasis(target, 40));
  MOBIUS_EXPECT(StoredBasisUsed(smallBasis, 0) == 0 && StoredBasisUsed(smallBasis, 1) == 0);
  MOBIUS_EXPECT(Differences(computed, smallBasis) == 0);

  // A basis of another surface with the same number of points is refused.
  auto foreign = vtkSmartPointer<vtkPolyData>::New();
  foreign->ShallowCopy(target);
  foreign->GetPointData()->AddArray(functions);
  foreign->GetFieldData()->AddArray(eigenvalues);
  foreign->GetFieldData()->AddArray(
    sourceBasis->GetFieldData()->GetAbstractArray("LaplaceBeltramiBasisMesh"));
  vtkNew<vtkCorrespondenceRefinement> refuses;
  vtkNew<vtkSO3Register> registration;
  registration->SetSourceData(source);
  registration->SetTargetData(foreign);
  registration->SetResolution(32);
  refuses->SetSourceConnection(registration->GetOutputPort());
  refuses->SetTargetData(foreign);
  failures += ExpectError(refuses, "Target (port 1): its LaplaceBeltramiBasis was computed for another surface");
  // ... and so is one without its eigenvalues.
  auto incomplete = vtkSmartPointer<vtkPolyData>::New();
  incomplete->ShallowCopy(sourceBasis);
  incomplete->GetFieldData()->RemoveArray("LaplaceBeltramiEigenvalues");
  vtkNew<vtkCorrespondenceRefinement> refusesIncomplete;
  refusesIncomplete->SetSourceData(incomplete);
  refusesIncomplete->SetTargetData(target);
  failures += ExpectError(refusesIncomplete, "comes without the field data LaplaceBeltramiEigenvalues");

  // Bad input to the filter itself.
  vtkNew<vtkLaplaceBeltramiBasis> tooLarge;
  tooLarge->SetInputData(mobius_test::MakeSphericalMap(1, [](const Eigen::Vector3d& x) { return x; }));
  failures += ExpectError(tooLarge, "a basis of 80 functions needs more");
  vtkNew<vtkPolyData> points;
  points->SetPoints(sourceMesh->GetPoints());
  vtkNew<vtkLaplaceBeltramiBasis> noTriangles;
  noTriangles->SetInputData(points);
  failures += ExpectError(noTriangles, "no triangles");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
