// mobius-benchmark: runs the pipeline stages on each mesh file given and prints a Markdown
// table of per-stage wall-clock seconds (median of --repeat runs), the quality figures of
// each stage and the process's peak resident memory.
//
//   mobius-benchmark [--repeat N] MESH [MESH ...]      (OBJ, OFF, PLY, STL, VTP, VTK)
#include "vtkMobiusCenter.h"
#include "vtkSphericalConformalMap.h"
#include "vtkSurfaceMeshReader.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
double PeakMemoryMB()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0; // Linux reports kilobytes
}

double Field(vtkPolyData* data, const char* name, int component = 0)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array ? array->GetComponent(0, component) : -1.0;
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

int Usage()
{
  std::cerr << "usage: mobius-benchmark [--repeat N] MESH [MESH ...]\n"
               "Runs the conformal map and the centering on each mesh (OBJ, OFF, PLY, STL, VTP,\n"
               "VTK) and prints per-stage seconds (median of N runs, default 3), quality\n"
               "figures and peak memory as a Markdown table.\n";
  return 2;
}
}

int main(int argc, char* argv[])
{
  int repeat = 3;
  std::vector<std::string> meshes;
  for (int i = 1; i < argc; ++i)
  {
    const std::string argument = argv[i];
    if (argument == "--repeat" && i + 1 < argc)
    {
      repeat = std::max(1, std::atoi(argv[++i]));
    }
    else if (argument == "-h" || argument == "--help" || argument.rfind("--", 0) == 0)
    {
      return Usage();
    }
    else
    {
      meshes.push_back(argument);
    }
  }
  if (meshes.empty())
  {
    return Usage();
  }

  std::printf("| mesh | V | map s | map iterations | mean QC | max QC | flips | center s | "
              "center iterations | final mu | peak MB |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  int status = 0;
  for (const auto& file : meshes)
  {
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

    vtkSmartPointer<vtkPolyData> map;
    const double mapSeconds = TimeMedian(repeat, [&] {
      vtkNew<vtkSphericalConformalMap> filter;
      filter->SetInputData(mesh);
      filter->Update();
      map = filter->GetOutput();
    });
    if (map->GetNumberOfPoints() == 0)
    {
      std::fprintf(stderr, "%s: the conformal map failed\n", file.c_str());
      status = 1;
      continue;
    }
    vtkSmartPointer<vtkPolyData> centered;
    const double centerSeconds = TimeMedian(repeat, [&] {
      vtkNew<vtkMobiusCenter> filter;
      filter->SetInputData(map);
      filter->Update();
      centered = filter->GetOutput();
    });

    std::printf("| %s | %lld | %.3f | %.0f | %.4f | %.3f | %.0f | %.4f | %.0f | %.1e | %.0f |\n",
      BaseName(file).c_str(), static_cast<long long>(mesh->GetNumberOfPoints()), mapSeconds,
      Field(map, "ConformalFlowIterations"), Field(map, "MeanQuasiConformalDistortion"),
      Field(map, "MaxQuasiConformalDistortion"), Field(map, "FlippedTriangles"), centerSeconds,
      Field(centered, "CenteringIterations"), Field(centered, "CenterOfMassNorm"), PeakMemoryMB());
    std::fflush(stdout);
  }
  return status;
}
