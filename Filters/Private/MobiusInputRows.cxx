#include "MobiusInputRows.h"

#include "MobiusCorrespondenceOutput.h"
#include "MobiusSphericalMapData.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticCellLocator.h"
#include "vtkStringArray.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

namespace mobius
{
namespace vtk
{
namespace
{
struct Location
{
  vtkIdType Triangle = -1;
  Eigen::Vector3d Weights = Eigen::Vector3d::Zero();
};

// A triangle mesh's closest points, with barycentric coordinates.
class ClosestPoints
{
public:
  ClosestPoints(const Points& points, const Triangles& triangles)
    : Corners(points)
    , Faces(triangles)
  {
    SetPoints(this->Surface, points);
    SetTriangles(this->Surface, triangles);
    this->Locator->SetDataSet(this->Surface);
    this->Locator->BuildLocator();
  }

  Location Find(const Eigen::Vector3d& x) const
  {
    double closest[3], distance2;
    vtkIdType cell = -1;
    int sub = 0;
    this->Locator->FindClosestPoint(const_cast<double*>(x.data()), closest, cell, sub, distance2);
    Location location;
    location.Triangle = cell;
    if (cell >= 0)
    {
      location.Weights = this->Barycentric(cell, Eigen::Vector3d(closest[0], closest[1], closest[2]));
      return location;
    }
    return this->NearestCorner(x);
  }

private:
  // The corner nearest to x, in long double (whose range holds the squares of coordinates
  // near the largest doubles, which the locator's distances overflow): a point so far away
  // that the locator finds no cell.
  Location NearestCorner(const Eigen::Vector3d& x) const
  {
    Location location;
    long double best = -1;
    for (Index t = 0; t < this->Faces.rows(); ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        long double distance = 0;
        for (int c = 0; c < 3; ++c)
        {
          const long double d = static_cast<long double>(this->Corners(this->Faces(t, k), c)) - x[c];
          distance += d * d;
        }
        if (best < 0 || distance < best)
        {
          best = distance;
          location.Triangle = t;
          location.Weights = Eigen::Vector3d::Unit(k);
        }
      }
    }
    return location;
  }

  // Barycentric coordinates of a point of triangle t (least squares in its plane).
  Eigen::Vector3d Barycentric(vtkIdType t, const Eigen::Vector3d& x) const
  {
    const Eigen::Vector3d a = this->Corners.row(this->Faces(t, 0)), b = this->Corners.row(this->Faces(t, 1)),
                          c = this->Corners.row(this->Faces(t, 2));
    Eigen::Matrix<double, 3, 2> edges;
    edges << b - a, c - a;
    Eigen::Vector2d st = edges.colPivHouseholderQr().solve(x - a);
    if (!st.allFinite())
    {
      st.setZero(); // a degenerate triangle: its first corner
    }
    Eigen::Vector3d w(1 - st.sum(), st[0], st[1]);
    w = w.cwiseMax(0.0);
    return w / w.sum();
  }

  const Points& Corners;
  const Triangles& Faces;
  vtkNew<vtkPolyData> Surface;
  vtkNew<vtkStaticCellLocator> Locator;
};

// A spherical map's surface: its SurfacePoints and triangles.
void MapSurface(vtkPolyData* map, Points& points, Triangles& triangles, std::string& error)
{
  error = ExtractSurfacePoints(map, points);
  error = error.empty() ? ExtractTriangles(map, triangles) : error;
}

// Each input vertex's first point in `map` (its InputPointId), -1 where it has none.
std::vector<vtkIdType> ProxyRows(vtkPolyData* map, vtkIdType inputPoints)
{
  std::vector<vtkIdType> rows(static_cast<size_t>(inputPoints), -1);
  vtkDataArray* ids = map->GetPointData()->GetArray(InputPointIdArrayName);
  for (vtkIdType p = ids ? ids->GetNumberOfTuples() - 1 : -1; p >= 0; --p)
  {
    const auto id = static_cast<vtkIdType>(ids->GetComponent(p, 0));
    if (id >= 0 && id < inputPoints)
    {
      rows[id] = p;
    }
  }
  return rows;
}

// Where the images land on the target as given: a triangle of the target's map that came
// from a triangle of the input (InputCellId) is that triangle, its weights matched to the
// input's corners by position (the repairs move no input point); an image on any other (a
// patch the repair created) goes to its closest point on the input's triangles that the map
// kept, and its row is marked.
class TargetAsGiven
{
public:
  TargetAsGiven(vtkPolyData* targetMap, const Triangles& mapTriangles, const Points& mapSurface,
    const Points& inputPoints, const Triangles& inputTriangles)
    : MapTriangles(mapTriangles)
    , MapSurface(mapSurface)
    , InputCells(targetMap->GetCellData()->GetArray(InputCellIdArrayName))
    , InputPoints(inputPoints)
    , InputTriangles(inputTriangles)
  {
  }

