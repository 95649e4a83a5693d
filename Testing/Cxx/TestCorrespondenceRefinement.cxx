// vtkCorrespondenceRefinement against ground truth on CGAL's cow (CC0): a rotated copy of
// itself must come out exact, a rotated, re-triangulated copy (midpoint subdivision: the
// same surface, vertex i of the mesh is vertex i of the copy) nearly so, within the issue's
// 5e-3 and well below the spectral map without the geometric polish, and a bent, rotated
// copy far better than the Möbius map the refinement starts from, and better polished in
// both directions (BothDirections, the default: two rounds, each from the averages) than in
// one; with the blended mass matrix the rotated copy does not come out as its mirror image.
// Bad input gives errors.
#include "MobiusTestUtilities.h"
#include "vtkCorrespondenceRefinement.h"
#include "vtkDenseCorrespondence.h"
#include "vtkMobiusCenter.h"
#include "vtkSO3Register.h"
#include "vtkSphericalConformalMap.h"
#include "vtkSurfaceMeshReader.h"

#include "vtkMath.h"

#include <Eigen/Dense>

#include <functional>

namespace
{
vtkSmartPointer<vtkPolyData> Moved(
  vtkPolyData* mesh, const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& move)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(mesh);
  for (vtkIdType i = 0; i < copy->GetNumberOfPoints(); ++i)
  {
    double p[3];
    copy->GetPoint(i, p);
    copy->GetPoints()->SetPoint(i, move(Eigen::Vector3d(p[0], p[1], p[2])).data());
  }
  return copy;
}

struct Maps
{
  vtkSmartPointer<vtkPolyData> Mobius, Refined;
  vtkSmartPointer<vtkPolyData> Unpolished; // the refinement without its geometric polish
  vtkSmartPointer<vtkPolyData> OneDirection; // the polish from source to target only
  double TargetArea = 0;
};

Maps Register(vtkPolyData* source, vtkPolyData* target, double consistentMassShare = 0.0,
  bool withUnpolished = false, bool withOneDirection = false)
{
  vtkNew<vtkSphericalConformalMap> sourceMap, targetMap;
  sourceMap->SetInputData(source);
  targetMap->SetInputData(target);
  vtkNew<vtkMobiusCenter> sourceCentered, targetCentered;
  sourceCentered->SetInputConnection(sourceMap->GetOutputPort());
  targetCentered->SetInputConnection(targetMap->GetOutputPort());
  vtkNew<vtkSO3Register> registration;
  registration->SetSourceConnection(sourceCentered->GetOutputPort());
  registration->SetTargetConnection(targetCentered->GetOutputPort());
  registration->SetResolution(128);
  vtkNew<vtkDenseCorrespondence> correspondence;
  correspondence->SetSourceConnection(registration->GetOutputPort());
  correspondence->SetTargetConnection(targetCentered->GetOutputPort());
  vtkNew<vtkCorrespondenceRefinement> refinement;
  refinement->SetSourceConnection(registration->GetOutputPort());
  refinement->SetTargetConnection(targetCentered->GetOutputPort());
  refinement->SetConsistentMassShare(consistentMassShare);
  refinement->RecordTimingsOn(); // PolishSeconds reads them
  correspondence->Update();
  refinement->Update();
  Maps maps;
  maps.Mobius = correspondence->GetOutput();
  maps.Refined = refinement->GetOutput();
  if (withUnpolished)
  {
    vtkNew<vtkCorrespondenceRefinement> unpolished;
    unpolished->SetSourceConnection(registration->GetOutputPort());
    unpolished->SetTargetConnection(targetCentered->GetOutputPort());
    unpolished->SetGeometricPolish(false);
    unpolished->RecordTimingsOn();
    unpolished->Update();
    maps.Unpolished = unpolished->GetOutput();
  }
  if (withOneDirection)
  {
    vtkNew<vtkCorrespondenceRefinement> one;
    one->SetSourceConnection(registration->GetOutputPort());
    one->SetTargetConnection(targetCentered->GetOutputPort());
    one->BothDirectionsOff();
    one->Update();
    maps.OneDirection = one->GetOutput();
  }
  vtkDataArray* areas = targetMap->GetOutput()->GetCellData()->GetArray("SurfaceArea");
  for (vtkIdType t = 0; t < areas->GetNumberOfTuples(); ++t)
  {
    maps.TargetArea += areas->GetTuple1(t);
  }
  return maps;
}

