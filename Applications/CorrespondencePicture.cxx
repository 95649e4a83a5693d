#include "CorrespondencePicture.h"

#include "MobiusPullBack.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <Eigen/Dense>

#include <cmath>
#include <cstdlib>

namespace
{
// "PositionColor": the surface position normalized to the bounding box, as RGB in [0, 1].
void AddPositionColors(vtkPolyData* map)
{
  vtkDataArray* surface = map->GetPointData()->GetArray("SurfacePoints");
  double low[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double high[3] = { VTK_DOUBLE_MIN, VTK_DOUBLE_MIN, VTK_DOUBLE_MIN };
  for (vtkIdType i = 0; i < surface->GetNumberOfTuples(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      low[k] = std::min(low[k], surface->GetComponent(i, k));
      high[k] = std::max(high[k], surface->GetComponent(i, k));
    }
  }
  vtkNew<vtkFloatArray> colors;
  colors->SetName("PositionColor");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(surface->GetNumberOfTuples());
  for (vtkIdType i = 0; i < surface->GetNumberOfTuples(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      const double extent = high[k] > low[k] ? high[k] - low[k] : 1.0;
      colors->SetComponent(i, k, 0.15 + 0.85 * (surface->GetComponent(i, k) - low[k]) / extent);
    }
  }
  map->GetPointData()->AddArray(colors);
}

// A view of a surface that does not depend on how the mesh was posed: look along its
// thinnest principal axis with the middle axis up, each axis's sign fixed by the skewness of
// the points along it (thin parts, such as a cow's legs, point down), so that two similar
// shapes in arbitrary poses are shown alike.
void SetCanonicalView(vtkPolyData* surface, vtkCamera* camera)
{
  const vtkIdType n = surface->GetNumberOfPoints();
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (vtkIdType i = 0; i < n; ++i)
  {
    mean += Eigen::Map<const Eigen::Vector3d>(surface->GetPoint(i)) / n;
  }
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (vtkIdType i = 0; i < n; ++i)
  {
    const Eigen::Vector3d d = Eigen::Map<const Eigen::Vector3d>(surface->GetPoint(i)) - mean;
    covariance += d * d.transpose() / n;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance); // ascending eigenvalues
  Eigen::Matrix3d axes = solver.eigenvectors();
  for (int k = 1; k < 3; ++k)
  {
    double skew = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      skew += std::pow((Eigen::Map<const Eigen::Vector3d>(surface->GetPoint(i)) - mean).dot(axes.col(k)), 3);
    }
    if (skew > 0)
    {
      axes.col(k) *= -1;
    }
  }
  // A right-handed frame: (long axis, up, toward the viewer).
  const Eigen::Vector3d toward = axes.col(2).cross(axes.col(1));
  const Eigen::Vector3d position = mean + toward;
  camera->SetFocalPoint(mean.data());
  camera->SetPosition(position.data());
  camera->SetViewUp(axes.col(1).data());
}

// A surface (points at `SurfacePoints`) colored directly by its "PositionColor".
void AddSurface(vtkPolyData* surface, vtkRenderWindow* window, double xmin, double xmax)
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(surface);
  normals->SplittingOff();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(normals->GetOutputPort());
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("PositionColor");
  mapper->SetColorModeToDirectScalars();
  mapper->ScalarVisibilityOn();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetViewport(xmin, 0, xmax, 1);
  renderer->SetBackground(1, 1, 1);
  SetCanonicalView(surface, renderer->GetActiveCamera());
  renderer->ResetCamera();
  window->AddRenderer(renderer);
}

vtkSmartPointer<vtkPolyData> OnSurface(vtkPolyData* map)
{
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->ShallowCopy(map);
  vtkNew<vtkPoints> points;
  points->SetData(map->GetPointData()->GetArray("SurfacePoints"));
  surface->SetPoints(points);
  return surface;
}
}

bool RenderCorrespondencePicture(vtkPolyData* alignedSource, vtkPolyData* targetMap,
  vtkPolyData* correspondence, std::string& png, std::string& error, int width, int height)
{
  // Debian's VTK renders through GLX only, and aborts the process without an X server.
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    error = "rendering needs an X display: run under xvfb-run -a, or leave out --png";
    return false;
  }
  vtkNew<vtkPolyData> source;
  source->ShallowCopy(alignedSource);
  AddPositionColors(source);

  // The source mesh placed where the map sends each vertex, with the source's colors.
  vtkDataArray* mapped = correspondence->GetPointData()->GetArray("MappedPoints");
  if (!mapped || mapped->GetNumberOfTuples() != source->GetNumberOfPoints())
  {
    error = "the correspondence has no MappedPoints for every source vertex";
    return false;
  }
  // The target's own mesh, with the colors pulled back from the placed source: where the
  // map is many-to-one the placed source folds over itself, the target's mesh does not.
  vtkNew<vtkPolyData> target;
  if (!targetMap || !mobius::vtk::PullBackToTarget(source, mapped, targetMap, target))
  {
    error = "the map could not be shown on the target's own mesh";
    return false;
  }

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  window->SetMultiSamples(0);
  AddSurface(OnSurface(source), window, 0.0, 0.5);
  AddSurface(target, window, 0.5, 1.0);
  window->Render();
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(capture->GetOutputPort());
  writer->WriteToMemoryOn();
  writer->Write();
  vtkUnsignedCharArray* bytes = writer->GetResult();
  if (writer->GetErrorCode() != 0 || !bytes || bytes->GetNumberOfValues() == 0)
  {
    error = "cannot encode the picture";
    return false;
  }
  png.assign(reinterpret_cast<const char*>(bytes->GetPointer(0)), bytes->GetNumberOfValues());
  return true;
}
