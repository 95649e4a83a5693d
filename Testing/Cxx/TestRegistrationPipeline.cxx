// The whole pipeline against ground truth: a real mesh (CGAL's hand) and a re-triangulated,
// rotated copy of the same surface (midpoint subdivision keeps the surface exactly and
// vertex i of the mesh is vertex i of the copy). Every source vertex must land near itself.
#include "MobiusTestUtilities.h"
#include "vtkDenseCorrespondence.h"
#include "vtkMobiusCenter.h"
#include "vtkSO3Register.h"
#include "vtkSphericalConformalMap.h"
#include "vtkSurfaceMeshReader.h"

#include <Eigen/Dense>

#ifndef MOBIUS_MESH_DIR
#error "TestRegistrationPipeline needs CGAL's meshes (MOBIUS_MESH_DIR); CMake lists it only with them"
#endif

int TestRegistrationPipeline(int, char*[])
{
  int failures = 0;
  vtkNew<vtkSurfaceMeshReader> reader;
  reader->SetFileName(MOBIUS_MESH_DIR "/hand.off");
  reader->Update();
  vtkPolyData* hand = reader->GetOutput();
  if (hand->GetNumberOfPoints() < 1000)
  {
    std::cerr << "FAILED: cannot read " MOBIUS_MESH_DIR "/hand.off\n";
    return EXIT_FAILURE;
  }
  auto copy = MidpointSubdivision(hand);
  const Eigen::Matrix3d rotation =
    Eigen::AngleAxisd(2.3, Eigen::Vector3d(-1, 2, 0.5).normalized()).toRotationMatrix();
  for (vtkIdType i = 0; i < copy->GetNumberOfPoints(); ++i)
  {
    double p[3];
    copy->GetPoint(i, p);
    const Eigen::Vector3d q = rotation * Eigen::Vector3d(p[0], p[1], p[2]);
    copy->GetPoints()->SetPoint(i, q.data());
  }

  vtkNew<vtkSphericalConformalMap> sourceMap, targetMap;
  sourceMap->SetInputData(hand);
  targetMap->SetInputData(copy);
  vtkNew<vtkMobiusCenter> sourceCentered, targetCentered;
  sourceCentered->SetInputConnection(sourceMap->GetOutputPort());
  targetCentered->SetInputConnection(targetMap->GetOutputPort());
  vtkNew<vtkSO3Register> registration;
  registration->SetSourceConnection(sourceCentered->GetOutputPort());
  registration->SetTargetConnection(targetCentered->GetOutputPort());
  vtkNew<vtkDenseCorrespondence> correspondence;
  correspondence->SetSourceConnection(registration->GetOutputPort());
  correspondence->SetTargetConnection(targetCentered->GetOutputPort());
  correspondence->Update();
  vtkPolyData* out = correspondence->GetOutput();
  MOBIUS_EXPECT(out->GetNumberOfPoints() == hand->GetNumberOfPoints());

  double area = 0;
  vtkDataArray* areas = targetMap->GetOutput()->GetCellData()->GetArray("SurfaceArea");
  for (vtkIdType t = 0; t < areas->GetNumberOfTuples(); ++t)
  {
    area += areas->GetTuple1(t);
  }
  vtkDataArray* mapped = out->GetPointData()->GetArray("MappedPoints");
  double sum = 0;
  for (vtkIdType i = 0; mapped && i < out->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    mapped->GetTuple(i, a);
    copy->GetPoint(i, b);
    sum += std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
  }
  const double meanError = sum / out->GetNumberOfPoints() / std::sqrt(area);
  std::cout << "hand onto its re-triangulated, rotated copy: mean error " << meanError
            << " of sqrt(area)\n";
  MOBIUS_EXPECT(mapped != nullptr);
  MOBIUS_EXPECT(meanError <= 0.01);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
