#include "MobiusSphericalMapData.h"

#include "LandmarkAlignment.h"
#include "MapDistortion.h"

#include <Eigen/Geometry> // cross

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <new>
#include <sstream>
#include <utility>
#include <vector>

namespace mobius
{
namespace vtk
{
namespace
{
bool NeedsTriangulation(vtkPolyData* input)
{
  if (input->GetNumberOfStrips() > 0 || input->GetNumberOfVerts() > 0 ||
    input->GetNumberOfLines() > 0)
  {
    return true;
  }
  vtkCellArray* polys = input->GetPolys();
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    if (polys->GetCellSize(c) != 3)
    {
      return true;
    }
  }
  return false;
}

}

vtkSmartPointer<vtkPolyData> TriangulatedSurface(vtkPolyData* input)
{
  if (!NeedsTriangulation(input))
  {
    return input;
  }
  vtkNew<vtkPolyData> shallow;
  shallow->ShallowCopy(input);
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(shallow);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  return triangulate->GetOutput();
}

std::string ExtractPoints(vtkPolyData* input, Points& points)
{
  const vtkIdType n = input->GetNumberOfPoints();
  if (n == 0)
  {
    return "the input has no points";
  }
  points.resize(n, 3);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      std::ostringstream error;
      error << "point " << i << " has a NaN or infinite coordinate";
      return error.str();
    }
    points.row(i) << p[0], p[1], p[2];
  }
  return {};
}

std::string CheckCellPointIds(vtkPolyData* input)
{
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  const std::pair<vtkCellArray*, const char*> kinds[] = { { input->GetVerts(), "vertex cell" },
    { input->GetLines(), "line" }, { input->GetPolys(), "polygon" },
    { input->GetStrips(), "triangle strip" } };
  for (const auto& kind : kinds)
  {
    if (!kind.first)
    {
      continue;
    }
    const vtkIdType cells = kind.first->GetNumberOfCells();
    for (vtkIdType c = 0; c < cells; ++c)
    {
      vtkIdType npts = 0;
      const vtkIdType* ids = nullptr;
      kind.first->GetCellAtId(c, npts, ids);
      for (vtkIdType k = 0; k < npts; ++k)
      {
        if (ids[k] < 0 || ids[k] >= numberOfPoints)
        {
          std::ostringstream error;
          error << kind.second << " " << c << " refers to point " << ids[k]
                << ", but there are " << numberOfPoints << " points (ids 0 to "
                << numberOfPoints - 1 << ")";
          return error.str();
        }
      }
    }
  }
  return {};
}

std::string ExtractTriangles(vtkPolyData* input, Triangles& triangles)
{
  if (input->GetNumberOfLines() > 0 || input->GetNumberOfStrips() > 0)
  {
    std::ostringstream error;
    error << "the input has " << input->GetNumberOfLines() << " line and "
          << input->GetNumberOfStrips()
          << " triangle-strip cells; only triangles are accepted (apply vtkTriangleFilter)";
    return error.str();
  }
  vtkCellArray* polys = input->GetPolys();
  triangles.resize(polys->GetNumberOfCells(), 3);
  vtkIdType npts = 0;
  const vtkIdType* ids = nullptr;
  // An iterator of our own, not the cell array's InitTraversal/GetNextCell: that cursor
  // lives in the array, which two meshes may share (a vtkTransformFilter's output shares its
  // input's cells), and the registration pipeline maps both meshes at once.
  auto cells = ::vtk::TakeSmartPointer(polys->NewIterator());
  vtkIdType t = 0;
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell(), ++t)
  {
    cells->GetCurrentCell(npts, ids);
    if (npts != 3)
    {
      std::ostringstream error;
      error << "polygon " << t << " has " << npts
            << " points; only triangles are accepted (apply vtkTriangleFilter)";
      return error.str();
    }
    for (int k = 0; k < 3; ++k)
    {
      if (ids[k] < 0 || ids[k] >= input->GetNumberOfPoints())
      {
        std::ostringstream error;
        error << "triangle " << t << " refers to point " << ids[k] << ", but there are "
              << input->GetNumberOfPoints() << " points (ids 0 to "
              << input->GetNumberOfPoints() - 1 << ")";
        return error.str();
      }
    }
    triangles.row(t) << ids[0], ids[1], ids[2];
  }
  return {};
}

std::string CheckOnUnitSphere(const Points& points)
{
  for (Eigen::Index i = 0; i < points.rows(); ++i)
  {
    const double radius = points.row(i).norm();
    if (std::abs(radius - 1.0) > UnitSphereTolerance)
    {
      std::ostringstream error;
      error << "point " << i << " is not on the unit sphere (radius " << radius
            << ", tolerance " << UnitSphereTolerance
            << "): the input must be a spherical map, e.g. the output of vtkSphericalConformalMap";
      return error.str();
    }
  }
  return {};
}

