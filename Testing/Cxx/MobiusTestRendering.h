// Rendering helpers of the regression-image tests: the arrays the pictures are colored by,
// side-by-side views with fixed cameras, and the comparison with the baseline.
#ifndef MobiusTestRendering_h
#define MobiusTestRendering_h

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTriangle.h"

#include <cmath>
#include <string>

namespace mobius_test
{
/// Cell array "LogAreaDistortion": log of (share of surface area) / (share of sphere area).
inline void AddLogAreaDistortion(vtkPolyData* map)
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
  map->GetCellData()->AddArray(distortion);
}

/// Point array "PositionColor": SurfacePoints normalized to their bounding box, as RGB.
inline void AddPositionColors(vtkPolyData* map)
{
  vtkDataArray* surface = map->GetPointData()->GetArray("SurfacePoints");
  double bounds[6];
  vtkNew<vtkPoints> points;
  points->SetData(surface);
  points->GetBounds(bounds);
  vtkNew<vtkFloatArray> colors;
  colors->SetName("PositionColor");
  colors->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < surface->GetNumberOfTuples(); ++i)
  {
    float rgb[3];
    for (int k = 0; k < 3; ++k)
    {
      rgb[k] = static_cast<float>(0.15 + 0.85 * (surface->GetComponent(i, k) - bounds[2 * k]) /
          (bounds[2 * k + 1] - bounds[2 * k]));
    }
    colors->InsertNextTypedTuple(rgb);
  }
  map->GetPointData()->AddArray(colors);
}

/// The map's original surface: the same data with its points at SurfacePoints.
inline vtkSmartPointer<vtkPolyData> OnSurface(vtkPolyData* map)
{
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->ShallowCopy(map);
  vtkNew<vtkPoints> points;
  points->SetData(map->GetPointData()->GetArray("SurfacePoints"));
  surface->SetPoints(points);
  return surface;
}

struct View
{
  std::string Array;          // colored by this array...
  bool CellData = true;       // ...of the cells, or of the points
  bool DirectColors = false;  // RGB in [0, 1] instead of a color map
  double Range[2] = { -3, 3 };
  double CameraPosition[3] = { 4, 2, 3 };
  double ViewUp[3] = { 0, 0, 1 };
  double Zoom = 1.5;
};

/// Adds a renderer showing `data` in the horizontal slice [xmin, xmax] of the window.
inline void AddView(vtkRenderWindow* window, vtkPolyData* data, const View& view, double xmin, double xmax)
{
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->Build();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  if (view.CellData)
  {
    mapper->SetScalarModeToUseCellFieldData();
  }
  else
  {
    mapper->SetScalarModeToUsePointFieldData();
  }
  mapper->SelectColorArray(view.Array.c_str());
  mapper->SetScalarRange(view.Range[0], view.Range[1]);
  mapper->SetLookupTable(lut);
  if (view.DirectColors)
  {
    mapper->SetColorModeToDirectScalars();
  }
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetViewport(xmin, 0, xmax, 1);
  renderer->SetBackground(1, 1, 1);
  double center[3];
  data->GetCenter(center);
  renderer->GetActiveCamera()->SetFocalPoint(center);
  renderer->GetActiveCamera()->SetPosition(center[0] + view.CameraPosition[0],
    center[1] + view.CameraPosition[1], center[2] + view.CameraPosition[2]);
  renderer->GetActiveCamera()->SetViewUp(view.ViewUp);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Zoom(view.Zoom);
  window->AddRenderer(renderer);
}

/// Renders and compares with the test's baseline; the test's return value.
inline int CompareWithBaseline(vtkRenderWindow* window, int argc, char* argv[])
{
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  window->SetMultiSamples(0);
  window->Render();
  const int result = vtkRegressionTestImage(window);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
}

#endif
