// mobius-score: how far a dense map computed by mobius-register is from the ground truth, by the
// project's measurement protocol (Kim et al. 2011): per source vertex, the distance on the target
// between the mapped point and the true image, in units of sqrt(target area); mean, median, 90th
// percentile and the shares within 0.025, 0.05, 0.1 and 0.25, Euclidean and geodesic (edge
// paths, see Filters/Core/Correspondence/CorrespondenceScore.h). With --dataset: the
// registration on pairs of a benchmark folder, scored at its .vts samples (DatasetScore.h).
// Run mobius-score --help.
#include "CorrespondenceScore.h"
#include "DatasetScore.h"
#include "Dataset.h"
#include "ScoreInput.h"

#include "PublishOutputs.h"
#include "StackLimit.h"
#include "StandardOutput.h"
#include "TextFormats.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSurfaceMeshReader.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
const char* const Program = "mobius-score";

const char* const Usage =
  "usage: mobius-score SOURCE TARGET MAP.csv [options]\n"
  "\n"
  "Scores the dense map MAP.csv that mobius-register computed from SOURCE to TARGET against\n"
  "the ground truth: per source vertex, the distance on TARGET between its mapped point and\n"
  "its true image, divided by sqrt(area of TARGET) (Kim et al. 2011). Prints the mean, median,\n"
  "90th percentile and the shares of source vertices within 0.025, 0.05, 0.1 and 0.25, for the\n"
  "Euclidean distance and for the geodesic distance (shortest paths along TARGET's edges, which\n"
  "overestimate true geodesics by a few percent).\n"
  "\n"
  "options:\n"
  "  --truth FILE        the true image of each source vertex: one line per source vertex,\n"
  "                      either a target vertex index, or a target triangle index and three\n"
  "                      barycentric weights (separated by commas or spaces); empty lines and\n"
  "                      lines starting with # are skipped (a UTF-8 byte-order mark and\n"
  "                      CR LF or CR line ends are read too). Default: identity (source vertex i\n"
  "                      is target vertex i; the meshes must have as many vertices)\n"
  "  --json              print the figures as JSON instead of a Markdown table\n"
  "  --max-geodesic N    compute geodesic errors for at most N source vertices, an even\n"
  "                      deterministic subsample (default 0: all)\n"
  "  --errors FILE       also write per-vertex errors: source_vertex,euclidean,geodesic\n"
  "                      (never over one of the inputs)\n"
  "  --threads N         threads for the geodesic searches (default 0: one per core)\n"
  "  -h, --help          print this help\n"
  "  --                  the arguments after it are files, also one that starts with '-'\n"
  "\n"
  "Exit status: 0 on success, 1 for input that cannot be read or does not fit together (row\n"
  "count, index out of range), 2 for a usage error.\n";

int Fail(const std::string& message, int status = 1)
{
  std::cerr << Program << ": " << message << std::endl;
  return status;
}

int UsageError(const std::string& message)
{
  std::cerr << Program << ": " << message << " (see mobius-score --help)" << std::endl;
  return 2;
}

// --truth FILE: per source vertex a target vertex, or a triangle and three weights.
bool ReadTruth(const std::string& path, const mobius::Points& points,
  const mobius::Triangles& triangles, std::vector<mobius::Index>& vertices,
  std::vector<mobius::SurfacePoint>& surfacePoints, std::string& error)
{
  std::ifstream file(path);
  if (!file)
  {
    error = path + ": cannot open the file for reading";
    return false;
  }
  std::vector<mobius::SurfacePoint> entries; // Triangle < 0: a vertex, in Barycentric[0]
  std::string line;
  TextLines lines(file);
  bool anyPoint = false;
  while (lines.Next(line))
  {
    const std::vector<std::string> fields = Fields(line);
    if (fields.empty() || fields[0][0] == '#')
    {
      continue;
    }
    const std::string where = path + " line " + std::to_string(lines.Number()) + ": ";
    mobius::SurfacePoint entry;
    mobius::Index index = 0;
    if (fields.size() == 1 && ParseIndex(fields[0], index))
    {
      if (index < 0 || index >= points.rows())
      {
        error = where + "target vertex " + std::to_string(index) + " is out of range (TARGET has " +
          std::to_string(points.rows()) + " vertices)";
        return false;
      }
      entry.Triangle = -1 - index;
    }
    else if (fields.size() == 4 && ParseIndex(fields[0], index) &&
      ParseNumber(fields[1], entry.Barycentric[0]) &&
      ParseNumber(fields[2], entry.Barycentric[1]) && ParseNumber(fields[3], entry.Barycentric[2]))
    {
      if (index < 0 || index >= triangles.rows())
      {
        error = where + "target triangle " + std::to_string(index) +
          " is out of range (TARGET has " + std::to_string(triangles.rows()) + " triangles)";
        return false;
      }
      entry.Triangle = index;
      anyPoint = true;
    }
    else
    {
      error = where + "expected a target vertex index, or a target triangle index and three "
                      "barycentric weights";
      return false;
    }
    entries.push_back(entry);
  }
  vertices.clear();
  surfacePoints.clear();
  if (!anyPoint)
  {
    for (const auto& entry : entries)
    {
      vertices.push_back(-1 - entry.Triangle);
    }
    return true;
  }
  // Mixed: a vertex becomes a point of one of its triangles, with weight 1 there.
  std::vector<mobius::SurfacePoint> star(points.rows());
  for (mobius::Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      star[triangles(t, k)].Triangle = t;
      star[triangles(t, k)].Barycentric = Eigen::Vector3d::Unit(k);
    }
  }
  for (const auto& entry : entries)
  {
    surfacePoints.push_back(entry.Triangle >= 0 ? entry : star[-1 - entry.Triangle]);
  }
  return true;
}