std::string ExtractSurfaceAreas(vtkPolyData* input, Vector& areas)
{
  vtkDataArray* array = input->GetCellData()->GetArray(SurfaceAreaArrayName);
  if (!array)
  {
    return std::string("the input has no cell array '") + SurfaceAreaArrayName +
      "' (the original surface area of each triangle; vtkSphericalConformalMap makes it)";
  }
  if (array->GetNumberOfComponents() != 1)
  {
    return std::string("cell array '") + SurfaceAreaArrayName + "' must have one component";
  }
  // Cell data is indexed over verts, lines, polys, strips in that order.
  const vtkIdType offset = input->GetNumberOfVerts() + input->GetNumberOfLines();
  const vtkIdType count = input->GetNumberOfPolys();
  areas.resize(count);
  for (vtkIdType t = 0; t < count; ++t)
  {
    const double area = array->GetComponent(offset + t, 0);
    if (!std::isfinite(area) || area < 0)
    {
      std::ostringstream error;
      error << "cell array '" << SurfaceAreaArrayName << "' has an invalid value " << area
            << " at triangle " << t << "; areas must be finite and not negative";
      return error.str();
    }
    areas[t] = area;
  }
  return {};
}

std::string ExtractSphericalMap(vtkPolyData* input, bool allowPointSet, Points& points,
  Triangles& triangles, Vector& areas)
{
  std::string error = ExtractPoints(input, points);
  if (error.empty())
  {
    error = ExtractTriangles(input, triangles);
  }
  if (error.empty() && triangles.rows() == 0 && !allowPointSet)
  {
    error = "the input has no triangles";
  }
  if (error.empty())
  {
    error = CheckOnUnitSphere(points);
  }
  if (error.empty() && triangles.rows() > 0)
  {
    error = ExtractSurfaceAreas(input, areas);
  }
  return error;
}

std::string CheckSurfacePoints(vtkPolyData* input)
{
  vtkDataArray* array = input->GetPointData()->GetArray(SurfacePointsArrayName);
  if (!array || array->GetNumberOfComponents() != 3 ||
    array->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    return std::string("it has no 3-component point array '") + SurfacePointsArrayName +
      "' (the original surface positions; vtkSphericalConformalMap makes it)";
  }
  return {};
}

std::string ExtractSurfacePoints(vtkPolyData* input, Points& surfacePoints)
{
  const std::string error = CheckSurfacePoints(input);
  if (!error.empty())
  {
    return error;
  }
  vtkDataArray* array = input->GetPointData()->GetArray(SurfacePointsArrayName);
  surfacePoints.resize(array->GetNumberOfTuples(), 3);
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    double p[3];
    array->GetTuple(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      std::ostringstream error;
      error << "point array '" << SurfacePointsArrayName << "' is not finite at point " << i;
      return error.str();
    }
    surfacePoints.row(i) << p[0], p[1], p[2];
  }
  return {};
}

int ReportException(vtkAlgorithm* filter, vtkInformationVector* outputVector,
  const std::string& subject)
{
  std::string reason;
  try
  {
    throw;
  }
  catch (const std::bad_alloc&)
  {
    reason = "out of memory (std::bad_alloc); the input or a setting such as Resolution is "
             "too large for this machine";
  }
  catch (const std::exception& exception)
  {
    reason = exception.what();
  }
  catch (...)
  {
    reason = "an unknown exception";
  }
  // A half-built output must not look like a result.
  for (int port = 0; outputVector && port < outputVector->GetNumberOfInformationObjects(); ++port)
  {
    if (vtkDataObject* output =
          outputVector->GetInformationObject(port)->Get(vtkDataObject::DATA_OBJECT()))
    {
      output->Initialize();
    }
  }
  vtkErrorWithObjectMacro(
    filter, << (subject.empty() ? std::string("Failed") : subject) << ": " << reason << ".");
  return 0;
}

std::function<bool(double)> ProgressAndAbort(vtkAlgorithm* filter)
{
  return [filter](double fraction) {
    filter->UpdateProgress(fraction);
    return !filter->GetAbortExecute();
  };
}

void SetPoints(vtkPolyData* output, const Points& points)
{
  vtkNew<vtkPoints> vtkpoints;
  vtkpoints->SetDataTypeToDouble();
  vtkpoints->SetNumberOfPoints(points.rows());
  for (Eigen::Index i = 0; i < points.rows(); ++i)
  {
    vtkpoints->SetPoint(i, points(i, 0), points(i, 1), points(i, 2));
  }
  output->SetPoints(vtkpoints);
}