  Location Convert(const Location& onMap, int& flags)
  {
    const vtkIdType source = this->InputCells
      ? static_cast<vtkIdType>(this->InputCells->GetComponent(onMap.Triangle, 0))
      : -1;
    Location location;
    location.Triangle = source;
    int matched = 0;
    for (int k = 0; source >= 0 && source < this->InputTriangles.rows() && k < 3; ++k)
    {
      const auto corner = this->MapSurface.row(this->MapTriangles(onMap.Triangle, k));
      for (int l = 0; l < 3; ++l)
      {
        if (corner == this->InputPoints.row(this->InputTriangles(source, l)))
        {
          location.Weights[l] += onMap.Weights[k];
          ++matched;
          break;
        }
      }
    }
    if (matched == 3)
    {
      return location;
    }
    flags |= kImageMovedOffPatch;
    return this->ClosestKept(this->PointOf(onMap));
  }

private:
  Eigen::Vector3d PointOf(const Location& onMap) const
  {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
    {
      x += onMap.Weights[k] * this->MapSurface.row(this->MapTriangles(onMap.Triangle, k)).transpose();
    }
    return x;
  }

  // The closest point among the input's triangles the map kept (not a fin, a loose part or a
  // triangle removed as a duplicate); their locator is built when a patch is first met.
  Location ClosestKept(const Eigen::Vector3d& x)
  {
    if (!this->Kept)
    {
      std::vector<char> kept(static_cast<size_t>(this->InputTriangles.rows()), 0);
      for (vtkIdType t = 0; this->InputCells && t < this->InputCells->GetNumberOfTuples(); ++t)
      {
        const auto source = static_cast<vtkIdType>(this->InputCells->GetComponent(t, 0));
        if (source >= 0 && source < this->InputTriangles.rows())
        {
          kept[source] = 1;
        }
      }
      for (Index t = 0; t < this->InputTriangles.rows(); ++t)
      {
        if (kept[t])
        {
          this->KeptRows.push_back(t);
        }
      }
      this->KeptTriangles.resize(static_cast<Index>(this->KeptRows.size()), 3);
      for (size_t r = 0; r < this->KeptRows.size(); ++r)
      {
        this->KeptTriangles.row(static_cast<Index>(r)) = this->InputTriangles.row(this->KeptRows[r]);
      }
      this->Kept = std::make_unique<ClosestPoints>(this->InputPoints, this->KeptTriangles);
    }
    Location location = this->Kept->Find(x);
    location.Triangle = this->KeptRows[location.Triangle];
    return location;
  }

  const Triangles& MapTriangles;
  const Points& MapSurface;
  vtkDataArray* InputCells;
  const Points& InputPoints;
  const Triangles& InputTriangles;
  std::vector<Index> KeptRows;
  Triangles KeptTriangles;
  std::unique_ptr<ClosestPoints> Kept;
};

// A copy of `mesh` (shallow) with point data SurfacePoints (its own points) and
// InputPointId (its own numbers), as the correspondence's query or located mesh.
vtkSmartPointer<vtkPolyData> AsMapOfItself(vtkPolyData* mesh, const Points& points)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(mesh);
  vtkNew<vtkDoubleArray> surface;
  surface->SetName(SurfacePointsArrayName);
  surface->SetNumberOfComponents(3);
  surface->SetNumberOfTuples(points.rows());
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName(InputPointIdArrayName);
  ids->SetNumberOfTuples(points.rows());
  for (Index i = 0; i < points.rows(); ++i)
  {
    surface->SetTuple(i, points.row(i).data());
    ids->SetValue(i, i);
  }
  vtkNew<vtkPointData> data;
  data->ShallowCopy(mesh->GetPointData());
  data->RemoveArray(SurfacePointsArrayName);
  data->RemoveArray(InputPointIdArrayName);
  data->AddArray(surface);
  data->AddArray(ids);
  copy->GetPointData()->ShallowCopy(data);
  return copy;
}

// The proxy correspondence's per-row arrays the output does not have yet (e.g. MapStretch),
// at each source vertex: its own proxy row's value, or the value at its closest point
// (floating-point arrays interpolated, others from the nearest corner).
void CarryProxyArrays(vtkPolyData* correspondence, const std::vector<vtkIdType>& rows,
  const std::vector<Location>& closest, const Triangles& sourceTriangles, vtkPolyData* output)
{
  vtkPointData* from = correspondence->GetPointData();
  vtkPointData* to = output->GetPointData();
  for (int a = 0; a < from->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = from->GetArray(a);
    if (!array || !array->GetName() || to->HasArray(array->GetName()))
    {
      continue;
    }
    vtkSmartPointer<vtkDataArray> carried;
    carried.TakeReference(array->NewInstance());
    carried->SetName(array->GetName());
    carried->SetNumberOfComponents(array->GetNumberOfComponents());
    carried->SetNumberOfTuples(static_cast<vtkIdType>(rows.size()));
    const bool interpolate = array->GetDataType() == VTK_FLOAT || array->GetDataType() == VTK_DOUBLE;
    vtkNew<vtkIdList> corners;
    corners->SetNumberOfIds(3);
    for (size_t i = 0; i < rows.size(); ++i)
    {
      const vtkIdType row = static_cast<vtkIdType>(i);
      if (rows[i] >= 0)
      {
        carried->SetTuple(row, rows[i], array);
        continue;
      }
      const Location& at = closest[i];
      Eigen::Index nearest = 0;
      at.Weights.maxCoeff(&nearest);
      for (int k = 0; k < 3; ++k)
      {
        corners->SetId(k, sourceTriangles(at.Triangle, k));
      }
      if (interpolate)
      {
        carried->InterpolateTuple(row, corners, array, const_cast<double*>(at.Weights.data()));
      }
      else
      {
        carried->SetTuple(row, sourceTriangles(at.Triangle, nearest), array);
      }
    }
    to->AddArray(carried);
  }
}
}

