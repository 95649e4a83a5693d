// Regression image in the style of the paper's Figure 6: the conformal factors of a
// centered spherical map on a 64 x 64 grid (left), and the low-passed factors shown by
// displacing the grid sphere radially (right).
#include "MobiusTestRendering.h"
#include "MobiusTestUtilities.h"
#include "vtkMobiusCenter.h"
#include "vtkSphericalScaleGrid.h"

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
  mobius_test::View view;
  raw->GetOutput()->GetCellData()->GetArray("ConformalFactor")->GetRange(view.Range);
  view.Zoom = 1.4;
  view.Array = "ConformalFactor";
  mobius_test::AddView(window, raw->GetOutput(), view, 0.0, 0.5);
  view.Array = "ConformalFactorSmoothed";
  mobius_test::AddView(window, displaced->GetOutput(), view, 0.5, 1.0);
  return mobius_test::CompareWithBaseline(window, argc, argv);
}
