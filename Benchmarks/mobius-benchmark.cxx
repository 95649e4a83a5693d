// mobius-benchmark: runs the pipeline stages on each mesh file given and prints Markdown
// tables of wall-clock seconds (median of --repeat runs), the quality figures of each
// stage and the process's peak resident memory.
//
//   mobius-benchmark [--repeat N] [--resolutions 128,256,512] [--stages map,grid,register,correspond] MESH...
//   mobius-benchmark --ladder MAX_VERTICES [--ladder-csv FILE] MESH...
//   (--surface-start with either: the conformal flow starts from the surface, as before the
//   linear start; --factorize-each-step: every flow step factorizes its matrix, as before
//   the reuse of the first step's factorization; for before/after comparisons in one run)
//
// map: vtkSphericalConformalMap + vtkMobiusCenter. grid: vtkSphericalScaleGrid at each
// resolution (exact rasterization, forward and inverse transform). register: vtkSO3Register
// of the centered map, rotated by a fixed rotation, back onto itself at each resolution
// (both signals, both transforms, correlation and refinement), with the angle error of the
// rotation found. correspond: vtkDenseCorrespondence of that pair. refine: the mesh against
// a bent, rotated copy of itself (near-isometric, vertex i <-> vertex i): the Möbius map
// (vtkDenseCorrespondence) and the refined one (vtkCorrespondenceRefinement), their
// geodesic errors (edge paths, over sqrt(area)) and the refinement's seconds per stage.
// --ladder: the conformal map's scaling instead: each mesh and its Loop subdivisions (x4
// vertices per level) up to MAX_VERTICES, each mapped once in a child process so that its
// peak memory is its own (Benchmarks/plot_ladder.py draws the CSV).
#include "MemoryReuse.h"
#include "StackLimit.h"
#include "CorrespondenceScore.h"
#include "vtkCorrespondenceRefinement.h"
#include "vtkDenseCorrespondence.h"
#include "vtkMobiusCenter.h"
#include "vtkSO3Register.h"
#include "vtkSphericalConformalMap.h"
#include "vtkSphericalScaleGrid.h"
#include "vtkSurfaceMeshReader.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkLoopSubdivisionFilter.h"
#include "vtkPointData.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <Eigen/Eigenvalues>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
// Start the conformal flow from the linear conformal map and reuse the first step's
// factorization (vtkSphericalConformalMap's defaults); --surface-start and
// --factorize-each-step turn them off.
bool LinearStart = true;
bool ReuseFactorization = true;

void ConfigureFlow(vtkSphericalConformalMap* filter)
{
  filter->SetLinearStart(LinearStart);
  filter->SetReuseFactorization(ReuseFactorization);
}

double PeakMemoryMB()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0; // Linux reports kilobytes
}

double Field(vtkPolyData* data, const char* name, int component = 0)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array ? array->GetComponent(0, component) : std::nan("");
}

// Median wall-clock seconds of `repeat` runs of `stage`.
double TimeMedian(int repeat, const std::function<void()>& stage)
{
  std::vector<double> seconds;
  for (int r = 0; r < repeat; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    stage();
    seconds.push_back(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  return seconds[seconds.size() / 2];
}

std::string BaseName(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// A fixed, generic rotation (about (1, 2, 3) by 50 degrees), row-major.
void TestRotation(double r[9])
{
  const double axis[3] = { 1 / std::sqrt(14.0), 2 / std::sqrt(14.0), 3 / std::sqrt(14.0) };
  const double angle = 50 * 3.14159265358979323846 / 180, c = std::cos(angle), s = std::sin(angle);
  const double k[9] = { 0, -axis[2], axis[1], axis[2], 0, -axis[0], -axis[1], axis[0], 0 };
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      double kk = 0;
      for (int m = 0; m < 3; ++m)
      {
        kk += k[3 * i + m] * k[3 * m + j];
      }
      r[3 * i + j] = (i == j) + s * k[3 * i + j] + (1 - c) * kk;
    }
  }
}

// Angle in degrees between the found transform (row-major) and the inverse of `applied`.
double AngleErrorDegrees(const double found[9], const double applied[9])
{
  // trace(found * applied) = trace(found * inverse(applied)^T ...): for the exact answer
  // found = applied^T, so found * applied = I.
  double trace = 0;
  for (int i = 0; i < 3; ++i)
  {
    for (int m = 0; m < 3; ++m)
    {
      trace += found[3 * i + m] * applied[3 * m + i];
    }
  }
  return std::acos(std::max(-1.0, std::min(1.0, (trace - 1) / 2))) * 180 / 3.14159265358979323846;
}

// The mesh bent into an arc along its longest principal axis (radius 2.5 times the axis's
// spread, little stretching: near-isometric), then turned by TestRotation.
vtkSmartPointer<vtkPolyData> BentCopy(vtkPolyData* mesh)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (vtkIdType i = 0; i < n; ++i)
  {
    mean += Eigen::Map<const Eigen::Vector3d>(mesh->GetPoint(i)) / n;
  }
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (vtkIdType i = 0; i < n; ++i)
  {
    const Eigen::Vector3d d = Eigen::Map<const Eigen::Vector3d>(mesh->GetPoint(i)) - mean;
    covariance += d * d.transpose() / n;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(covariance); // ascending
  const Eigen::Matrix3d frame = axes.eigenvectors();
  const double radius = 5 * std::sqrt(axes.eigenvalues()[2]);
  double r[9];
  TestRotation(r);
  const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> rotation(r);
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(mesh);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const Eigen::Vector3d y = frame.transpose() * (Eigen::Map<const Eigen::Vector3d>(mesh->GetPoint(i)) - mean);
    const double angle = y[2] / radius;
    const Eigen::Vector3d bent(y[0], (radius + y[1]) * std::cos(angle) - radius, (radius + y[1]) * std::sin(angle));
    const Eigen::Vector3d moved = rotation * (frame * bent);
    copy->GetPoints()->SetPoint(i, moved.data());
  }
  return copy;
}

