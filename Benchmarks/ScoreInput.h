// Input of mobius-score: meshes, mobius-register's map CSVs, and the number parsing they
// share; every function returns false with a one-line message naming the file.
#ifndef ScoreInput_h
#define ScoreInput_h

#include "CorrespondenceScore.h"

#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

/// Reads a mesh, turning the reader's error into one line that names the file.
bool ReadMesh(const std::string& path, vtkSmartPointer<vtkPolyData>& mesh, std::string& error);

/// The mesh as the core sees it: points, and triangles split from polygons the way
/// vtkSphericalConformalMap splits them (vtkTriangleFilter), so triangle rows match the map's.
bool ExtractTriangleMesh(
  vtkPolyData* input, mobius::Points& points, mobius::Triangles& triangles, std::string& error);

/// Comma- or blank-separated fields of a line (empty fields are dropped).
std::vector<std::string> Fields(const std::string& line);

/// A whole-text integer / finite number.
bool ParseIndex(const std::string& text, mobius::Index& value);
bool ParseNumber(const std::string& text, double& value);

/// mobius-register's OUT.csv (source_vertex, target_triangle, target_vertex_0..2,
/// barycentric_0..2, ...; columns found by name): per source vertex, in order, the point of
/// the target (points, triangles) it is mapped to.
bool ReadMap(const std::string& path, const mobius::Points& points,
  const mobius::Triangles& triangles, std::vector<mobius::SurfacePoint>& mapped,
  std::string& error);

#endif