std::string Number(double value, bool json)
{
  if (std::isinf(value))
  {
    return json ? "null" : "inf";
  }
  char text[32];
  std::snprintf(text, sizeof text, json ? "%.17g" : "%.4g", value);
  return text;
}

std::string Percent(double share)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.1f%%", 100 * share);
  return text;
}

void PrintJsonSummary(const char* name, const mobius::CorrespondenceErrorSummary& summary,
  bool last)
{
  std::cout << "  \"" << name << "\": {\"count\": " << summary.Count
            << ", \"unreachable\": " << summary.Unreachable
            << ", \"mean\": " << Number(summary.Mean, true)
            << ", \"median\": " << Number(summary.Median, true)
            << ", \"p90\": " << Number(summary.Percentile90, true) << ", \"within\": {";
  for (size_t k = 0; k < summary.Within.size(); ++k)
  {
    std::cout << (k ? ", " : "") << "\"" << mobius::CorrespondenceErrorThresholds[k]
              << "\": " << Number(summary.Within[k], true);
  }
  std::cout << "}}" << (last ? "\n" : ",\n");
}

void PrintRow(const char* name, const mobius::CorrespondenceErrorSummary& summary)
{
  std::cout << "| " << name << " | " << Number(summary.Mean, false) << " | "
            << Number(summary.Median, false) << " | " << Number(summary.Percentile90, false);
  for (double share : summary.Within)
  {
    std::cout << " | " << Percent(share);
  }
  std::cout << " |\n";
}
}

