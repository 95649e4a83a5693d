// Regression image in the style of the paper's Figure 10: CGAL's hand colored by its own
// coordinates (left), and a re-triangulated, bent copy colored by the colors the dense
// correspondence (target to source) brings over (right).
#include "MobiusTestRendering.h"
#include "MobiusTestUtilities.h"
#include "vtkDenseCorrespondence.h"
#include "vtkMobiusCenter.h"
#include "vtkSO3Register.h"
#include "vtkSphericalConformalMap.h"
#include "vtkSurfaceMeshReader.h"

int TestDenseCorrespondenceImage(int argc, char* argv[])
{
#ifndef MOBIUS_MESH_DIR
  return EXIT_SUCCESS; // not added to the tests without the example meshes
#else
  vtkNew<vtkSurfaceMeshReader> reader;
  reader->SetFileName(MOBIUS_MESH_DIR "/hand.off");
  reader->Update();
  // The target: the hand with its fingers bent a little (a smooth, non-rigid change).
  vtkNew<vtkPolyData> bent;
  bent->DeepCopy(reader->GetOutput());
  double bounds[6];
  bent->GetBounds(bounds);
  for (vtkIdType i = 0; i < bent->GetNumberOfPoints(); ++i)
  {
    double p[3];
    bent->GetPoint(i, p);
    const double t = (p[1] - bounds[2]) / (bounds[3] - bounds[2]);
    p[2] += 0.15 * (bounds[3] - bounds[2]) * t * t;
    bent->GetPoints()->SetPoint(i, p);
  }

  vtkNew<vtkSphericalConformalMap> sourceMap, targetMap;
  sourceMap->SetInputConnection(reader->GetOutputPort());
  targetMap->SetInputData(bent);
  vtkNew<vtkMobiusCenter> sourceCentered, targetCentered;
  sourceCentered->SetInputConnection(sourceMap->GetOutputPort());
  targetCentered->SetInputConnection(targetMap->GetOutputPort());
  vtkNew<vtkSO3Register> registration;
  registration->SetSourceConnection(sourceCentered->GetOutputPort());
  registration->SetTargetConnection(targetCentered->GetOutputPort());
  registration->SetResolution(128);
  registration->Update();
  vtkNew<vtkPolyData> source;
  source->DeepCopy(registration->GetOutput());
  mobius_test::AddPositionColors(source);

  // The inverse map: every target vertex takes the color of its place on the source.
  vtkNew<vtkDenseCorrespondence> inverse;
  inverse->SetSourceData(source);
  inverse->SetTargetConnection(targetCentered->GetOutputPort());
  inverse->SetDirectionToTargetToSource();
  inverse->SetOutputGeometryToSource();
  inverse->Update();

  vtkNew<vtkRenderWindow> window;
  window->SetSize(600, 300);
  mobius_test::View view;
  view.Array = "PositionColor";
  view.CellData = false;
  view.DirectColors = true;
  view.CameraPosition[0] = 0;
  view.CameraPosition[1] = 0;
  view.CameraPosition[2] = 1;
  view.ViewUp[2] = 0;
  view.ViewUp[1] = 1;
  view.Zoom = 1.2;
  mobius_test::AddView(window, mobius_test::OnSurface(source), view, 0.0, 0.5);
  mobius_test::AddView(window, inverse->GetOutput(), view, 0.5, 1.0);
  return mobius_test::CompareWithBaseline(window, argc, argv);
#endif
}
