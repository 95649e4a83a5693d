// Regression image: CGAL's hand (left) and its conformal map onto the sphere (right), both
// colored by log area distortion (share of surface area over share of sphere area): red
// where much surface is crowded into little sphere, as at the fingers.
#include "MobiusTestRendering.h"
#include "MobiusTestUtilities.h"
#include "vtkMobiusCenter.h"
#include "vtkSphericalConformalMap.h"
#include "vtkSurfaceMeshReader.h"

int TestSphericalConformalMapImage(int argc, char* argv[])
{
#ifndef MOBIUS_MESH_DIR
  return EXIT_SUCCESS; // not added to the tests without the example meshes
#else
  vtkNew<vtkSurfaceMeshReader> reader;
  reader->SetFileName(MOBIUS_MESH_DIR "/hand.off");
  vtkNew<vtkSphericalConformalMap> map;
  map->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkMobiusCenter> center;
  center->SetInputConnection(map->GetOutputPort());
  center->Update();
  vtkNew<vtkPolyData> sphere;
  sphere->DeepCopy(center->GetOutput());
  mobius_test::AddLogAreaDistortion(sphere);
  auto surface = mobius_test::OnSurface(sphere);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(600, 300);
  mobius_test::View view;
  view.Array = "LogAreaDistortion";
  view.Range[0] = -4;
  view.Range[1] = 4;
  view.CameraPosition[0] = 0;
  view.CameraPosition[1] = 0;
  view.CameraPosition[2] = 1;
  view.ViewUp[2] = 0;
  view.ViewUp[1] = 1;
  view.Zoom = 1.2;
  mobius_test::AddView(window, surface, view, 0.0, 0.5);
  mobius_test::AddView(window, sphere, view, 0.5, 1.0);
  return mobius_test::CompareWithBaseline(window, argc, argv);
#endif
}