// Geodesic error summary of a correspondence onto `targetMap` whose truth is "same input
// vertex" (InputPointId).
mobius::CorrespondenceErrorSummary GeodesicErrors(vtkPolyData* correspondence, vtkPolyData* targetMap)
{
  mobius::Points points(targetMap->GetNumberOfPoints(), 3);
  vtkDataArray* surface = targetMap->GetPointData()->GetArray("SurfacePoints");
  for (vtkIdType i = 0; i < targetMap->GetNumberOfPoints(); ++i)
  {
    surface->GetTuple(i, points.row(i).data());
  }
  mobius::Triangles triangles(targetMap->GetNumberOfCells(), 3);
  for (vtkIdType t = 0; t < targetMap->GetNumberOfCells(); ++t)
  {
    vtkIdType npts;
    const vtkIdType* ids;
    targetMap->GetCellPoints(t, npts, ids);
    triangles.row(t) << ids[0], ids[1], ids[2];
  }
  vtkDataArray* targetIds = targetMap->GetPointData()->GetArray("InputPointId");
  std::vector<mobius::Index> byInputId(targetMap->GetNumberOfPoints(), -1);
  for (vtkIdType i = 0; i < targetMap->GetNumberOfPoints(); ++i)
  {
    const auto id = static_cast<vtkIdType>(targetIds->GetTuple1(i));
    if (id >= 0 && id < static_cast<vtkIdType>(byInputId.size()))
    {
      byInputId[id] = i;
    }
  }
  vtkDataArray* cells = correspondence->GetPointData()->GetArray("TargetCellId");
  vtkDataArray* weights = correspondence->GetPointData()->GetArray("TargetBarycentric");
  vtkDataArray* sourceIds = correspondence->GetPointData()->GetArray("InputPointId");
  std::vector<mobius::SurfacePoint> mapped;
  std::vector<mobius::Index> truth;
  for (vtkIdType i = 0; i < correspondence->GetNumberOfPoints(); ++i)
  {
    const auto id = static_cast<vtkIdType>(sourceIds->GetTuple1(i));
    if (id < 0 || id >= static_cast<vtkIdType>(byInputId.size()) || byInputId[id] < 0)
    {
      continue;
    }
    mobius::SurfacePoint point;
    point.Triangle = static_cast<mobius::Index>(cells->GetTuple1(i));
    weights->GetTuple(i, point.Barycentric.data());
    mapped.push_back(point);
    truth.push_back(byInputId[id]);
  }
  mobius::CorrespondenceScore score;
  std::string error;
  if (!mobius::ScoreCorrespondence(points, triangles, mapped, truth, {}, score, error))
  {
    std::fprintf(stderr, "scoring failed: %s\n", error.c_str());
  }
  return score.GeodesicSummary;
}

std::vector<int> ParseList(const std::string& text)
{
  std::vector<int> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ','))
  {
    values.push_back(std::atoi(item.c_str()));
  }
  return values;
}

