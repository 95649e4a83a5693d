// The picture's right half shows the target's own mesh with the colors pulled back from the
// source mesh as the map places it (PullBackColors). Colors that are an affine function of
// the position are interpolated exactly within a triangle, so on a finer mesh of the same
// surface (each triangle split in four: every new vertex lies on an edge of the placed
// mesh) the pulled colors must be that function of the target's vertices; and a map that
// places the source mirrored must bring the mirrored colors.
#include "CorrespondencePicture.h"

#include "vtkFloatArray.h"
#include "vtkLinearSubdivisionFilter.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSphereSource.h"

#include <cmath>
#include <iostream>

namespace
{
// An affine color of the position: (0.5 + x/2, 0.5 + y/2, 0.5 + z/2) on the unit sphere.
void ColorOf(const double point[3], double color[3], double mirror = 1.0)
{
  color[0] = 0.5 + 0.5 * mirror * point[0];
  color[1] = 0.5 + 0.5 * point[1];
  color[2] = 0.5 + 0.5 * point[2];
}

// The largest difference between the target's pulled colors and the affine colors of its
// vertices (mirrored in x when `mirror` is -1).
double LargestColorError(vtkPolyData* target, double mirror)
{
  vtkDataArray* pulled = target->GetPointData()->GetArray("PositionColor");
  if (!pulled || pulled->GetNumberOfTuples() != target->GetNumberOfPoints())
  {
    return INFINITY;
  }
  double largest = 0;
  for (vtkIdType i = 0; i < target->GetNumberOfPoints(); ++i)
  {
    double point[3], expected[3];
    target->GetPoint(i, point);
    ColorOf(point, expected, mirror);
    for (int k = 0; k < 3; ++k)
    {
      largest = std::max(largest, std::abs(pulled->GetComponent(i, k) - expected[k]));
    }
  }
  return largest;
}

// The sphere as the map places it: its points mirrored in x when `mirror` is -1, with the
// colors of the unmirrored points.
vtkSmartPointer<vtkPolyData> Placed(vtkPolyData* sphere, double mirror)
{
  auto placed = vtkSmartPointer<vtkPolyData>::New();
  placed->CopyStructure(sphere);
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> colors;
  colors->SetName("PositionColor");
  colors->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    double point[3], color[3];
    sphere->GetPoint(i, point);
    ColorOf(point, color);
    colors->InsertNextTuple(color);
    points->InsertNextPoint(mirror * point[0], point[1], point[2]);
  }
  placed->SetPoints(points);
  placed->GetPointData()->AddArray(colors);
  return placed;
}
}

int main()
{
  vtkNew<vtkSphereSource> source;
  source->SetRadius(1.0);
  source->SetThetaResolution(24);
  source->SetPhiResolution(16);
  source->Update();
  vtkNew<vtkLinearSubdivisionFilter> finer;
  finer->SetInputConnection(source->GetOutputPort());
  finer->SetNumberOfSubdivisions(1);
  finer->Update();
  int failures = 0;
  for (const double mirror : { 1.0, -1.0 })
  {
    vtkNew<vtkPolyData> target;
    target->DeepCopy(finer->GetOutput());
    target->GetPointData()->Initialize();
    PullBackColors(Placed(source->GetOutput(), mirror), target);
    const double error = LargestColorError(target, mirror);
    std::cout << (mirror > 0 ? "placed as it is" : "placed mirrored") << ": largest color error "
              << error << " over " << target->GetNumberOfPoints() << " target vertices\n";
    if (!(error < 1e-5))
    {
      std::cerr << "FAILED: the pulled colors are not the placed source's\n";
      ++failures;
    }
  }
  return failures == 0 ? 0 : 1;
}
