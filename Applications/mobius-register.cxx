// mobius-register: dense correspondence between two genus-0 meshes from the command line.
// See UsageText() in CommandLine.cxx, or run mobius-register --help.
#include "CommandLine.h"
#include "DemoMeshes.h"
#include "JsonSummary.h"
#include "MobiusFilterMessages.h"
#include "MemoryReuse.h"
#include "OutputFiles.h"
#include "RegistrationPipeline.h"
#include "StackLimit.h"
#include "StandardOutput.h"
#include "VTKMessages.h"

#include "vtkNew.h"
#include "vtkSMP.h"
#include "vtkSurfaceMeshReader.h"
#include "vtkVersion.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <new>
#include <stdexcept>
#include <vector>
#include <sys/stat.h>
#include <unistd.h>

namespace
{
const char* const Program = "mobius-register";

// Messages are one line each, the promise scripts rely on; a file name may hold a line break
// or other control characters, shown escaped (\n, \t, \xHH).
std::string OneLine(const std::string& text)
{
  std::string line;
  for (const char c : text)
  {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte != 0x7f)
    {
      line += c;
    }
    else if (c == '\n' || c == '\t' || c == '\r')
    {
      line += c == '\n' ? "\\n" : c == '\t' ? "\\t" : "\\r";
    }
    else
    {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      line += escaped;
    }
  }
  return line;
}

int Fail(const std::string& message, int status = 1)
{
  std::cerr << Program << ": " << OneLine(message) << std::endl;
  return status;
}

// Reads a mesh, turning the reader's error into one line that names the file.
bool ReadMesh(const std::string& path, vtkSmartPointer<vtkPolyData>& mesh, std::string& error)
{
  vtkNew<vtkSurfaceMeshReader> reader;
  // Its warnings reach VTK's output window, which CaptureVTKMessages turns into ours.
  mobius::vtk::FilterMessages messages(reader, /*catchWarnings=*/false);
  const std::string& message = messages.Error;
  reader->SetFileName(path.c_str());
  // The reader reports its own exceptions; this is for anything thrown around it.
  try
  {
    reader->Update();
  }
  catch (const std::bad_alloc&)
  {
    error = path + ": not enough memory to read the mesh";
    return false;
  }
  if (!message.empty() || reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    // The reader's message starts with the file name already; drop VTK's class prefix.
    // A name with line breaks comes back with them joined into spaces.
    std::string joined = path;
    std::replace(joined.begin(), joined.end(), '\n', ' ');
    const auto start = message.find(path), joinedStart = message.find(joined);
    error = start != std::string::npos ? message.substr(start)
      : joinedStart != std::string::npos ? path + message.substr(joinedStart + joined.size())
                                         : path + ": cannot read the mesh";
    return false;
  }
  mesh = reader->GetOutput();
  return true;
}

// Stage name and percentage on one terminal line, redrawn in place.
StageProgress TerminalProgress(bool enabled)
{
  if (!enabled)
  {
    return {};
  }
  return [](const std::string& stage, double fraction) {
    std::fprintf(stderr, "\r  %-28s %3d%%%s", stage.c_str(), static_cast<int>(100 * fraction + 0.5),
      fraction >= 1.0 ? "\n" : "");
    std::fflush(stderr);
  };
}

double RotationAngleDegrees(vtkPolyData* aligned)
{
  const double trace = FieldValue(aligned, "Rotation", 0) + FieldValue(aligned, "Rotation", 4) +
    FieldValue(aligned, "Rotation", 8);
  const double det = FieldValue(aligned, "Determinant");
  // For a reflection T = -R: the angle of R.
  const double c = (det * trace - 1) / 2;
  return std::acos(std::max(-1.0, std::min(1.0, c))) * 180 / 3.14159265358979323846;
}

// Warnings, then the per-stage seconds and the total (the job's wall time where measured:
// some stages run side by side), on standard error.
void PrintWarningsAndTimes(const std::vector<std::string>& warnings, const PipelineResult& result)
{
  for (const auto& warning : warnings)
  {
    std::cerr << Program << ": warning: " << OneLine(warning) << "\n";
  }
  double total = 0;
  for (const auto& stage : result.Stages)
  {
    std::fprintf(stderr, "  %-28s %8.3f s\n", stage.Name.c_str(), stage.Seconds);
    total += stage.Seconds;
  }
  std::fprintf(stderr, "  %-28s %8.3f s\n", "total", result.WallSeconds > 0 ? result.WallSeconds : total);
}

// Everything VTK said since the last call, as warnings.
void CollectVTKMessages(std::vector<std::string>& warnings)
{
  for (const auto& message : TakeVTKMessages())
  {
    warnings.push_back("VTK: " + message);
  }
}

