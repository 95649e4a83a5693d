#include "DemoMeshes.h"

#include "vtkSurfaceMeshReader.h"

#include "vtkDataArray.h"
#include "vtkMassProperties.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTransform.h"
#include "vtkTriangleFilter.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace
{
// The installed copy, found relative to the executable so that any install prefix works
// (and an installed program never depends on the build tree); else the build tree's copy,
// unpacked at configure time.
std::string FindDemoMesh()
{
  std::error_code failed;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", failed);
  if (!failed)
  {
    const std::filesystem::path installedCopy =
      executable.parent_path() / MOBIUS_INSTALLED_MESH_DIR / "cow.off";
    if (std::ifstream(installedCopy))
    {
      return installedCopy.lexically_normal().string();
    }
  }
  return std::string(MOBIUS_MESH_DIR) + "/cow.off";
}
}

bool MakeDemoMeshes(DemoMeshes& demo, std::string& error)
{
  demo.SourcePath = FindDemoMesh();
  if (!std::ifstream(demo.SourcePath))
  {
    error = demo.SourcePath +
      ": the demo mesh is missing (install libcgal-demo and re-run cmake, or run scripts/setup.sh)";
    return false;
  }
  vtkNew<vtkSurfaceMeshReader> reader;
  reader->SetFileName(demo.SourcePath.c_str());
  reader->Update();
  demo.Source = reader->GetOutput();

  // The cow's body runs along x (length about 1), y is up, z across.
  demo.Target = vtkSmartPointer<vtkPolyData>::New();
  demo.Target->DeepCopy(demo.Source);
  vtkNew<vtkTransform> rotation;
  rotation->RotateWXYZ(120.0, 0.6, 0.48, 0.64);
  vtkPoints* points = demo.Target->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    // A gentle bend of the back, slightly longer legs, a wider body.
    const double bent[3] = { p[0], p[1] + 0.08 * std::sin(3.0 * p[0]) + (p[1] < 0 ? 0.15 * p[1] : 0.0),
      1.15 * p[2] };
    points->SetPoint(i, rotation->TransformPoint(bent));
  }
  return true;
}

double DemoMeanError(vtkPolyData* correspondence, vtkPolyData* target)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(target);
  vtkNew<vtkMassProperties> mass;
  mass->SetInputConnection(triangles->GetOutputPort());
  mass->Update();
  const double scale = std::sqrt(mass->GetSurfaceArea());
  vtkDataArray* mapped = correspondence->GetPointData()->GetArray("MappedPoints");
  // The counterpart of source file vertex i is target vertex i; the map's point i is source
  // file vertex InputPointId[i].
  vtkDataArray* sourceIds = correspondence->GetPointData()->GetArray("InputPointId");
  double sum = 0;
  vtkIdType counted = 0;
  for (vtkIdType i = 0; i < correspondence->GetNumberOfPoints(); ++i)
  {
    const vtkIdType counterpart =
      sourceIds ? static_cast<vtkIdType>(sourceIds->GetComponent(i, 0)) : i;
    if (counterpart < 0) // a point a repair created has no counterpart
    {
      continue;
    }
    double a[3], b[3];
    mapped->GetTuple(i, a);
    target->GetPoint(counterpart, b);
    sum += std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
    ++counted;
  }
  return counted > 0 ? sum / counted / scale : 0.0;
}
