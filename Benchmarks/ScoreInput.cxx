#include "ScoreInput.h"

#include "MobiusFilterMessages.h"
#include "TextFormats.h"
#include "vtkCellArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkSurfaceMeshReader.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

namespace
{
// Finds the triangle with vertices {a, b, c} (in any order) and orders the weights like its row.
class TriangleFinder
{
public:
  explicit TriangleFinder(const mobius::Triangles& triangles)
    : Rows(triangles)
  {
  }

  // Row `hint` if it has these vertices, otherwise any row that has; -1 if none.
  mobius::Index Find(mobius::Index hint, const std::array<mobius::Index, 3>& vertices,
    const Eigen::Vector3d& weights, Eigen::Vector3d& ordered)
  {
    if (hint >= 0 && hint < this->Rows.rows() && this->Match(hint, vertices, weights, ordered))
    {
      return hint;
    }
    if (this->Lookup.empty())
    {
      for (mobius::Index t = 0; t < this->Rows.rows(); ++t)
      {
        this->Lookup.emplace(Key({ this->Rows(t, 0), this->Rows(t, 1), this->Rows(t, 2) }), t);
      }
    }
    const auto found = this->Lookup.find(Key(vertices));
    if (found != this->Lookup.end() && this->Match(found->second, vertices, weights, ordered))
    {
      return found->second;
    }
    return -1;
  }

private:
  static std::array<mobius::Index, 3> Key(std::array<mobius::Index, 3> vertices)
  {
    std::sort(vertices.begin(), vertices.end());
    return vertices;
  }

  bool Match(mobius::Index t, const std::array<mobius::Index, 3>& vertices,
    const Eigen::Vector3d& weights, Eigen::Vector3d& ordered) const
  {
    std::array<bool, 3> used = { false, false, false };
    for (int k = 0; k < 3; ++k)
    {
      int j = 0;
      while (j < 3 && (used[j] || vertices[j] != this->Rows(t, k)))
      {
        ++j;
      }
      if (j == 3)
      {
        return false;
      }
      used[j] = true;
      ordered[k] = weights[j];
    }
    return true;
  }

  const mobius::Triangles& Rows;
  std::map<std::array<mobius::Index, 3>, mobius::Index> Lookup;
};

}

bool ReadMesh(const std::string& path, vtkSmartPointer<vtkPolyData>& mesh, std::string& error)
{
  vtkNew<vtkSurfaceMeshReader> reader;
  mobius::vtk::FilterMessages messages(reader, /*catchWarnings=*/false);
  const std::string& message = messages.Error;
  reader->SetFileName(path.c_str());
  reader->Update();
  if (!message.empty() || reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    const auto start = message.find(path);
    error = start != std::string::npos ? message.substr(start) : path + ": cannot read the mesh";
    return false;
  }
  mesh = reader->GetOutput();
  return true;
}

bool ExtractTriangleMesh(
  vtkPolyData* input, mobius::Points& points, mobius::Triangles& triangles, std::string& error)
{
  vtkSmartPointer<vtkPolyData> surface = input;
  bool triangulate = input->GetNumberOfStrips() > 0;
  vtkCellArray* polys = input->GetPolys();
  for (vtkIdType c = 0; c < polys->GetNumberOfCells() && !triangulate; ++c)
  {
    triangulate = polys->GetCellSize(c) != 3;
  }
  if (triangulate)
  {
    vtkNew<vtkPolyData> shallow;
    shallow->ShallowCopy(input);
    vtkNew<vtkTriangleFilter> filter;
    filter->SetInputData(shallow);
    filter->PassVertsOff();
    filter->PassLinesOff();
    filter->Update();
    surface = filter->GetOutput();
  }
  points.resize(surface->GetNumberOfPoints(), 3);
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    double x[3];
    surface->GetPoint(i, x);
    points.row(i) << x[0], x[1], x[2];
  }
  vtkCellArray* cells = surface->GetPolys();
  triangles.resize(cells->GetNumberOfCells(), 3);
  vtkIdType row = 0;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
  {
    cells->GetCellAtId(c, ids);
    if (ids->GetNumberOfIds() != 3)
    {
      continue;
    }
    triangles.row(row++) << ids->GetId(0), ids->GetId(1), ids->GetId(2);
  }
  triangles.conservativeResize(row, 3);
  if (row == 0)
  {
    error = "has no triangles";
    return false;
  }
  return true;
}