// One rung of the size ladder: what the child process that mapped it reports.
struct LadderRung
{
  std::string Mesh;
  int Level = 0;
  long long Vertices = 0;
  double MapSeconds = 0;
  double FlowSteps = 0;
  double MeanQuasiConformal = 0;
  double Flips = 0;
  double PeakMB = 0;
  bool Ok = false;
};

// Maps `mesh` once in a forked child (so that the peak resident memory, read from the
// child's rusage, is that of this one map: mesh, map and solver) and returns its figures.
LadderRung MapInChild(vtkPolyData* mesh)
{
  LadderRung rung;
  rung.Vertices = mesh->GetNumberOfPoints();
  int channel[2];
  if (pipe(channel) != 0)
  {
    return rung;
  }
  std::fflush(nullptr);
  const pid_t child = fork();
  if (child == 0)
  {
    close(channel[0]);
    vtkSmartPointer<vtkPolyData> map;
    const auto start = std::chrono::steady_clock::now();
    vtkNew<vtkSphericalConformalMap> filter;
    filter->SetInputData(mesh);
    ConfigureFlow(filter);
    filter->Update();
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    map = filter->GetOutput();
    double figures[5] = { map->GetNumberOfPoints() > 0 ? 1.0 : 0.0, seconds,
      Field(map, "ConformalFlowIterations"), Field(map, "MeanQuasiConformalDistortion"),
      Field(map, "FlippedTriangles") };
    const ssize_t written = write(channel[1], figures, sizeof(figures));
    _exit(written == static_cast<ssize_t>(sizeof(figures)) ? 0 : 1);
  }
  close(channel[1]);
  if (child < 0)
  {
    close(channel[0]);
    return rung;
  }
  double figures[5] = { 0, 0, 0, 0, 0 };
  const ssize_t got = read(channel[0], figures, sizeof(figures));
  close(channel[0]);
  int status = 0;
  rusage usage{};
  wait4(child, &status, 0, &usage);
  rung.Ok = got == static_cast<ssize_t>(sizeof(figures)) && WIFEXITED(status) &&
    WEXITSTATUS(status) == 0 && figures[0] == 1.0;
  rung.MapSeconds = figures[1];
  rung.FlowSteps = figures[2];
  rung.MeanQuasiConformal = figures[3];
  rung.Flips = figures[4];
  rung.PeakMB = usage.ru_maxrss / 1024.0;
  return rung;
}

// The size ladder: every mesh and its Loop subdivisions up to maxVertices.
int RunLadder(const std::vector<std::string>& meshes, long long maxVertices, const std::string& csv)
{
  std::vector<LadderRung> rungs;
  int status = 0;
  for (const auto& file : meshes)
  {
    vtkNew<vtkSurfaceMeshReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkSmartPointer<vtkPolyData> mesh = reader->GetOutput();
    if (mesh->GetNumberOfPoints() == 0)
    {
      std::fprintf(stderr, "%s: cannot read the mesh\n", file.c_str());
      status = 1;
      continue;
    }
    for (int level = 0; mesh->GetNumberOfPoints() <= maxVertices; ++level)
    {
      LadderRung rung = MapInChild(mesh);
      rung.Mesh = BaseName(file);
      rung.Level = level;
      std::fprintf(stderr, "%s level %d: %lld vertices, %.2f s, %.0f MB%s\n", rung.Mesh.c_str(),
        level, rung.Vertices, rung.MapSeconds, rung.PeakMB, rung.Ok ? "" : " (FAILED)");
      status = rung.Ok ? status : 1;
      rungs.push_back(rung);
      // Loop subdivision: each triangle into four, smoothing the positions (a closed genus-0
      // mesh stays one; vertices go from V to about 4V).
      vtkNew<vtkLoopSubdivisionFilter> subdivide;
      subdivide->SetInputData(mesh);
      subdivide->SetNumberOfSubdivisions(1);
      subdivide->Update();
      mesh = subdivide->GetOutput();
      if (mesh->GetNumberOfPoints() == 0)
      {
        break;
      }
    }
  }
  std::sort(rungs.begin(), rungs.end(),
    [](const LadderRung& a, const LadderRung& b) { return a.Vertices < b.Vertices; });
  std::cout << "Conformal map over a size ladder (Loop subdivisions; one run each, own process)\n\n"
            << "| mesh | Loop level | V | map s | flow steps | mean QC | flips | peak MB |\n"
            << "|---|---:|---:|---:|---:|---:|---:|---:|\n";
  std::ofstream table;
  if (!csv.empty())
  {
    table.open(csv);
    table << "mesh,level,vertices,map_seconds,flow_steps,mean_qc,flips,peak_mb\n";
  }
  for (const auto& r : rungs)
  {
    char row[512];
    std::snprintf(row, sizeof(row), "| %s | %d | %lld | %.3f | %.0f | %.4f | %.0f | %.0f |\n",
      r.Mesh.c_str(), r.Level, r.Vertices, r.MapSeconds, r.FlowSteps, r.MeanQuasiConformal,
      r.Flips, r.PeakMB);
    std::cout << row;
    if (table.is_open() && r.Ok)
    {
      table << r.Mesh << "," << r.Level << "," << r.Vertices << "," << r.MapSeconds << ","
            << r.FlowSteps << "," << r.MeanQuasiConformal << "," << r.Flips << "," << r.PeakMB
            << "\n";
    }
  }
  if (!csv.empty() && !table)
  {
    std::fprintf(stderr, "cannot write %s\n", csv.c_str());
    status = 1;
  }
  return status;
}

