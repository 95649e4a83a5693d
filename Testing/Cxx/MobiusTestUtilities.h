// Shared helpers of the C++ filter tests: generated surface meshes and spherical maps, and
// an observer that records vtkErrorMacro messages so tests can check what a filter says.
#ifndef MobiusTestUtilities_h
#define MobiusTestUtilities_h

#include "Icosphere.h"
#include "MobiusCentering.h"

#include "vtkCallbackCommand.h"

#include <Eigen/Geometry>
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPoints.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkExecutive.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <functional>
#include <map>
#include <iostream>
#include <string>

namespace mobius_test
{
/// Records the last error and warning an object reports (instead of printing them), and every
/// warning, one a line.
class MessageCatcher
{
public:
  explicit MessageCatcher(vtkObject* observed)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback([](vtkObject*, unsigned long event, void* clientData, void* callData) {
      auto self = static_cast<MessageCatcher*>(clientData);
      const std::string message = callData ? static_cast<const char*>(callData) : "";
      (event == vtkCommand::ErrorEvent ? self->Error : self->Warning) = message;
      if (event == vtkCommand::WarningEvent)
      {
        self->Warnings += message + "\n";
      }
    });
    this->Tags[0] = observed->AddObserver(vtkCommand::ErrorEvent, this->Callback);
    this->Tags[1] = observed->AddObserver(vtkCommand::WarningEvent, this->Callback);
    this->Observed = observed;
  }
  // The observed object usually outlives the catcher: its callback must go with it, or a later
  // message is written into a catcher that no longer exists.
  ~MessageCatcher()
  {
    this->Observed->RemoveObserver(this->Tags[0]);
    this->Observed->RemoveObserver(this->Tags[1]);
  }
  MessageCatcher(const MessageCatcher&) = delete;
  MessageCatcher& operator=(const MessageCatcher&) = delete;

  std::string Error;
  std::string Warning;
  std::string Warnings;

private:
  vtkNew<vtkCallbackCommand> Callback;
  vtkSmartPointer<vtkObject> Observed;
  unsigned long Tags[2] = { 0, 0 };
};

/// A spherical map of the surface embed(S^2): an icosphere with `SurfaceArea` the area of
/// each triangle pushed through `embed`, `SurfacePoints` the embedded vertices, then moved
/// off center by the inversion with center `inversion`.
inline vtkSmartPointer<vtkPolyData> MakeSphericalMap(int levels,
  const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& embed,
  const Eigen::Vector3d& inversion = Eigen::Vector3d::Zero())
{
  mobius::Points sphere;
  mobius::Triangles triangles;
  mobius::MakeIcosphere(levels, sphere, triangles);
  mobius::Points surface(sphere.rows(), 3);
  for (Eigen::Index i = 0; i < sphere.rows(); ++i)
  {
    surface.row(i) = embed(sphere.row(i).transpose()).transpose();
  }
  mobius::ApplyInversion(inversion, sphere);

  auto map = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> surfacePoints;
  surfacePoints->SetName("SurfacePoints");
  surfacePoints->SetNumberOfComponents(3);
  for (Eigen::Index i = 0; i < sphere.rows(); ++i)
  {
    points->InsertNextPoint(sphere(i, 0), sphere(i, 1), sphere(i, 2));
    surfacePoints->InsertNextTuple3(surface(i, 0), surface(i, 1), surface(i, 2));
  }
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkDoubleArray> areas;
  areas->SetName("SurfaceArea");
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    const vtkIdType ids[3] = { triangles(t, 0), triangles(t, 1), triangles(t, 2) };
    polys->InsertNextCell(3, ids);
    const Eigen::Vector3d a = surface.row(ids[0]), b = surface.row(ids[1]), c = surface.row(ids[2]);
    areas->InsertNextValue(0.5 * (b - a).cross(c - a).norm());
  }
  map->SetPoints(points);
  map->SetPolys(polys);
  map->GetPointData()->AddArray(surfacePoints);
  map->GetCellData()->AddArray(areas);
  return map;
}

/// An asymmetric blob (stretched, with a bulge), so its centered map is far from the
/// identity.
inline Eigen::Vector3d BumpySurface(const Eigen::Vector3d& x)
{
  const double bulge =
    1.0 + 0.8 * std::exp(-4.0 * (x - Eigen::Vector3d(0.6, 0.6, 0.5)).squaredNorm());
  return Eigen::Vector3d(1.7 * x.x(), x.y(), 0.6 * x.z()) * bulge;
}

/// BumpySurface as a surface mesh (not a spherical map): an icosphere pushed through it.
inline vtkSmartPointer<vtkPolyData> BumpyMesh(int levels)
{
  mobius::Points sphere;
  mobius::Triangles triangles;
  mobius::MakeIcosphere(levels, sphere, triangles);
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (Eigen::Index i = 0; i < sphere.rows(); ++i)
  {
    const Eigen::Vector3d p = BumpySurface(sphere.row(i).transpose());
    points->InsertNextPoint(p.data());
  }
  vtkNew<vtkCellArray> polys;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    const vtkIdType ids[3] = { triangles(t, 0), triangles(t, 1), triangles(t, 2) };
    polys->InsertNextCell(3, ids);
  }
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}

/// First component of field-data array `name`, NaN if absent.
inline double FieldValue(vtkPolyData* data, const char* name)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array ? array->GetComponent(0, 0) : std::nan("");
}
}

#define MOBIUS_EXPECT(condition)                                                                   \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #condition << std::endl;      \
      ++failures;                                                                                  \
    }                                                                                              \
  } while (false)

// Splits every triangle into four at its edge midpoints; the original points keep their ids.
inline vtkSmartPointer<vtkPolyData> MidpointSubdivision(vtkPolyData* mesh)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->DeepCopy(mesh->GetPoints());
  std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> midpoints;
  auto middle = [&](vtkIdType a, vtkIdType b) {
    const auto key = std::minmax(a, b);
    auto found = midpoints.find(key);
    if (found != midpoints.end())
    {
      return found->second;
    }
    double p[3], q[3];
    points->GetPoint(a, p);
    points->GetPoint(b, q);
    const vtkIdType id = points->InsertNextPoint((p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2);
    midpoints.emplace(key, id);
    return id;
  };
  vtkNew<vtkCellArray> triangles;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* ids;
    mesh->GetCellPoints(c, npts, ids);
    const vtkIdType ab = middle(ids[0], ids[1]), bc = middle(ids[1], ids[2]), ca = middle(ids[2], ids[0]);
    const vtkIdType pieces[4][3] = { { ids[0], ab, ca }, { ids[1], bc, ab }, { ids[2], ca, bc },
      { ab, bc, ca } };
    for (const auto& piece : pieces)
    {
      triangles->InsertNextCell(3, piece);
    }
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->SetPoints(points);
  result->SetPolys(triangles);
  return result;
}

// Runs `filter` and checks it fails with an error containing `words` and an empty output.
inline int ExpectError(vtkPolyDataAlgorithm* filter, const std::string& words)
{
  int failures = 0;
  mobius_test::MessageCatcher catcher(filter);
  mobius_test::MessageCatcher executiveCatcher(filter->GetExecutive());
  filter->Update();
  if (catcher.Error.find(words) == std::string::npos)
  {
    std::cerr << filter->GetClassName() << ": expected an error containing '" << words
              << "', got '" << catcher.Error << "'\n";
    ++failures;
  }
  MOBIUS_EXPECT(filter->GetOutput()->GetNumberOfPoints() == 0);
  return failures;
}

#endif