vtkSmartPointer<vtkPolyData> SurfaceAsGiven(vtkPolyData* mesh)
{
  const vtkSmartPointer<vtkPolyData> triangles = TriangulatedSurface(mesh);
  Points points;
  ExtractPoints(triangles, points);
  return AsMapOfItself(triangles, points);
}

bool MapWasRepaired(vtkPolyData* map)
{
  auto repairs = vtkStringArray::SafeDownCast(map->GetFieldData()->GetAbstractArray("MeshRepairs"));
  return repairs && repairs->GetNumberOfValues() > 0;
}

vtkSmartPointer<vtkPolyData> CorrespondenceOnInputs(vtkPolyData* source, vtkPolyData* target,
  vtkPolyData* sourceMap, vtkPolyData* targetMap, vtkPolyData* correspondence,
  bool pointsOnTarget, std::string& error)
{
  Points sourcePoints, sourceSurface, targetSurface, targetPoints;
  Triangles sourceTriangles, targetMapTriangles, targetTriangles;
  const vtkSmartPointer<vtkPolyData> targetInput = TriangulatedSurface(target);
  MapSurface(sourceMap, sourceSurface, sourceTriangles, error);
  if (error.empty())
  {
    MapSurface(targetMap, targetSurface, targetMapTriangles, error);
  }
  error = error.empty() ? ExtractPoints(source, sourcePoints) : error;
  error = error.empty() ? ExtractPoints(targetInput, targetPoints) : error;
  error = error.empty() ? ExtractTriangles(targetInput, targetTriangles) : error;
  vtkDataArray* cells = correspondence->GetPointData()->GetArray("TargetCellId");
  vtkDataArray* weights = correspondence->GetPointData()->GetArray("TargetBarycentric");
  vtkDataArray* mapped = correspondence->GetPointData()->GetArray("MappedPoints");
  if (error.empty() && (!cells || !weights || !mapped))
  {
    error = "the correspondence lacks TargetCellId, TargetBarycentric or MappedPoints";
  }
  if (!error.empty())
  {
    return nullptr;
  }
  const std::vector<vtkIdType> rows = ProxyRows(sourceMap, source->GetNumberOfPoints());
  const ClosestPoints onSourceProxy(sourceSurface, sourceTriangles);
  std::unique_ptr<ClosestPoints> onTargetProxy;
  TargetAsGiven asGiven(targetMap, targetMapTriangles, targetSurface, targetPoints, targetTriangles);
  SurfaceLocations locations;
  locations.LocatedTriangles = &targetTriangles;
  std::vector<Location> closest(rows.size());
  vtkNew<vtkIntArray> repaired;
  repaired->SetName(RepairedVertexArrayName);
  repaired->SetNumberOfTuples(static_cast<vtkIdType>(rows.size()));
  for (size_t i = 0; i < rows.size(); ++i)
  {
    int flags = 0;
    Location onTarget;
    if (rows[i] >= 0)
    {
      onTarget.Triangle = static_cast<vtkIdType>(cells->GetComponent(rows[i], 0));
      weights->GetTuple(rows[i], onTarget.Weights.data());
    }
    else
    {
      flags |= kRepairedSourceVertex;
      closest[i] = onSourceProxy.Find(sourcePoints.row(static_cast<Index>(i)).transpose());
      Eigen::Vector3d image = Eigen::Vector3d::Zero();
      for (int k = 0; k < 3; ++k)
      {
        double corner[3];
        mapped->GetTuple(sourceTriangles(closest[i].Triangle, k), corner);
        image += closest[i].Weights[k] * Eigen::Vector3d(corner[0], corner[1], corner[2]);
      }
      if (!onTargetProxy)
      {
        onTargetProxy = std::make_unique<ClosestPoints>(targetSurface, targetMapTriangles);
      }
      onTarget = onTargetProxy->Find(image);
    }
    const Location given = asGiven.Convert(onTarget, flags);
    locations.Triangle.push_back(given.Triangle);
    locations.Barycentric.push_back(given.Weights);
    repaired->SetValue(static_cast<vtkIdType>(i), flags);
  }
  auto output = vtkSmartPointer<vtkPolyData>::New();
  AssembleCorrespondence(AsMapOfItself(source, sourcePoints), AsMapOfItself(targetInput, targetPoints),
    locations, pointsOnTarget, output);
  CarryProxyArrays(correspondence, rows, closest, sourceTriangles, output);
  output->GetPointData()->AddArray(repaired);
  output->GetFieldData()->ShallowCopy(correspondence->GetFieldData());
  return output;
}
}
}