// The last of the refinement's stage timings: its geometric polish.
double PolishSeconds(vtkPolyData* map)
{
  vtkDataArray* seconds = map->GetFieldData()->GetArray("RefinementStageSeconds");
  return seconds && seconds->GetNumberOfComponents() == 4 ? seconds->GetComponent(0, 3) : -1.0;
}

// Mean distance of MappedPoints from target point i (the truth), over sqrt(target area).
double MeanError(vtkPolyData* map, vtkPolyData* target, double area)
{
  vtkDataArray* mapped = map->GetPointData()->GetArray("MappedPoints");
  if (!mapped || map->GetNumberOfPoints() == 0)
  {
    return 1e9;
  }
  double sum = 0;
  for (vtkIdType i = 0; i < map->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    mapped->GetTuple(i, a);
    target->GetPoint(i, b);
    sum += std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
  }
  return sum / map->GetNumberOfPoints() / std::sqrt(area);
}
}

int TestCorrespondenceRefinement(int, char*[])
{
  int failures = 0;
#ifdef MOBIUS_MESH_DIR
  vtkNew<vtkSurfaceMeshReader> reader;
  reader->SetFileName(MOBIUS_MESH_DIR "/cow.off");
  reader->Update();
  vtkPolyData* cow = reader->GetOutput();
  const Eigen::Matrix3d rotation =
    Eigen::AngleAxisd(2.3, Eigen::Vector3d(-1, 2, 0.5).normalized()).toRotationMatrix();
  auto rotate = [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(rotation * p); };

  // Exact isometries: a rotated copy comes out exact (measured 3.4e-7 under each CPU dispatch
  // of scripts/test-dispatches.sh; 5.5e-4 without the polish), a rotated, re-triangulated one
  // nearly so (below).
  auto rotated = Moved(cow, rotate);
  Maps maps = Register(cow, rotated);
  const double rotatedError = MeanError(maps.Refined, rotated, maps.TargetArea);
  std::cout << "cow onto its rotated copy: Möbius " << MeanError(maps.Mobius, rotated, maps.TargetArea)
            << ", refined " << rotatedError << "\n";
  MOBIUS_EXPECT(rotatedError <= 1e-3);
  MOBIUS_EXPECT(mobius_test::FieldValue(maps.Refined, "RefinementBasisSize") == 80);
  vtkDataArray* residuals = maps.Refined->GetFieldData()->GetArray("CandidateOrthogonalityResiduals");
  MOBIUS_EXPECT(residuals && residuals->GetNumberOfTuples() >= 1);
  const double kept = mobius_test::FieldValue(maps.Refined, "RefinementCandidate");
  MOBIUS_EXPECT(residuals && kept >= 0 && kept < residuals->GetNumberOfTuples());
  MOBIUS_EXPECT(mobius_test::FieldValue(maps.Refined, "RefinementOrientationAgreement") > 0.9);
  MOBIUS_EXPECT(maps.Refined->GetPointData()->GetArray("TargetBarycentric") != nullptr);
  MOBIUS_EXPECT(maps.Refined->GetPointData()->GetArray("InputPointId") != nullptr);

  // The same pair with the blended mass matrix: the cow is nearly mirror-symmetric, its
  // first eigenfunctions are all symmetric, and every candidate's ZoomOut came out as the
  // mirror image (mean 0.47, orientation agreement 0.03) until iterations that come out
  // mirrored were redone with one eigenfunction's sign flipped.
  maps = Register(cow, rotated, 0.5);
  const double blendedError = MeanError(maps.Refined, rotated, maps.TargetArea);
  std::cout << "cow onto its rotated copy, blended mass: refined " << blendedError
            << ", orientation agreement "
            << mobius_test::FieldValue(maps.Refined, "RefinementOrientationAgreement") << "\n";
  MOBIUS_EXPECT(blendedError <= 1e-3);
  MOBIUS_EXPECT(mobius_test::FieldValue(maps.Refined, "RefinementOrientationAgreement") > 0.9);
  vtkDataArray* agreements = maps.Refined->GetFieldData()->GetArray("CandidateOrientationAgreement");
  for (vtkIdType c = 0; agreements && c < agreements->GetNumberOfTuples(); ++c)
  {
    // Measured 1, 0.96, 0.97, 0.93 (a mirrored one keeps about 0.03): no candidate mirrored.
    MOBIUS_EXPECT(agreements->GetComponent(c, 0) > 0.5);
  }

  // The re-triangulated copy (4x the vertices): the spectral map is limited by this coarse
  // mesh's discretization of the Laplacian (measured 4.6e-3; the Möbius map alone 3.3e-2),
  // the geometric polish takes it to 5.9e-4 under each dispatch (3.6e-3 when the mean
  // curvature the polish matches was clamped before its diffusion, as the candidates' is,
  // 1.6e-3 when the Gaussian curvature was smoothed in one step instead of 4: both break the
  // match between two resolutions). Both from the same registration.
  auto remeshed = Moved(MidpointSubdivision(cow), rotate);
  maps = Register(cow, remeshed, 0.0, true);
  const double remeshedError = MeanError(maps.Refined, remeshed, maps.TargetArea);
  const double unpolishedError = MeanError(maps.Unpolished, remeshed, maps.TargetArea);
  std::cout << "cow onto its re-triangulated, rotated copy: Möbius "
            << MeanError(maps.Mobius, remeshed, maps.TargetArea) << ", refined without polish "
            << unpolishedError << ", refined " << remeshedError << ", polish seconds "
            << PolishSeconds(maps.Refined) << "\n";
  MOBIUS_EXPECT(remeshedError <= 1.1e-3);
  MOBIUS_EXPECT(remeshedError <= 0.6 * unpolishedError);
  MOBIUS_EXPECT(PolishSeconds(maps.Refined) > 0 && PolishSeconds(maps.Unpolished) == 0);

  // A near-isometric deformation: the cow's body (along x) bent into an arc, then rotated.
  auto bent = Moved(cow, [&](const Eigen::Vector3d& p) {
    const double radius = 1.2, angle = p.x() / radius;
    const Eigen::Vector3d arc((radius + p.y()) * std::sin(angle), (radius + p.y()) * std::cos(angle) - radius, p.z());
    return Eigen::Vector3d(rotation * arc);
  });
  maps = Register(cow, bent, 0.0, false, true);
  const double mobiusError = MeanError(maps.Mobius, bent, maps.TargetArea);
  const double bentError = MeanError(maps.Refined, bent, maps.TargetArea);
  const double oneError = MeanError(maps.OneDirection, bent, maps.TargetArea);
  std::cout << "cow onto its bent, rotated copy: Möbius " << mobiusError << ", refined "
            << bentError << ", polished in one direction only " << oneError << "\n";
  MOBIUS_EXPECT(bentError <= 0.02 && bentError <= 0.5 * mobiusError);
  // The bent copy is made with std::sin and std::cos, whose last bits depend on the CPU (the
  // C library's FMA or SSE2 routines), and the polish carries such differences into the
  // figures below: measured 1.763e-3 (default dispatch and OPENBLAS_CORETYPE=Haswell) and
  // 1.765e-3 (glibc.cpu.hwcaps=-FMA,-AVX2), 1.759e-3 to 1.771e-3 on 12 copies whose coordinates
  // were moved by up to 2 ulps; without the polish's curvature terms 3.1e-3 (version 81ce314).
  MOBIUS_EXPECT(bentError <= 2.4e-3);
  // The polish both ways, the two meeting every kMeetingInterval iterations (each map moved
  // towards the other's inverse) and each point averaged with the other direction's inverse
  // at the end, against the polish from source to target alone (1.976e-3 and 1.979e-3 under
  // the dispatches above, 1.976e-3 to 1.985e-3 on the 12 moved copies): the ratio measured
  // 0.892 and 0.891, 0.889 to 0.896 on the moved copies; without the meetings 0.937 to 0.957
  // (kMeetingMaximumVertices set to 0), so the bound fails without them. It was
  // 0.79, from a one-direction figure of 2.29e-3 that no dispatch of this version gives.
  MOBIUS_EXPECT(bentError < 0.92 * oneError);

  // Bad input: a basis larger than half the mesh (642 points), and a target without
  // SurfacePoints.
  auto small = mobius_test::MakeSphericalMap(3, [](const Eigen::Vector3d& x) { return x; });
  vtkNew<vtkCorrespondenceRefinement> tooLarge;
  tooLarge->SetSourceData(small);
  tooLarge->SetTargetData(small);
  tooLarge->SetBasisSize(500);
  failures += ExpectError(tooLarge, "fewer than twice the BasisSize");
  vtkNew<vtkPolyData> bare;
  bare->CopyStructure(small);
  vtkNew<vtkCorrespondenceRefinement> noSurface;
  noSurface->SetSourceData(small);
  noSurface->SetTargetData(bare);
  failures += ExpectError(noSurface, "SurfacePoints");
#else
  std::cout << "CGAL's meshes are not installed: nothing to test\n";
  return VTK_SKIP_RETURN_CODE;
#endif
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
