// Regression image in the style of the paper's Figure 6: the conformal factors of a
// centered spherical map on a 64 x 64 grid (left), and the low-passed factors shown by
// displacing the grid sphere radially (right).
#include "MobiusTestUtilities.h"
#include "vtkMobiusCenter.h"
#include "vtkSphericalScaleGrid.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLookupTable.h"
#include "vtkPolyDataMapper.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

namespace
{
void AddGrid(vtkPolyData* grid, const char* array, vtkRenderWindow* window, double xmin, double xmax)
{
  double range[2];
  grid->GetCellData()->GetArray("ConformalFactor")->GetRange(range);
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->Build();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(grid);
  mapper->SetScalarModeToUseCellFieldData();
  mapper->SelectColorArray(array);
  mapper->SetScalarRange(range);
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
  renderer->GetActiveCamera()->Zoom(1.4);
  window->AddRenderer(renderer);
}
}

int TestSphericalScaleGridImage(int argc, char* argv[])
{
  auto map = mobius_test::MakeSphericalMap(5, mobius_test::BumpySurface);
  vtkNew<vtkMobiusCenter> center;
  center->SetInputData(map);
  vtkNew<vtkSphericalScaleGrid> raw;
  raw->SetInputConnection(center->GetOutputPort());
  raw->SetResolution(64);
  raw->Update();
  vtkNew<vtkSphericalScaleGrid> displaced;
  displaced->SetInputConnection(center->GetOutputPort());
  displaced->SetResolution(64);
  displaced->SetSmoothingTime(2e-3);
  displaced->DisplaceByValueOn();
  displaced->Update();

  vtkNew<vtkRenderWindow> window;
  window->SetSize(600, 300);
  window->SetMultiSamples(0);
  AddGrid(raw->GetOutput(), "ConformalFactor", window, 0.0, 0.5);
  AddGrid(displaced->GetOutput(), "ConformalFactorSmoothed", window, 0.5, 1.0);
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