std::vector<std::string> Fields(const std::string& line)
{
  std::vector<std::string> fields;
  std::string field;
  for (char c : line + ",")
  {
    if (c == ',' || c == ' ' || c == '\t' || c == '\r')
    {
      if (!field.empty())
      {
        fields.push_back(field);
      }
      field.clear();
    }
    else
    {
      field += c;
    }
  }
  return fields;
}

bool ParseIndex(const std::string& text, mobius::Index& value)
{
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const long long parsed = std::strtoll(text.c_str(), &end, 10);
  if (errno != 0 || *end != '\0')
  {
    return false;
  }
  value = parsed;
  return true;
}

bool ParseNumber(const std::string& text, double& value)
{
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return *end == '\0' && std::isfinite(value);
}

// mobius-register's OUT.csv: source_vertex, target_triangle, target_vertex_0..2,
// barycentric_0..2, mapped_x..z.
bool ReadMap(const std::string& path, const mobius::Points& points,
  const mobius::Triangles& triangles, std::vector<mobius::SurfacePoint>& mapped,
  std::string& error)
{
  std::ifstream file(path);
  if (!file)
  {
    error = path + ": cannot open the file for reading";
    return false;
  }
  // Columns by name, so that added or reordered columns do not matter.
  const std::array<const char*, 8> names = { "source_vertex", "target_triangle", "target_vertex_0",
    "target_vertex_1", "target_vertex_2", "barycentric_0", "barycentric_1", "barycentric_2" };
  std::array<size_t, 8> column;
  std::string line;
  TextLines lines(file);
  lines.Next(line);
  const std::vector<std::string> header = Fields(line);
  for (size_t k = 0; k < names.size(); ++k)
  {
    column[k] = std::find(header.begin(), header.end(), names[k]) - header.begin();
    if (column[k] == header.size())
    {
      error = path + ": not a mobius-register CSV (no column " + names[k] + " in the first line)";
      return false;
    }
  }
  const size_t columns = header.size();
  TriangleFinder finder(triangles);
  while (lines.Next(line))
  {
    if (line.empty())
    {
      continue;
    }
    const std::string where = path + " line " + std::to_string(lines.Number()) + ": ";
    const std::vector<std::string> fields = Fields(line);
    if (fields.size() != columns)
    {
      error = where + "expected " + std::to_string(columns) + " columns, found " +
        std::to_string(fields.size());
      return false;
    }
    mobius::Index source = 0, triangle = 0;
    std::array<mobius::Index, 3> vertices;
    Eigen::Vector3d weights;
    bool ok = ParseIndex(fields[column[0]], source) && ParseIndex(fields[column[1]], triangle);
    for (int k = 0; k < 3; ++k)
    {
      ok = ok && ParseIndex(fields[column[2 + k]], vertices[k]) &&
        ParseNumber(fields[column[5 + k]], weights[k]);
    }
    if (!ok)
    {
      error = where + "not a row of numbers";
      return false;
    }
    if (source != static_cast<mobius::Index>(mapped.size()))
    {
      error = where + "source vertex " + std::to_string(source) + " where " +
        std::to_string(mapped.size()) + " was expected (rows must be in source vertex order)";
      return false;
    }
    for (mobius::Index v : vertices)
    {
      if (v < 0 || v >= points.rows())
      {
        error = where + "target vertex " + std::to_string(v) + " is out of range (TARGET has " +
          std::to_string(points.rows()) + " vertices)";
        return false;
      }
    }
    mobius::SurfacePoint point;
    point.Triangle = finder.Find(triangle, vertices, weights, point.Barycentric);
    if (point.Triangle < 0)
    {
      std::ostringstream message;
      message << where << "target triangle " << triangle << " (vertices " << vertices[0] << ", "
              << vertices[1] << ", " << vertices[2]
              << ") is not a triangle of TARGET; was the map computed to this target?";
      error = message.str();
      return false;
    }
    mapped.push_back(point);
  }
  if (mapped.empty())
  {
    error = path + ": no rows";
    return false;
  }
  return true;
}

