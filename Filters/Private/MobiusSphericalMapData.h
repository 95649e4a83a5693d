/**
 * @file MobiusSphericalMapData.h
 * @brief Conversions between vtkPolyData spherical maps and the VTK-free core, and the
 * checks every filter applies to them (private to the module).
 *
 * A spherical map (see docs/architecture.md, "Pipeline and data contract") is a vtkPolyData of
 * triangles whose points lie on the unit sphere, with point data `SurfacePoints` (the
 * vertex on the original surface) and cell data `SurfaceArea` (the triangle's original
 * area). Each function returns an empty string on success, else a message naming the
 * problem, ready for vtkErrorMacro.
 */
#ifndef MobiusSphericalMapData_h
#define MobiusSphericalMapData_h

#include "MeshTypes.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer
#include "vtkType.h"         // For vtkIdType

#include <functional>
#include <string>
#include <utility>
#include <vector>

class vtkAlgorithm;
class vtkFieldData;
class vtkInformationVector;
class vtkPolyData;

namespace mobius
{
namespace vtk
{
/// Array names of the data contract; part of the public API, keep them stable.
constexpr const char* SurfacePointsArrayName = "SurfacePoints";
constexpr const char* SurfaceAreaArrayName = "SurfaceArea";
/// Point array of vtkSphericalConformalMap's output: the index of the point in the filter's
/// input (-1 for a point a repair created), i.e. the vertex number in the mesh file.
constexpr const char* InputPointIdArrayName = "InputPointId";
/// Cell array of vtkSphericalConformalMap's output: the triangle of its input (polygons split
/// into triangles, TriangulatedSurface) each triangle came from, -1 for one a repair created.
constexpr const char* InputCellIdArrayName = "InputCellId";

/// Distance from 1 that a spherical map's point radius may have.
constexpr double UnitSphereTolerance = 1e-6;

/// The input's triangles: `input` itself when its cells are all triangles, else a copy with
/// polygons and strips split into triangles (in cell order) and vertex and line cells
/// dropped with their data. The triangles every filter and result number.
vtkSmartPointer<vtkPolyData> TriangulatedSurface(vtkPolyData* input);

/// Copies the points; fails on an empty point set or NaN/Inf coordinates.
std::string ExtractPoints(vtkPolyData* input, Points& points);

/// Fails if a cell (vertex, line, polygon or strip) refers to a point id outside
/// [0, number of points): VTK's readers do not check, and every later step would read or
/// write out of bounds.
std::string CheckCellPointIds(vtkPolyData* input);

/// Copies the polygons, all of which must be triangles of point ids in range; fails on
/// lines, strips, polygons of other sizes and ids outside [0, number of points).
std::string ExtractTriangles(vtkPolyData* input, Triangles& triangles);

/// Fails unless every point is within UnitSphereTolerance of the unit sphere.
std::string CheckOnUnitSphere(const Points& points);

/// Reads cell data `SurfaceArea` for the triangles: present, one component, finite, > 0.
std::string ExtractSurfaceAreas(vtkPolyData* input, Vector& areas);

/// All of the above for a spherical map: points (finite, on the unit sphere), triangles
/// and their `SurfaceArea`. With `allowPointSet`, an input without polygons is accepted as
/// a point set (no triangles, no areas); otherwise it is an error.
std::string ExtractSphericalMap(vtkPolyData* input, bool allowPointSet, Points& points,
  Triangles& triangles, Vector& areas);

/// Checks that point data `SurfacePoints` is there with 3 components and one tuple per point.
std::string CheckSurfacePoints(vtkPolyData* input);

/// Reads point data `SurfacePoints` (CheckSurfacePoints, and finite).
std::string ExtractSurfacePoints(vtkPolyData* input, Points& surfacePoints);

/// The first of a stage filter's landmarks (point ids of its Source and Target maps) naming
/// a point its map does not have, e.g. "landmark 2 names point 5000 of the Target (port 1),
/// which has 4000 points"; empty if every one names a point.
std::string CheckLandmarkPoints(const std::vector<std::pair<vtkIdType, vtkIdType>>& landmarks,
  vtkIdType sourcePoints, vtkIdType targetPoints);

/// For a filter's RequestData, inside `catch (...)`: reports the exception being handled
/// (std::bad_alloc as running out of memory) as the filter's error, prefixed by `subject`
/// when given (a file name), empties the output and returns 0 (RequestData's failure).
int ReportException(vtkAlgorithm* filter, vtkInformationVector* outputVector,
  const std::string& subject = {});

/// A core progress callback for `filter`: reports the fraction done as the filter's progress
/// and returns false once the filter is asked to abort.
std::function<bool(double)> ProgressAndAbort(vtkAlgorithm* filter);

/// Replaces the output's points by `points` (double precision).
void SetPoints(vtkPolyData* output, const Points& points);

/// Replaces the output's polygons by `triangles`.
void SetTriangles(vtkPolyData* output, const Triangles& triangles);

/// Per-triangle distortion of the map from the surface (point array `SurfacePoints`) to
/// the output's points, as cell arrays to color the map by: `QuasiConformalDistortion`
/// (sigma_max / sigma_min of the triangle's linear map, 1 where it is conformal) and
/// `LogAreaRatio` (log2 of the triangle's share of the sphere over its share of the
/// surface, 0 where the map keeps area). `active` (one of the two names) becomes the active
/// cell scalars: ParaView colors a new display by them. Does nothing without SurfacePoints
/// or triangles.
void AddDistortionArrays(vtkPolyData* map, const char* active);

/// Adds (or replaces) a named field-data array with one tuple of `count` components.
void SetFieldValues(vtkFieldData* fieldData, const char* name, const double* values, int count);
void SetFieldValue(vtkFieldData* fieldData, const char* name, double value);
/// The same with one integer (docs/data-contract.md, "Types of field values"): a 0/1 flag,
/// a setting or a small count (iterations, threads, a candidate) in a vtkIntArray; a count
/// of mesh elements (points, vertices, triangles, edges) in a vtkIdTypeArray.
void SetFieldInteger(vtkFieldData* fieldData, const char* name, int value);
void SetFieldCount(vtkFieldData* fieldData, const char* name, vtkIdType value);
/// Several integers (flags or settings, e.g. one per input) in one tuple of a vtkIntArray.
void SetFieldIntegers(vtkFieldData* fieldData, const char* name, const int* values, int count);
}
}

#endif