// --symmetry MESH: the mesh's symmetric map and symmetry measures.
int RunSymmetry(const CommandLine& commandLine)
{
  std::string error;
  OutputFiles outputs;
  vtkSmartPointer<vtkPolyData> mesh;
  if (!outputs.Plan(commandLine.Output, "", commandLine.Force, { commandLine.Source }, error) ||
    !ReadMesh(commandLine.Source, mesh, error))
  {
    return Fail(error);
  }
  std::vector<std::string> warnings;
  CollectVTKMessages(warnings);
  const bool verbose = !commandLine.Quiet;
  PipelineResult result;
  if (!RunSymmetryDetection(mesh, commandLine.Source, commandLine.Pipeline, result, error,
        TerminalProgress(verbose && isatty(STDERR_FILENO))))
  {
    return Fail(error);
  }
  if (!outputs.WriteCsv(result.Correspondence, error) ||
    !outputs.WriteMesh(result.Correspondence, error) || !outputs.Commit(error))
  {
    return Fail(error);
  }
  CollectVTKMessages(warnings);
  warnings.insert(warnings.end(), result.Warnings.begin(), result.Warnings.end());
  if (verbose)
  {
    PrintWarningsAndTimes(warnings, result);
  }
  if (commandLine.Json)
  {
    std::cout << SymmetryJsonSummary(commandLine.Source, result, outputs);
  }
  else if (verbose)
  {
    vtkPolyData* symmetry = result.Correspondence;
    std::cout << "Symmetry of " << commandLine.Source << ": distance "
              << FieldValue(symmetry, "SymmetryDistance") << " (0 symmetric .. 1), mirror plane normal ("
              << FieldValue(symmetry, "MirrorPlaneNormal", 0) << ", "
              << FieldValue(symmetry, "MirrorPlaneNormal", 1) << ", "
              << FieldValue(symmetry, "MirrorPlaneNormal", 2) << ") on the sphere, mean asymmetry "
              << FieldValue(symmetry, "MeanAsymmetry") << " of sqrt(area).\n"
              << "Wrote " << outputs.MeshPath << ", " << outputs.CsvPath << ".\n";
  }
  return 0;
}

// --orbifold N MESH: the n-fold spherical orbifold map of the mesh.
int RunOrbifold(const CommandLine& commandLine)
{
  std::string error;
  OutputFiles outputs;
  vtkSmartPointer<vtkPolyData> mesh;
  if (!outputs.Plan(commandLine.Output, "", commandLine.Force, { commandLine.Source }, error,
        /*writesCsv=*/false) ||
    !ReadMesh(commandLine.Source, mesh, error))
  {
    return Fail(error);
  }
  std::vector<std::string> warnings;
  CollectVTKMessages(warnings);
  const bool verbose = !commandLine.Quiet;
  PipelineResult result;
  if (!RunOrbifoldMap(mesh, commandLine.Source, commandLine.Pipeline, commandLine.OrbifoldCopies,
        commandLine.Cones, commandLine.Covering, result, error,
        TerminalProgress(verbose && isatty(STDERR_FILENO))))
  {
    return Fail(error);
  }
  if (!outputs.WriteMesh(result.Correspondence, error) || !outputs.Commit(error))
  {
    return Fail(error);
  }
  CollectVTKMessages(warnings);
  warnings.insert(warnings.end(), result.Warnings.begin(), result.Warnings.end());
  if (verbose)
  {
    PrintWarningsAndTimes(warnings, result);
  }
  vtkPolyData* map = result.Correspondence;
  if (commandLine.Json)
  {
    std::cout << OrbifoldJsonSummary(commandLine.Source, result, outputs);
  }
  else if (verbose)
  {
    std::cout << commandLine.OrbifoldCopies << "-fold orbifold map of " << commandLine.Source
              << ": cones " << FieldValue(map, "ConeIds", 0) << " and "
              << FieldValue(map, "ConeIds", 1) << ", symmetry error "
              << FieldValue(map, "SymmetryError") << ", std of log area ratio "
              << FieldValue(map, "StdLogAreaRatio") << " (plain spherical map: "
              << FieldValue(map, "PlainStdLogAreaRatio") << ").\n"
              << "Wrote " << outputs.MeshPath << ".\n";
  }
  return 0;
}

int Run(int argc, char* argv[]);
}

namespace
{
// VTK prints three lines straight to standard error (not through its output window, so
// --quiet cannot hold them) when VTK_SMP_BACKEND_IN_USE names a backend this VTK was not
// built with, and falls back on Sequential. The program does that itself, first, with one
// warning line or none under --quiet.
void CheckSMPBackend(bool quiet)
{
  const char* requested = std::getenv("VTK_SMP_BACKEND_IN_USE");
  if (!requested)
  {
    return;
  }
  const std::string name = requested;
  const bool built = name == "Sequential" || (VTK_SMP_ENABLE_STDTHREAD && name == "STDThread") ||
    (VTK_SMP_ENABLE_TBB && name == "TBB") || (VTK_SMP_ENABLE_OPENMP && name == "OpenMP");
  if (built)
  {
    return;
  }
  if (!quiet)
  {
    std::cerr << Program << ": warning: VTK_SMP_BACKEND_IN_USE='" << name
              << "' is not a threading backend of this VTK; using Sequential\n";
  }
  setenv("VTK_SMP_BACKEND_IN_USE", "Sequential", 1);
}
}

