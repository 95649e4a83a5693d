// The map on the target's own mesh (mobius::vtk::PullBackToTarget, vtkMobiusRegistration's
// port 3, the right half of mobius-register --png): every target vertex takes the source's
// arrays at its closest point on the source as the map places it. Values that are an affine
// function of the position are interpolated exactly within a triangle, so on a finer mesh of
// the same surface (each triangle split in four: every new vertex lies on an edge of the
// placed mesh) the carried-back values must be that function of the target's vertices; a
// map that places the source mirrored must bring the mirrored values; and SourcePoints must
// say where on the source each vertex comes from.
#include "MobiusPullBack.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkLinearSubdivisionFilter.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <cmath>
#include <iostream>
#include <string>

namespace
{
// An affine color of the position: (0.5 + x/2, 0.5 + y/2, 0.5 + z/2) on the unit sphere.
void ColorOf(const double point[3], double color[3], double mirror = 1.0)
{
  color[0] = 0.5 + 0.5 * mirror * point[0];
  color[1] = 0.5 + 0.5 * point[1];
  color[2] = 0.5 + 0.5 * point[2];
}

// The largest difference between a carried-back 3-component array and `expected` of the
// output's vertices.
template <typename Expected>
double LargestError(vtkPolyData* output, const char* name, Expected expected)
{
  vtkDataArray* carried = output->GetPointData()->GetArray(name);
  if (!carried || carried->GetNumberOfTuples() != output->GetNumberOfPoints() ||
    carried->GetNumberOfComponents() != 3)
  {
    std::cerr << "no array " << name << " of 3 components for every vertex\n";
    return INFINITY;
  }
  double largest = 0;
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double point[3], value[3];
    output->GetPoint(i, point);
    expected(point, value);
    for (int k = 0; k < 3; ++k)
    {
      largest = std::max(largest, std::abs(carried->GetComponent(i, k) - value[k]));
    }
  }
  return largest;
}

// A map with SurfacePoints (its own points), as the pipeline's maps have them.
vtkSmartPointer<vtkPolyData> WithSurfacePoints(vtkPolyData* mesh)
{
  auto map = vtkSmartPointer<vtkPolyData>::New();
  map->DeepCopy(mesh);
  map->GetPointData()->Initialize();
  vtkNew<vtkDoubleArray> surface;
  surface->SetName("SurfacePoints");
  surface->DeepCopy(mesh->GetPoints()->GetData());
  surface->SetName("SurfacePoints");
  map->GetPointData()->AddArray(surface);
  return map;
}
}

int TestPullBackToTarget(int, char*[])
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(16);
  sphere->Update();
  vtkNew<vtkLinearSubdivisionFilter> finer;
  finer->SetInputConnection(sphere->GetOutputPort());
  finer->SetNumberOfSubdivisions(1);
  finer->Update();

  auto source = WithSurfacePoints(sphere->GetOutput());
  vtkNew<vtkFloatArray> colors;
  colors->SetName("PositionColor");
  colors->SetNumberOfComponents(3);
  vtkNew<vtkIntArray> label; // an integer array: taken from the nearest vertex, not averaged
  label->SetName("Label");
  for (vtkIdType i = 0; i < source->GetNumberOfPoints(); ++i)
  {
    double point[3], color[3];
    source->GetPoint(i, point);
    ColorOf(point, color);
    colors->InsertNextTuple(color);
    label->InsertNextValue(7);
  }
  source->GetPointData()->AddArray(colors);
  source->GetPointData()->AddArray(label);
  auto target = WithSurfacePoints(finer->GetOutput());

  int failures = 0;
  for (const double mirror : { 1.0, -1.0 })
  {
    // The source placed by the map: its points mirrored in x when `mirror` is -1.
    vtkNew<vtkDoubleArray> mapped;
    mapped->SetNumberOfComponents(3);
    for (vtkIdType i = 0; i < source->GetNumberOfPoints(); ++i)
    {
      double point[3];
      source->GetPoint(i, point);
      point[0] *= mirror;
      mapped->InsertNextTuple(point);
    }
    vtkNew<vtkPolyData> output;
    if (!mobius::vtk::PullBackToTarget(source, mapped, target, output))
    {
      std::cerr << "FAILED: PullBackToTarget refused a valid map\n";
      return 1;
    }
    const double colorError = LargestError(output, "PositionColor",
      [mirror](const double p[3], double c[3]) { ColorOf(p, c, mirror); });
    const double pointError = LargestError(output, "SourcePoints", [mirror](const double p[3], double s[3]) {
      s[0] = mirror * p[0];
      s[1] = p[1];
      s[2] = p[2];
    });
    vtkDataArray* labels = output->GetPointData()->GetArray("Label");
    const bool labelsKept = labels && labels->GetDataType() == VTK_INT &&
      labels->GetRange()[0] == 7 && labels->GetRange()[1] == 7;
    std::cout << (mirror > 0 ? "placed as it is" : "placed mirrored") << ": largest color error "
              << colorError << ", source point error " << pointError << " over "
              << output->GetNumberOfPoints() << " target vertices\n";
    if (!(colorError < 1e-5) || !(pointError < 1e-5) || !labelsKept ||
      output->GetNumberOfPoints() != target->GetNumberOfPoints() ||
      output->GetNumberOfPolys() != target->GetNumberOfPolys() ||
      !output->GetPointData()->GetArray("SourceCellId") ||
      !output->GetPointData()->GetArray("SourceBarycentric"))
    {
      std::cerr << "FAILED: the carried-back arrays are not the placed source's\n";
      ++failures;
    }
  }
  // A placement of the wrong size is refused, not read out of bounds.
  vtkNew<vtkDoubleArray> tooShort;
  tooShort->SetNumberOfComponents(3);
  tooShort->SetNumberOfTuples(3);
  tooShort->Fill(0.0);
  vtkNew<vtkPolyData> refused;
  if (mobius::vtk::PullBackToTarget(source, tooShort, target, refused) ||
    refused->GetNumberOfPoints() != 0)
  {
    std::cerr << "FAILED: a placement of 3 points for " << source->GetNumberOfPoints()
              << " source points was taken\n";
    ++failures;
  }
  return failures == 0 ? 0 : 1;
}
