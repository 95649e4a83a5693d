// libFuzzer target: the path a mesh file takes through mobius-register before the
// registration proper. The bytes become a mesh file that vtkSurfaceMeshReader reads (with
// its file checks), and a tiny mesh that reads goes through vtkSphericalConformalMap (its
// topology checks, repairs and a few flow steps) and, when that gives a map, vtkMobiusCenter.
//
// Input: "<header>\n<file>". The header names the file's format by its extension (off, obj,
// ply, stl, vtk, vtp), optionally followed by repair flags: 'h' FillHoles, 'k'
// KeepLargestComponent (e.g. "off hk"). A header that names no format picks one from its
// first byte, so every input is read as something. Seeds: Testing/Fuzz/Corpus.
//
// Besides crashes, leaks and undefined behaviour (found by the sanitizers), the oracle is
// the project's rule for bad input: an error, never a result with a NaN. A filter that
// reports success with a non-finite output point aborts.
#include "vtkMobiusCenter.h"
#include "vtkSphericalConformalMap.h"
#include "vtkSurfaceMeshReader.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

namespace
{
// Meshes above these sizes are only read: the map of a larger mesh would take longer than
// the few milliseconds per input that keep the fuzzer exploring.
constexpr long long MaximumMappedPoints = 200;
constexpr long long MaximumMappedCells = 400;

struct Header
{
  std::string Extension;
  bool FillHoles = false;
  bool KeepLargestComponent = false;
};

Header ParseHeader(const std::string& line)
{
  static const char* const extensions[] = { "off", "obj", "ply", "stl", "vtk", "vtp" };
  Header header;
  const std::string name = line.substr(0, line.find(' '));
  for (const char* extension : extensions)
  {
    if (name == extension)
    {
      header.Extension = extension;
    }
  }
  if (header.Extension.empty())
  {
    const auto first = line.empty() ? 0u : static_cast<unsigned char>(line[0]);
    header.Extension = extensions[first % 6];
  }
  const std::string flags = name.size() < line.size() ? line.substr(name.size()) : "";
  header.FillHoles = flags.find('h') != std::string::npos;
  header.KeepLargestComponent = flags.find('k') != std::string::npos;
  return header;
}

// Catches a filter's error and warning messages: bad input is the normal case here, and
// printing thousands of messages a second would slow the fuzzer down. Failed tells whether
// the filter reported an error.
class FilterErrors
{
public:
  explicit FilterErrors(vtkAlgorithm* filter)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback([](vtkObject*, unsigned long event, void* self, void*) {
      if (event == vtkCommand::ErrorEvent)
      {
        static_cast<FilterErrors*>(self)->Failed = true;
      }
    });
    filter->AddObserver(vtkCommand::ErrorEvent, this->Callback);
    filter->AddObserver(vtkCommand::WarningEvent, this->Callback);
    filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->Callback);
  }

  bool Failed = false;

private:
  vtkNew<vtkCallbackCommand> Callback;
};

// Aborts (a finding for the fuzzer) if a filter that reported success gave a non-finite point.
void RequireFinitePoints(vtkPolyData* output, const char* filter)
{
  vtkPoints* points = output->GetPoints();
  for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      std::fprintf(stderr, "%s succeeded with a non-finite point %lld\n", filter,
        static_cast<long long>(i));
      std::abort();
    }
  }
}

// One file per process, reused for every input: /tmp/mobius-fuzz-<pid>.<extension>.
std::string WriteInputFile(const Header& header, const uint8_t* data, size_t size)
{
  const char* directory = std::getenv("TMPDIR");
  const std::string path = std::string(directory && *directory ? directory : "/tmp") +
    "/mobius-fuzz-" + std::to_string(::getpid()) + "." + header.Extension;
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!file)
  {
    std::fprintf(stderr, "cannot write the fuzzer's input file %s\n", path.c_str());
    std::abort();
  }
  return path;
}
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  // The filters' messages are caught by FilterErrors; anything else (the internal objects
  // of VTK's readers) would go to the output window.
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  const auto* end = data + size;
  const auto* newline = data;
  while (newline != end && *newline != '\n' && newline - data < 16)
  {
    ++newline;
  }
  const Header header = ParseHeader(std::string(data, newline));
  const auto* file = newline != end && *newline == '\n' ? newline + 1 : newline;
  const std::string path = WriteInputFile(header, file, static_cast<size_t>(end - file));

  vtkNew<vtkSurfaceMeshReader> reader;
  const FilterErrors readerErrors(reader);
  reader->SetFileName(path.c_str());
  reader->Update();
  std::remove(path.c_str());
  vtkPolyData* mesh = reader->GetOutput();
  if (readerErrors.Failed || mesh->GetNumberOfPoints() == 0 ||
    mesh->GetNumberOfPoints() > MaximumMappedPoints ||
    mesh->GetNumberOfCells() > MaximumMappedCells)
  {
    return 0;
  }

  // A few flow steps and repair passes: the checks and repairs run in full, the flow's
  // iterations do not find more bugs than its first ones.
  vtkNew<vtkSphericalConformalMap> map;
  const FilterErrors mapErrors(map);
  map->SetInputConnection(reader->GetOutputPort());
  map->SetMaximumNumberOfIterations(4);
  map->SetFlipRepairPasses(4);
  map->SetFillHoles(header.FillHoles);
  map->SetKeepLargestComponent(header.KeepLargestComponent);
  map->Update();
  if (mapErrors.Failed || map->GetOutput()->GetNumberOfPoints() == 0)
  {
    return 0;
  }
  RequireFinitePoints(map->GetOutput(), "vtkSphericalConformalMap");

  vtkNew<vtkMobiusCenter> center;
  const FilterErrors centerErrors(center);
  center->SetInputConnection(map->GetOutputPort());
  center->Update();
  if (!centerErrors.Failed && center->GetOutput()->GetNumberOfPoints() > 0)
  {
    RequireFinitePoints(center->GetOutput(), "vtkMobiusCenter");
  }
  return 0;
}