void SetTriangles(vtkPolyData* output, const Triangles& triangles)
{
  vtkNew<vtkCellArray> polys;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    const vtkIdType ids[3] = { triangles(t, 0), triangles(t, 1), triangles(t, 2) };
    polys->InsertNextCell(3, ids);
  }
  output->SetPolys(polys);
}

namespace
{
// One tuple of `count` components.
template <typename ArrayType, typename Value>
void SetOneTuple(vtkFieldData* fieldData, const char* name, const Value* values, int count)
{
  vtkNew<ArrayType> array;
  array->SetName(name);
  array->SetNumberOfComponents(count);
  array->SetNumberOfTuples(1);
  for (int k = 0; k < count; ++k)
  {
    array->SetTypedComponent(0, k, values[k]);
  }
  fieldData->RemoveArray(name);
  fieldData->AddArray(array);
}
}

void SetFieldValues(vtkFieldData* fieldData, const char* name, const double* values, int count)
{
  SetOneTuple<vtkDoubleArray>(fieldData, name, values, count);
}

void SetFieldIntegers(vtkFieldData* fieldData, const char* name, const int* values, int count)
{
  SetOneTuple<vtkIntArray>(fieldData, name, values, count);
}

void SetFieldValue(vtkFieldData* fieldData, const char* name, double value)
{
  SetFieldValues(fieldData, name, &value, 1);
}

void SetFieldInteger(vtkFieldData* fieldData, const char* name, int value)
{
  SetOneTuple<vtkIntArray>(fieldData, name, &value, 1);
}

void SetFieldCount(vtkFieldData* fieldData, const char* name, vtkIdType value)
{
  SetOneTuple<vtkIdTypeArray>(fieldData, name, &value, 1);
}

void AddDistortionArrays(vtkPolyData* map, const char* active)
{
  Points mapped, surface;
  Triangles triangles;
  if (!ExtractPoints(map, mapped).empty() || !ExtractTriangles(map, triangles).empty() ||
    !ExtractSurfacePoints(map, surface).empty() || surface.rows() != mapped.rows())
  {
    return;
  }
  const Eigen::Index count = triangles.rows();
  std::vector<double> surfaceAreas(count), mappedAreas(count);
  double surfaceTotal = 0, mappedTotal = 0;
  vtkNew<vtkDoubleArray> quasiConformal;
  quasiConformal->SetName("QuasiConformalDistortion");
  quasiConformal->SetNumberOfTuples(count);
  for (Eigen::Index t = 0; t < count; ++t)
  {
    const Eigen::Vector3d p[3] = { surface.row(triangles(t, 0)).transpose(),
      surface.row(triangles(t, 1)).transpose(), surface.row(triangles(t, 2)).transpose() };
    const Eigen::Vector3d q[3] = { mapped.row(triangles(t, 0)).transpose(),
      mapped.row(triangles(t, 1)).transpose(), mapped.row(triangles(t, 2)).transpose() };
    surfaceAreas[t] = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
    mappedAreas[t] = 0.5 * (q[1] - q[0]).cross(q[2] - q[0]).norm();
    surfaceTotal += surfaceAreas[t];
    mappedTotal += mappedAreas[t];
    quasiConformal->SetValue(t, surfaceAreas[t] > 0
        ? TriangleQuasiConformalDistortion(p[0], p[1], p[2], q[0], q[1], q[2])
        : 1.0);
  }
  vtkNew<vtkDoubleArray> logAreaRatio;
  logAreaRatio->SetName("LogAreaRatio");
  logAreaRatio->SetNumberOfTuples(count);
  for (Eigen::Index t = 0; t < count; ++t)
  {
    // Clamped to +-60 (a factor of 1e18): a triangle collapsed to a point has no finite
    // log; one with no area on either side (0 / 0) counts as keeping its area.
    const double logRatio =
      std::log2((mappedAreas[t] / mappedTotal) / (surfaceAreas[t] / surfaceTotal));
    logAreaRatio->SetValue(t, std::isnan(logRatio) ? 0.0 : std::max(-60.0, std::min(60.0, logRatio)));
  }
  map->GetCellData()->AddArray(quasiConformal);
  map->GetCellData()->AddArray(logAreaRatio);
  map->GetCellData()->SetActiveScalars(active);
}

std::string CheckLandmarkPoints(const std::vector<std::pair<vtkIdType, vtkIdType>>& landmarks,
  vtkIdType sourcePoints, vtkIdType targetPoints)
{
  const std::vector<std::pair<Index, Index>> ids(landmarks.begin(), landmarks.end());
  const Index counts[2] = { sourcePoints, targetPoints };
  const std::string names[2] = { "Source (port 0)", "Target (port 1)" };
  return CheckLandmarkIds(ids, counts, names);
}
}
}