// --help prints to standard output and succeeds (the man page is made from it); a usage
// error prints the same text to standard error and exits 2.
int Usage(std::ostream& out, int status)
{
  out << "usage: mobius-benchmark [--repeat N] [--resolutions 128,256,512]\n"
         "                        [--stages map,grid,register,correspond,refine] MESH [MESH ...]\n"
         "       mobius-benchmark --ladder MAX_VERTICES [--ladder-csv FILE] MESH [MESH ...]\n"
         "       mobius-benchmark --version | -h/--help\n"
         "--surface-start, --factorize-each-step (with either form): start the conformal\n"
         "flow from the surface instead of the linear conformal map; factorize every flow\n"
         "step's matrix instead of reusing the first one's (before/after comparisons).\n"
         "\n"
         "Per stage: seconds (median of N runs, default 3), quality figures and peak memory,\n"
         "as Markdown tables. Meshes: .obj .off .ply .stl .vtp .vtk. Build Release to measure.\n"
         "--ladder: the conformal map alone on each mesh and its Loop subdivisions up to\n"
         "MAX_VERTICES vertices, one run each in its own process: seconds, flow steps, quality\n"
         "and peak memory (--ladder-csv also writes them as CSV for plot_ladder.py).\n";
  return status;
}
}

int main(int argc, char* argv[])
{
  KeepFreedMemoryForReuse();
  const std::string stack = CheckStackLimit("mobius-benchmark");
  if (!stack.empty())
  {
    std::cerr << "mobius-benchmark: " << stack << std::endl;
    return 1;
  }
  int repeat = 3;
  std::vector<int> resolutions = { 128, 256, 512 };
  std::string stages = "map,grid,register,correspond,refine";
  std::vector<std::string> meshes;
  long long ladder = 0;
  std::string ladderCsv;
  for (int i = 1; i < argc; ++i)
  {
    const std::string argument = argv[i];
    if (argument == "--repeat" && i + 1 < argc)
    {
      repeat = std::max(1, std::atoi(argv[++i]));
    }
    else if (argument == "--resolutions" && i + 1 < argc)
    {
      resolutions = ParseList(argv[++i]);
    }
    else if (argument == "--stages" && i + 1 < argc)
    {
      stages = argv[++i];
    }
    else if (argument == "--ladder" && i + 1 < argc)
    {
      ladder = std::atoll(argv[++i]);
      if (ladder <= 0)
      {
        return Usage(std::cerr, 2);
      }
    }
    else if (argument == "--ladder-csv" && i + 1 < argc)
    {
      ladderCsv = argv[++i];
    }
    else if (argument == "--surface-start")
    {
      LinearStart = false;
    }
    else if (argument == "--factorize-each-step")
    {
      ReuseFactorization = false;
    }
    else if (argument == "--help" || argument == "-h")
    {
      return Usage(std::cout, 0);
    }
    else if (argument == "--version")
    {
      std::cout << "mobius-benchmark " << MOBIUS_VERSION << "\n";
      return 0;
    }
    else if (argument.rfind("-", 0) == 0)
    {
      return Usage(std::cerr, 2);
    }
    else
    {
      meshes.push_back(argument);
    }
  }
  if (meshes.empty())
  {
    return Usage(std::cerr, 2);
  }
  if (ladder > 0)
  {
    return RunLadder(meshes, ladder, ladderCsv);
  }
  auto wants = [&stages](const char* stage) { return stages.find(stage) != std::string::npos; };

  int status = 0;
  std::ostringstream mapTable, gridTable, registerTable, correspondTable, refineTable;
  refineTable << "| mesh | V | Möbius mean | Möbius <= 0.1 | refined mean | refined <= 0.1 | "
                 "refinement s | bases s | candidates s | extension s | polish s | candidate kept |\n"
                 "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  mapTable << "| mesh | V | map s | flow steps | factorizations | mean QC | max QC | median QC | p95 QC | "
              "squashed % | flips | degenerate | center s | center steps | final mu |\n"
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  gridTable << "| mesh | N | scale grid s |\n|---|---:|---:|\n";
  registerTable << "| mesh | N | register s | B' | rotation error (deg) | registration error |\n"
                   "|---|---:|---:|---:|---:|---:|\n";
  correspondTable << "| mesh | V | correspondence s | clamped points |\n|---|---:|---:|---:|\n";
  for (const auto& file : meshes)
  {
    const std::string name = BaseName(file);
    vtkNew<vtkSurfaceMeshReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkPolyData* mesh = reader->GetOutput();
    if (mesh->GetNumberOfPoints() == 0)
    {
      std::fprintf(stderr, "%s: cannot read the mesh\n", file.c_str());
      status = 1;
      continue;
    }
    vtkSmartPointer<vtkPolyData> map, centered;
    const double mapSeconds = TimeMedian(repeat, [&] {
      vtkNew<vtkSphericalConformalMap> filter;
      filter->SetInputData(mesh);
      ConfigureFlow(filter);
      filter->Update();
      map = filter->GetOutput();
    });
    if (map->GetNumberOfPoints() == 0)
    {
      std::fprintf(stderr, "%s: the conformal map failed\n", file.c_str());
      status = 1;
      continue;
    }
    const double centerSeconds = TimeMedian(repeat, [&] {
      vtkNew<vtkMobiusCenter> filter;
      filter->SetInputData(map);
      filter->Update();
      centered = filter->GetOutput();
    });
    char row[512];
    std::snprintf(row, sizeof(row),
      "| %s | %lld | %.3f | %.0f | %.0f | %.4f | %.1f | %.3f | %.3f | %.3f | %.0f | %.0f | %.4f | %.0f | %.1e |\n",
      name.c_str(), static_cast<long long>(mesh->GetNumberOfPoints()), mapSeconds,
      Field(map, "ConformalFlowIterations"), Field(map, "ConformalFlowFactorizations"),
      Field(map, "MeanQuasiConformalDistortion"), Field(map, "MaxQuasiConformalDistortion"),
      Field(map, "MedianQuasiConformalDistortion"), Field(map, "P95QuasiConformalDistortion"),
      100 * Field(map, "SquashedAreaShare"), Field(map, "FlippedTriangles"),
      Field(map, "DegenerateMap"), centerSeconds, Field(centered, "CenteringIterations"),
      Field(centered, "CenterOfMassNorm"));
    mapTable << row;

    // The centered map rotated by a known rotation: registration must find its inverse.
    double rotation[9];
    TestRotation(rotation);
    vtkNew<vtkPolyData> rotated;
    rotated->DeepCopy(centered);
    for (vtkIdType i = 0; i < rotated->GetNumberOfPoints(); ++i)
    {
      double p[3], q[3] = { 0, 0, 0 };
      rotated->GetPoint(i, p);
      for (int r = 0; r < 3; ++r)
      {
        for (int c = 0; c < 3; ++c)
        {
          q[r] += rotation[3 * r + c] * p[c];
        }
      }
      rotated->GetPoints()->SetPoint(i, q);
    }
    vtkSmartPointer<vtkPolyData> aligned;
    for (int resolution : resolutions)
    {
      if (wants("grid"))
      {
        const double seconds = TimeMedian(repeat, [&] {
          vtkNew<vtkSphericalScaleGrid> grid;
          grid->SetInputData(centered);
          grid->SetResolution(resolution);
          grid->Update();
        });
        std::snprintf(row, sizeof(row), "| %s | %d | %.3f |\n", name.c_str(), resolution, seconds);
        gridTable << row;
      }
      if (wants("register") || wants("correspond"))
      {
        const double seconds = TimeMedian(repeat, [&] {
          vtkNew<vtkSO3Register> registration;
          registration->SetSourceData(rotated);
          registration->SetTargetData(centered);
          registration->SetResolution(resolution);
          registration->Update();
          aligned = registration->GetOutput();
        });
        double found[9];
        for (int k = 0; k < 9; ++k)
        {
          found[k] = Field(aligned, "Rotation", k);
        }
        std::snprintf(row, sizeof(row), "| %s | %d | %.3f | %.0f | %.4f | %.2e |\n", name.c_str(),
          resolution, seconds, Field(aligned, "CorrelationBandwidth"),
          AngleErrorDegrees(found, rotation), Field(aligned, "RegistrationError"));
        registerTable << row;
      }
    }
    if (wants("correspond") && aligned)
    {
      vtkSmartPointer<vtkPolyData> correspondence;
      const double seconds = TimeMedian(repeat, [&] {
        vtkNew<vtkDenseCorrespondence> filter;
        filter->SetSourceData(aligned);
        filter->SetTargetData(centered);
        filter->Update();
        correspondence = filter->GetOutput();
      });
      std::snprintf(row, sizeof(row), "| %s | %lld | %.3f | %.0f |\n", name.c_str(),
        static_cast<long long>(aligned->GetNumberOfPoints()), seconds,
        Field(correspondence, "ClampedPoints"));
      correspondTable << row;
    }
    if (wants("refine"))
    {
      auto bent = BentCopy(mesh);
      vtkNew<vtkSphericalConformalMap> targetMap;
      targetMap->SetInputData(bent);
      ConfigureFlow(targetMap);
      vtkNew<vtkMobiusCenter> targetCentered;
      targetCentered->SetInputConnection(targetMap->GetOutputPort());
      targetCentered->Update();
      vtkNew<vtkSO3Register> registration;
      registration->SetSourceData(centered);
      registration->SetTargetConnection(targetCentered->GetOutputPort());
      vtkNew<vtkDenseCorrespondence> mobiusMap;
      mobiusMap->SetSourceConnection(registration->GetOutputPort());
      mobiusMap->SetTargetConnection(targetCentered->GetOutputPort());
      mobiusMap->Update();
      vtkSmartPointer<vtkPolyData> refined;
      const double seconds = TimeMedian(repeat, [&] {
        vtkNew<vtkCorrespondenceRefinement> refinement;
        refinement->RecordTimingsOn(); // the stage columns below
        refinement->SetSourceConnection(registration->GetOutputPort());
        refinement->SetTargetConnection(targetCentered->GetOutputPort());
        refinement->Update();
        refined = refinement->GetOutput();
      });
      if (refined->GetNumberOfPoints() == 0)
      {
        std::fprintf(stderr, "%s: the refinement failed\n", file.c_str());
        status = 1;
      }
      else
      {
        const auto before = GeodesicErrors(mobiusMap->GetOutput(), targetCentered->GetOutput());
        const auto after = GeodesicErrors(refined, targetCentered->GetOutput());
        std::snprintf(row, sizeof(row),
          "| %s | %lld | %.4f | %.1f%% | %.4f | %.1f%% | %.2f | %.2f | %.2f | %.2f | %.2f | %.0f |\n",
          name.c_str(), static_cast<long long>(mesh->GetNumberOfPoints()), before.Mean,
          100 * before.Within[2], after.Mean, 100 * after.Within[2], seconds,
          Field(refined, "RefinementStageSeconds", 0), Field(refined, "RefinementStageSeconds", 1),
          Field(refined, "RefinementStageSeconds", 2), Field(refined, "RefinementStageSeconds", 3),
          Field(refined, "RefinementCandidate"));
        refineTable << row;
      }
    }
    std::fprintf(stderr, "%s done, peak memory so far %.0f MB\n", name.c_str(), PeakMemoryMB());
  }
  if (wants("map"))
  {
    std::cout << "Conformal map and centering\n\n" << mapTable.str() << "\n";
  }
  if (wants("grid"))
  {
    std::cout << "Scale-factor grid\n\n" << gridTable.str() << "\n";
  }
  if (wants("register"))
  {
    std::cout << "Rotational alignment (a rotated copy back onto the map)\n\n" << registerTable.str() << "\n";
  }
  if (wants("correspond"))
  {
    std::cout << "Dense correspondence\n\n" << correspondTable.str() << "\n";
  }
  if (wants("refine"))
  {
    std::cout << "Refinement (the mesh onto a bent, rotated copy; geodesic errors over sqrt(area); "
                 "stage seconds of the last run)\n\n"
              << refineTable.str() << "\n";
  }
  std::cout << "Peak resident memory: " << PeakMemoryMB() << " MB\n";
  return status;
}