// One map scored against its truth.
int ScoreMap(int argc, char* argv[])
{
  std::vector<std::string> positional;
  std::string truthPath, errorsPath;
  bool json = false;
  mobius::CorrespondenceScoreOptions options;
  bool optionsEnded = false; // after "--" every argument is a file, "-name" included
  for (int i = 1; i < argc; ++i)
  {
    const std::string argument = argv[i];
    if (optionsEnded || argument == "--")
    {
      if (optionsEnded)
      {
        positional.push_back(argument);
      }
      optionsEnded = true;
      continue;
    }
    auto value = [&](std::string& out) {
      if (i + 1 >= argc)
      {
        return false;
      }
      out = argv[++i];
      return true;
    };
    auto count = [&](long long& out) {
      std::string text;
      mobius::Index parsed = 0;
      if (!value(text) || !ParseIndex(text, parsed) || parsed < 0)
      {
        return false;
      }
      out = parsed;
      return true;
    };
    long long number = 0;
    if (argument == "-h" || argument == "--help")
    {
      std::cout << Usage << "\n" << DatasetUsage;
      return 0;
    }
    else if (argument == "--json")
    {
      json = true;
    }
    else if (argument == "--truth")
    {
      if (!value(truthPath))
      {
        return UsageError("--truth needs a file");
      }
    }
    else if (argument == "--errors")
    {
      if (!value(errorsPath))
      {
        return UsageError("--errors needs a file");
      }
    }
    else if (argument == "--max-geodesic")
    {
      if (!count(number))
      {
        return UsageError("--max-geodesic needs a count (0 for all)");
      }
      options.MaximumGeodesicQueries = number;
    }
    else if (argument == "--threads")
    {
      if (!count(number) || number > 1024)
      {
        return UsageError("--threads needs a count (0 for one per core)");
      }
      options.NumberOfThreads = static_cast<int>(number);
    }
    else if (argument.size() > 1 && argument[0] == '-')
    {
      return UsageError("unknown option " + argument);
    }
    else
    {
      positional.push_back(argument);
    }
  }
  if (positional.size() != 3)
  {
    return UsageError("expected SOURCE TARGET MAP.csv, got " + std::to_string(positional.size()) +
      " file" + (positional.size() == 1 ? "" : "s"));
  }
  const std::string& sourcePath = positional[0];
  const std::string& targetPath = positional[1];
  const std::string& mapPath = positional[2];

  std::string error;
  vtkSmartPointer<vtkPolyData> source, target;
  if (!ReadMesh(sourcePath, source, error) || !ReadMesh(targetPath, target, error))
  {
    return Fail(error);
  }
  mobius::Points points;
  mobius::Triangles triangles;
  if (!ExtractTriangleMesh(target, points, triangles, error))
  {
    return Fail(targetPath + ": " + error);
  }
  std::vector<mobius::SurfacePoint> mapped;
  if (!ReadMap(mapPath, points, triangles, mapped, error))
  {
    return Fail(error);
  }
  const mobius::Index sourceVertices = source->GetNumberOfPoints();
  if (static_cast<mobius::Index>(mapped.size()) != sourceVertices)
  {
    return Fail(mapPath + ": " + std::to_string(mapped.size()) + " rows, but SOURCE (" +
      sourcePath + ") has " + std::to_string(sourceVertices) + " vertices");
  }

  std::vector<mobius::Index> truthVertices;
  std::vector<mobius::SurfacePoint> truthPoints;
  if (truthPath.empty())
  {
    if (sourceVertices != points.rows())
    {
      return Fail("the identity ground truth needs as many vertices in SOURCE (" +
        std::to_string(sourceVertices) + ") as in TARGET (" + std::to_string(points.rows()) +
        "); give --truth FILE");
    }
    for (mobius::Index i = 0; i < sourceVertices; ++i)
    {
      truthVertices.push_back(i);
    }
  }
  else
  {
    if (!ReadTruth(truthPath, points, triangles, truthVertices, truthPoints, error))
    {
      return Fail(error);
    }
    const size_t entries = truthPoints.empty() ? truthVertices.size() : truthPoints.size();
    if (static_cast<mobius::Index>(entries) != sourceVertices)
    {
      return Fail(truthPath + ": " + std::to_string(entries) + " entries, but SOURCE (" +
        sourcePath + ") has " + std::to_string(sourceVertices) + " vertices");
    }
  }

  const auto start = std::chrono::steady_clock::now();
  mobius::CorrespondenceScore score;
  const bool scored = truthPoints.empty()
    ? mobius::ScoreCorrespondence(points, triangles, mapped, truthVertices, options, score, error)
    : mobius::ScoreCorrespondence(points, triangles, mapped, truthPoints, options, score, error);
  if (!scored)
  {
    return Fail(targetPath + ": " + error);
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if (!errorsPath.empty())
  {
    for (const std::string& input : { sourcePath, targetPath, mapPath, truthPath })
    {
      if (!input.empty() && SameFile(errorsPath, input))
      {
        return Fail("--errors " + errorsPath + " is the input " + input +
          ": it would be overwritten; choose another file");
      }
    }
    std::ostringstream out;
    out << "source_vertex,euclidean,geodesic\n";
    out.precision(10);
    for (mobius::Index i = 0; i < sourceVertices; ++i)
    {
      out << i << ',' << score.Euclidean[i] << ',';
      if (!std::isnan(score.Geodesic[i]))
      {
        out << score.Geodesic[i];
      }
      out << '\n';
    }
    if (!ReplaceFile(errorsPath, out.str(), error))
    {
      return Fail(error);
    }
  }

  if (json)
  {
    std::cout << "{\n  \"source_vertices\": " << sourceVertices
              << ",\n  \"target_vertices\": " << points.rows()
              << ",\n  \"target_triangles\": " << triangles.rows()
              << ",\n  \"target_area\": " << Number(score.TargetArea, true)
              << ",\n  \"truth\": " << JsonString(truthPath.empty() ? "identity" : truthPath)
              << ",\n  \"geodesic_method\": \"edge paths\""
              << ",\n  \"seconds\": " << Number(seconds, true) << ",\n";
    PrintJsonSummary("euclidean", score.EuclideanSummary, false);
    PrintJsonSummary("geodesic", score.GeodesicSummary, true);
    std::cout << "}\n";
    return 0;
  }
  std::cout << "| error / √area | mean | median | p90 | ≤ 0.025 | ≤ 0.05 | ≤ 0.1 | ≤ 0.25 |\n"
            << "|---|---:|---:|---:|---:|---:|---:|---:|\n";
  PrintRow("Euclidean", score.EuclideanSummary);
  PrintRow("geodesic", score.GeodesicSummary);
  std::cout << "\n"
            << sourceVertices << " source vertices (" << score.GeodesicSummary.Count
            << " with geodesic errors, edge paths on the target's edges"
            << (score.GeodesicSummary.Unreachable
                   ? ", " + std::to_string(score.GeodesicSummary.Unreachable) + " unreachable"
                   : std::string())
            << "); target area " << Number(score.TargetArea, false) << ", truth "
            << (truthPath.empty() ? "identity" : truthPath) << "; " << Number(seconds, false)
            << " s\n";
  return 0;
}

int main(int argc, char* argv[])
{
  const std::string stack = CheckStackLimit(Program);
  if (!stack.empty())
  {
    return Fail(stack);
  }
  const int status = IsDatasetScore(argc, argv) ? RunDatasetScore(argc, argv) : ScoreMap(argc, argv);
  std::string error;
  return status == 0 && !FlushStandardOutput(error) ? Fail(error) : status;
}
