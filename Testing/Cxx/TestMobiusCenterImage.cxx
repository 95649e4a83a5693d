// Regression image: a spherical map colored by log area distortion before (left) and after
// (right) vtkMobiusCenter. Before, the surface's area is crowded into one region of the
// sphere; after, it is spread around the sphere.
#include "MobiusTestUtilities.h"
#include "vtkMobiusCenter.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkPolyDataMapper.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkTriangle.h"

namespace
{
// Cell array: log of (share of surface area) / (share of sphere area) per triangle.
void AddLogAreaDistortion(vtkPolyData* map)
{
  vtkDataArray* surfaceArea = map->GetCellData()->GetArray("SurfaceArea");
  double total = 0;
  for (vtkIdType t = 0; t < map->GetNumberOfCells(); ++t)
  {
    total += surfaceArea->GetTuple1(t);
  }
  vtkNew<vtkDoubleArray> distortion;
  distortion->SetName("LogAreaDistortion");
  for (vtkIdType t = 0; t < map->GetNumberOfCells(); ++t)
  {
    double a[3], b[3], c[3];
    vtkIdType npts;
    const vtkIdType* ids;
    map->GetCellPoints(t, npts, ids);
    map->GetPoint(ids[0], a);
    map->GetPoint(ids[1], b);
    map->GetPoint(ids[2], c);
    const double sphereShare = vtkTriangle::TriangleArea(a, b, c) / (4 * vtkMath::Pi());
    distortion->InsertNextValue(std::log((surfaceArea->GetTuple1(t) / total) / sphereShare));
  }
  map->GetCellData()->SetScalars(distortion);
}

void AddMapToRenderer(vtkPolyData* map, vtkRenderWindow* window, double xmin, double xmax)
{
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->Build();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(map);
  mapper->SetScalarModeToUseCellData();
  mapper->SetScalarRange(-3, 3);
  mapper->SetLookupTable(lut);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetViewport(xmin, 0, xmax, 1);
  renderer->SetBackground(1, 1, 1);
  renderer->GetActiveCamera()->SetPosition(4, 2, 3);
  renderer->GetActiveCamera()->SetFocalPoint(0, 0, 0);
  renderer->GetActiveCamera()->SetViewUp(0, 0, 1);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Zoom(1.5);
  window->AddRenderer(renderer);
}
}

int TestMobiusCenterImage(int argc, char* argv[])
{
  auto map = mobius_test::MakeSphericalMap(4, mobius_test::BumpySurface, { 0.55, 0.2, -0.3 });
  vtkNew<vtkMobiusCenter> center;
  center->SetInputData(map);
  center->Update();
  vtkNew<vtkPolyData> centered;
  centered->DeepCopy(center->GetOutput());

  AddLogAreaDistortion(map);
  AddLogAreaDistortion(centered);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(600, 300);
  window->SetMultiSamples(0);
  AddMapToRenderer(map, window, 0.0, 0.5);
  AddMapToRenderer(centered, window, 0.5, 1.0);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  window->Render();

  const int result = vtkRegressionTestImage(window);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
