// Regression image: a spherical map colored by log area distortion before (left) and after
// (right) vtkMobiusCenter. Before, the surface's area is crowded into one region of the
// sphere; after, it is spread around the sphere.
#include "MobiusTestRendering.h"
#include "MobiusTestUtilities.h"
#include "vtkMobiusCenter.h"

int TestMobiusCenterImage(int argc, char* argv[])
{
  auto map = mobius_test::MakeSphericalMap(4, mobius_test::BumpySurface, { 0.55, 0.2, -0.3 });
  vtkNew<vtkMobiusCenter> center;
  center->SetInputData(map);
  center->Update();
  vtkNew<vtkPolyData> centered;
  centered->DeepCopy(center->GetOutput());
  mobius_test::AddLogAreaDistortion(map);
  mobius_test::AddLogAreaDistortion(centered);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(600, 300);
  mobius_test::View view;
  view.Array = "LogAreaDistortion";
  mobius_test::AddView(window, map, view, 0.0, 0.5);
  mobius_test::AddView(window, centered, view, 0.5, 1.0);
  return mobius_test::CompareWithBaseline(window, argc, argv);
}