int main(int argc, char* argv[])
{
  // VTK's messages become ours: warnings (unless --quiet), or nothing when the program fails
  // with its own one-line reason.
  CaptureVTKMessages();
  KeepFreedMemoryForReuse();
  const std::string stack = CheckStackLimit(Program);
  if (!stack.empty())
  {
    return Fail(stack);
  }
  try
  {
    const int status = Run(argc, argv);
    std::string error;
    return status == 0 && !FlushStandardOutput(error) ? Fail(error) : status;
  }
  catch (const std::bad_alloc&)
  {
    return Fail("out of memory");
  }
  catch (const std::exception& exception)
  {
    return Fail(std::string("unexpected error: ") + exception.what());
  }
}

namespace
{
int Run(int argc, char* argv[])
{
  CommandLine commandLine;
  std::string error;
  if (!ParseCommandLine(argc, argv, commandLine, error))
  {
    return Fail(error, 2);
  }
  if (commandLine.Help)
  {
    std::cout << UsageText();
    return 0;
  }
  if (commandLine.Version)
  {
    std::cout << Program << " " << MOBIUS_VERSION << " (VTK " << vtkVersion::GetVTKVersion()
              << ")\n";
    return 0;
  }
  CheckSMPBackend(commandLine.Quiet);
  if (commandLine.Symmetry)
  {
    return RunSymmetry(commandLine);
  }
  if (commandLine.OrbifoldCopies > 0)
  {
    return RunOrbifold(commandLine);
  }

  vtkSmartPointer<vtkPolyData> source, target;
  std::string sourceName = commandLine.Source, targetName = commandLine.Target;
  DemoMeshes demo;
  if (commandLine.Demo)
  {
    if (!MakeDemoMeshes(demo, error))
    {
      return Fail(error);
    }
    source = demo.Source;
    target = demo.Target;
    sourceName = demo.SourcePath;
    targetName = "deformed copy of " + demo.SourcePath;
    if (commandLine.Output.empty())
    {
      struct stat folder;
      if (mkdir("mobius-demo", 0755) != 0 &&
        (errno != EEXIST || stat("mobius-demo", &folder) != 0 || !S_ISDIR(folder.st_mode)))
      {
        return Fail(std::string("mobius-demo: cannot create the demo's output folder here (") +
          std::strerror(errno) + "); run it in a folder you can write to, or give -o OUT");
      }
      commandLine.Output = "mobius-demo/demo";
      if (commandLine.Picture.empty())
      {
        commandLine.Picture = "mobius-demo/demo.png";
      }
    }
  }
  OutputFiles outputs;
  if (!outputs.Plan(commandLine.Output, commandLine.Picture, commandLine.Force,
        { commandLine.Source, commandLine.Target }, error))
  {
    return Fail(error);
  }
  if (!commandLine.Demo &&
    (!ReadMesh(commandLine.Source, source, error) || !ReadMesh(commandLine.Target, target, error)))
  {
    return Fail(error);
  }
  std::vector<std::string> warnings;
  CollectVTKMessages(warnings);

  const bool verbose = !commandLine.Quiet;
  PipelineResult result;
  if (!RunRegistration(source, target, sourceName, targetName, commandLine.Pipeline, result,
        error, TerminalProgress(verbose && isatty(STDERR_FILENO))))
  {
    return Fail(error);
  }
  // The CSV, usually the smaller file, first: under a file size limit between the two sizes
  // a complete file is then taken back too (Testing/Applications/test_output_faults.py).
  // The user's outputs on the meshes as given; the picture shows the maps of the proxies.
  if (!outputs.WriteCsv(result.InputCorrespondence, error) ||
    !outputs.WriteMesh(result.InputCorrespondence, error) ||
    !outputs.WritePicture(result.Aligned, result.TargetCentered, result.Correspondence, error) || !outputs.Commit(error))
  {
    return Fail(error);
  }

  const double demoError =
    commandLine.Demo ? DemoMeanError(result.InputCorrespondence, target) : std::nan("");
  CollectVTKMessages(warnings);
  warnings.insert(warnings.end(), result.Warnings.begin(), result.Warnings.end());
  if (verbose)
  {
    PrintWarningsAndTimes(warnings, result);
  }
  if (commandLine.Json)
  {
    std::cout << JsonSummary(sourceName, targetName, commandLine.Pipeline, result, outputs, demoError);
  }
  else if (verbose)
  {
    std::cout << "Mapped " << result.InputCorrespondence->GetNumberOfPoints() << " vertices of "
              << sourceName << " onto " << targetName << ": "
              << (FieldValue(result.Aligned, "Determinant") < 0 ? "reflection" : "rotation")
              << " by " << RotationAngleDegrees(result.Aligned) << " degrees, registration error "
              << FieldValue(result.Aligned, "RegistrationError") << ".\n";
    if (commandLine.Demo)
    {
      std::cout << "Demo ground truth (vertex i <-> vertex i): mean error " << demoError
                << " of sqrt(target area).\n";
    }
    std::cout << "Wrote " << outputs.MeshPath << ", " << outputs.CsvPath
              << (outputs.PicturePath.empty() ? "" : ", " + outputs.PicturePath) << ".\n";
  }
  return 0;
}
}
