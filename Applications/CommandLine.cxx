#include "CommandLine.h"

#include "vtkSO3Register.h"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <vector>

namespace
{
bool ParseNumber(const std::string& text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && end && *end == '\0';
}

bool ParseInteger(const std::string& text, int& value)
{
  double number;
  // Range first: converting NaN or a value outside int's range to int is undefined.
  if (!ParseNumber(text, number) || !(number >= std::numeric_limits<int>::min() &&
        number <= std::numeric_limits<int>::max()) ||
    number != std::trunc(number))
  {
    return false;
  }
  value = static_cast<int>(number);
  return true;
}
}

std::string UsageText()
{
  const PipelineOptions defaults;
  std::ostringstream text;
  text << "usage: mobius-register [options] SOURCE TARGET -o OUT\n"
          "       mobius-register [options] --symmetry MESH -o OUT\n"
          "       mobius-register [options] --orbifold N MESH -o OUT [--cones I,J] [--covering]\n"
          "       mobius-register [options]            (demo on CGAL's cow and a deformed copy)\n"
          "\n"
          "Dense correspondence between two closed genus-0 surface meshes by Moebius\n"
          "registration (Baden, Crane & Kazhdan, SGP 2018): conformal map of each mesh onto the\n"
          "sphere, canonical centering, rotational alignment by correlation over SO(3), and a\n"
          "point-to-point map. Meshes: .obj .off .ply .stl .vtp .vtk\n"
          "\n"
          "Outputs (existing files are kept unless --force):\n"
          "  -o, --output OUT       OUT.vtp: the source mesh mapped onto the target, with point\n"
          "                         arrays TargetCellId, TargetBarycentric, MappedPoints and the\n"
          "                         target's point arrays; OUT.csv: per source vertex, the target\n"
          "                         triangle, its vertices and the barycentric coordinates.\n"
          "                         The demo writes mobius-demo/demo.{vtp,csv,png} by default.\n"
          "  --png FILE             picture: source colored by position, and the source mesh\n"
          "                         placed on the target by the map (needs X; use xvfb-run)\n"
          "\n"
          "Symmetry (paper Section 7.3):\n"
          "  --symmetry MESH        bilateral symmetry of one mesh: its best orientation-\n"
          "                         reversing self-map. OUT.vtp: the mesh with the symmetric\n"
          "                         map (TargetCellId, TargetBarycentric, MappedPoints: each\n"
          "                         vertex's mirror image), Asymmetry per vertex and field data\n"
          "                         SymmetryDistance (0 symmetric .. 1), MirrorPlaneNormal,\n"
          "                         candidates; OUT.csv as for two meshes, the mesh against\n"
          "                         itself. Uses the options below except --transform.\n"
          "  --no-centering         skip the Moebius centering (and the centering between flow\n"
          "                         steps): the paper's uncentered comparison; the flow then\n"
          "                         drifts and may need --allow-poor-maps\n"
          "\n"
          "Orbifold map (paper Section 7.2):\n"
          "  --orbifold N MESH      n-fold spherical orbifold map (N = 2..8): cut MESH between\n"
          "                         two cone vertices, glue N copies into the cyclic covering,\n"
          "                         map and center it. OUT.vtp: one copy on its 1/N of the\n"
          "                         sphere (cones on the z axis), with SurfacePoints,\n"
          "                         InputPointId, field data SymmetryError, StdLogAreaRatio\n"
          "                         and PlainStdLogAreaRatio (area distortion of this map and\n"
          "                         of the plain one). Uses the conformal map options below.\n"
          "  --cones I,J            the cone vertices (vertex numbers in MESH; default two\n"
          "                         far-apart vertices)\n"
          "  --covering             OUT.vtp holds the whole covering (all N copies)\n"
          "\n"
          "Conformal map:\n"
          "  --iterations N         maximum flow steps (default "
       << defaults.FlowIterations
       << ")\n"
          "  --tolerance T          flow convergence tolerance, 0 to 1 (default "
       << defaults.FlowTolerance
       << ")\n"
          "  --no-center-flow       plain CMCF: no Moebius centering between flow steps\n"
          "  --fill-holes           close holes instead of rejecting open meshes\n"
          "  --keep-largest-component  map only the largest connected component\n"
          "  --allow-poor-maps      write the result even when a conformal map is degenerate\n"
          "                         (triangles flipped after repair, area collapsed or\n"
          "                         squashed, flow not converged, squeezed-region\n"
          "                         refinement failed)\n"
          "Centering:\n"
          "  --degree L             centering degree for both meshes, 1 to 8 (default "
       << defaults.CenteringDegree
       << "):\n"
          "                         1 is the paper's Moebius centering (conformal); 2..8 go on\n"
          "                         to its generalized centering (Section 5, Figure 5): no\n"
          "                         area moments of spherical-harmonic degree 1..L, area spread\n"
          "                         more evenly at the cost of conformality\n"
          "Registration:\n"
          "  --resolution N         scale-factor grid size, even, as memory allows (default "
       << defaults.Resolution
       << ")\n"
          "  --smoothing T          heat-kernel smoothing time, 0 to 1 (default "
       << defaults.SmoothingTime
       << ")\n"
          "  --transform MODE       rotation | reflection | both (default rotation)\n"
          "  --candidates K         correlation peaks to report (default "
       << defaults.NumberOfCandidates
       << ")\n"
          "  --candidate K          keep the refinement's map from candidate K (0..K-1 of\n"
          "                         --candidates; 0 the best peak) instead of the one it\n"
          "                         chooses: for a map that came out turned or mirrored\n"
          "                         while a warning named a near-equal runner-up\n"
          "Correspondence:\n"
          "  --refine METHOD        spectral | none: refine the Moebius map (ZoomOut on the\n"
          "                         surfaces' Laplace-Beltrami bases, from every candidate\n"
          "                         rotation) or keep the paper's map (default spectral)\n"
          "  --basis-size K         eigenfunctions of the refinement (default "
       << defaults.BasisSize
       << ")\n"
          "  --no-polish            keep the spectral map: no geometric polish (ARAP\n"
          "                         non-rigid ICP of the source onto the target) after it\n"
          "  --output-geometry G    target | source: where OUT.vtp's points are (default target)\n"
          "Other:\n"
          "  --threads N            threads per threaded stage, 0 to 1024; 0: one per core\n"
          "                         this process may use (CPU affinity), at most\n"
          "                         VTK_SMP_MAX_THREADS if set (default 0); results are the\n"
          "                         same for any N\n"
          "  --force                overwrite existing output files\n"
          "  --quiet                no progress or warnings\n"
          "  --json                 print a machine-readable summary on standard output\n"
          "  --version, -h/--help\n"
          "\n"
          "Exit status: 0 on success; 1 if a mesh cannot be read or mapped (a degenerate map\n"
          "included, unless --allow-poor-maps), or an output cannot be written (an existing\n"
          "file without --force included); 2 for usage errors (unknown options, values out\n"
          "of range, wrong number of meshes, no -o).\n";
  return text.str();
}

bool ParsePipelineOption(
  int argc, char* argv[], int& i, PipelineOptions& pipeline, bool& recognized, std::string& error)
{
  const std::string option = argv[i];
  auto value = [&](std::string& out) {
    if (i + 1 >= argc)
    {
      error = option + " needs a value";
      return false;
    }
    out = argv[++i];
    return true;
  };
  std::string text;
  recognized = true;
  if (option == "--no-polish")
  {
    pipeline.GeometricPolish = false;
  }
  else if (option == "--no-center-flow")
  {
    pipeline.CenterBetweenSteps = false;
  }
  else if (option == "--fill-holes")
  {
    pipeline.FillHoles = true;
  }
  else if (option == "--keep-largest-component")
  {
    pipeline.KeepLargestComponent = true;
  }
  else if (option == "--allow-poor-maps")
  {
    pipeline.AllowPoorMaps = true;
  }
  else if (option == "--refine")
  {
    if (!value(text) || (text != "spectral" && text != "none"))
    {
      error = error.empty() ? "--refine must be spectral or none, not '" + text + "'" : error;
      return false;
    }
    pipeline.Refine = text == "spectral";
  }
  else if (option == "--threads")
  {
    int number = 0;
    if (!value(text) || !ParseInteger(text, number) || number < 0 || number > 1024)
    {
      error = error.empty() ? "--threads needs an integer from 0 to 1024, not '" + text + "'" : error;
      return false;
    }
    pipeline.NumberOfThreads = number;
  }
  else if (option == "--basis-size")
  {
    int number = 0;
    if (!value(text) || !ParseInteger(text, number) || number < 2 || number > 500)
    {
      error = error.empty() ? "--basis-size needs an integer from 2 to 500, not '" + text + "'" : error;
      return false;
    }
    pipeline.BasisSize = number;
  }
  else if (option == "--degree")
  {
    // vtkMobiusCenter clamps its Degree to 1..8; a value outside is refused, not clamped.
    int number = 0;
    if (!value(text) || !ParseInteger(text, number) || number < 1 || number > 8)
    {
      error = error.empty() ? "--degree needs an integer from 1 (the paper's Moebius centering) "
                              "to 8, not '" + text + "'"
                            : error;
      return false;
    }
    pipeline.CenteringDegree = number;
  }
  else if (option == "--iterations" || option == "--resolution" || option == "--candidates")
  {
    int number = 0;
    if (!value(text) || !ParseInteger(text, number) || number < 1)
    {
      error = error.empty() ? option + " needs a positive integer, not '" + text + "'" : error;
      return false;
    }
    if (option == "--resolution" && (number < 4 || number % 2 != 0))
    {
      error = "--resolution must be even and at least 4, not " + text;
      return false;
    }
    // Said now, not after minutes of conformal maps (vtkSO3Register checks it too).
    if (option == "--resolution" && number > vtkSO3Register::LargestResolution())
    {
      std::ostringstream message;
      message << "--resolution " << number << " needs about "
              << vtkSO3Register::EstimateMemory(number) / 1e9
              << " GB, more than this machine's memory; at most "
              << vtkSO3Register::LargestResolution() << " fits";
      error = message.str();
      return false;
    }
    (option == "--iterations"       ? pipeline.FlowIterations
        : option == "--resolution" ? pipeline.Resolution
                                   : pipeline.NumberOfCandidates) = number;
  }
  else if (option == "--candidate")
  {
    int number = 0;
    if (!value(text) || !ParseInteger(text, number) || number < 0 || number > 63)
    {
      error = error.empty() ? "--candidate needs an integer from 0 to 63, not '" + text + "'" : error;
      return false;
    }
    pipeline.Candidate = number;
  }
  else if (option == "--tolerance" || option == "--smoothing")
  {
    // NaN passes every comparison and an infinite or huge smoothing time wipes out the
    // signals (exp(-l(l+1) t) leaves nothing of degree 1 and up well before t = 1): the
    // run would silently return garbage. A relative change above 1 is no tolerance either.
    double number = 0;
    if (!value(text) || !ParseNumber(text, number) || !std::isfinite(number) || number < 0 ||
      number > 1)
    {
      error = error.empty() ? option + " needs a number from 0 to 1, not '" + text + "'" : error;
      return false;
    }
    (option == "--tolerance" ? pipeline.FlowTolerance
                             : pipeline.SmoothingTime) = number;
  }
  else if (option == "--transform")
  {
    if (!value(text))
    {
      return false;
    }
    const std::vector<std::string> modes = { "rotation", "reflection", "both" };
    int mode = -1;
    for (size_t m = 0; m < modes.size(); ++m)
    {
      mode = text == modes[m] ? static_cast<int>(m) : mode;
    }
    if (mode < 0)
    {
      error = "--transform must be rotation, reflection or both, not '" + text + "'";
      return false;
    }
    pipeline.TransformMode = mode;
  }
  else if (option == "--output-geometry")
  {
    if (!value(text) || (text != "target" && text != "source"))
    {
      error = error.empty() ? "--output-geometry must be target or source, not '" + text + "'" : error;
      return false;
    }
    pipeline.OutputGeometry = text == "target" ? 0 : 1;
  }
  else
  {
    recognized = false;
  }
  return true;
}

bool ParseCommandLine(int argc, char* argv[], CommandLine& commandLine, std::string& error)
{
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i)
  {
    const std::string option = argv[i];
    auto value = [&](std::string& out) {
      if (i + 1 >= argc)
      {
        error = option + " needs a value";
        return false;
      }
      out = argv[++i];
      return true;
    };
    std::string text;
    bool pipelineOption = false;
    if (!ParsePipelineOption(argc, argv, i, commandLine.Pipeline, pipelineOption, error))
    {
      return false;
    }
    if (pipelineOption)
    {
      continue;
    }
    if (option == "-h" || option == "--help")
    {
      commandLine.Help = true;
    }
    else if (option == "--version")
    {
      commandLine.Version = true;
    }
    else if (option == "--force")
    {
      commandLine.Force = true;
    }
    else if (option == "--quiet")
    {
      commandLine.Quiet = true;
    }
    else if (option == "--json")
    {
      commandLine.Json = true;
    }
    else if (option == "--symmetry")
    {
      std::string mesh;
      if (!value(mesh))
      {
        return false;
      }
      if (commandLine.Symmetry)
      {
        error = "--symmetry takes one mesh and may be given once";
        return false;
      }
      commandLine.Symmetry = true;
      commandLine.Source = mesh;
    }
    else if (option == "--orbifold")
    {
      std::string copies, mesh;
      if (!value(copies) || !value(mesh))
      {
        error = "--orbifold takes N (2..8) and a mesh";
        return false;
      }
      if (!ParseInteger(copies, commandLine.OrbifoldCopies) || commandLine.OrbifoldCopies < 2 ||
        commandLine.OrbifoldCopies > 8)
      {
        error = "--orbifold N: N must be an integer from 2 to 8, not '" + copies + "'";
        return false;
      }
      commandLine.Source = mesh;
    }
    else if (option == "--cones")
    {
      if (!value(text))
      {
        return false;
      }
      const auto comma = text.find(',');
      int cone0 = -1, cone1 = -1;
      if (comma == std::string::npos || !ParseInteger(text.substr(0, comma), cone0) ||
        !ParseInteger(text.substr(comma + 1), cone1) || cone0 < 0 || cone1 < 0)
      {
        error = "--cones takes two vertex numbers I,J (non-negative integers), not '" + text + "'";
        return false;
      }
      if (cone0 == cone1)
      {
        error = "--cones: the two cone vertices must differ";
        return false;
      }
      commandLine.Cones[0] = cone0;
      commandLine.Cones[1] = cone1;
    }
    else if (option == "--covering")
    {
      commandLine.Covering = true;
    }
    else if (option == "--no-centering")
    {
      commandLine.Pipeline.Centering = false;
    }
    else if (option == "-o" || option == "--output")
    {
      if (!value(commandLine.Output))
      {
        return false;
      }
    }
    else if (option == "--png")
    {
      if (!value(commandLine.Picture))
      {
        return false;
      }
    }
    else if (option.size() > 1 && option[0] == '-')
    {
      error = "unknown option " + option + " (see --help)";
      return false;
    }
    else
    {
      positional.push_back(option);
    }
  }
  if (commandLine.Help || commandLine.Version)
  {
    return true;
  }
  // Symmetry detection and the orbifold map center with the Möbius centering only.
  if (commandLine.Pipeline.CenteringDegree != 1 &&
    (commandLine.OrbifoldCopies > 0 || commandLine.Symmetry))
  {
    error = "--degree is for registering two meshes; --symmetry and --orbifold use the Moebius "
            "centering (degree 1)";
    return false;
  }
  if (commandLine.OrbifoldCopies > 0)
  {
    if (commandLine.Symmetry || !positional.empty())
    {
      error = "--orbifold takes one mesh; no --symmetry or SOURCE TARGET besides it (see --help)";
      return false;
    }
    if (!commandLine.Picture.empty() || !commandLine.Pipeline.Centering)
    {
      error = "--png and --no-centering are not available with --orbifold";
      return false;
    }
    if (commandLine.Output.empty())
    {
      error = "no output given: add -o OUT";
      return false;
    }
    return true;
  }
  if (commandLine.Cones[0] >= 0 || commandLine.Covering)
  {
    error = "--cones and --covering are for --orbifold only";
    return false;
  }
  if (commandLine.Symmetry)
  {
    if (!positional.empty())
    {
      error = "--symmetry takes one mesh; no SOURCE TARGET besides it (see --help)";
      return false;
    }
    if (!commandLine.Picture.empty())
    {
      error = "--png is not available with --symmetry";
      return false;
    }
    if (commandLine.Output.empty())
    {
      error = "no output given: add -o OUT";
      return false;
    }
    return true;
  }
  if (!commandLine.Pipeline.Centering)
  {
    error = "--no-centering is for --symmetry only";
    return false;
  }
  if (commandLine.Pipeline.Candidate >= commandLine.Pipeline.NumberOfCandidates)
  {
    error = "--candidate " + std::to_string(commandLine.Pipeline.Candidate) +
      " names no candidate: there are " + std::to_string(commandLine.Pipeline.NumberOfCandidates) +
      " (--candidates), numbered from 0";
    return false;
  }
  if (positional.empty())
  {
    commandLine.Demo = true;
    return true;
  }
  if (positional.size() != 2)
  {
    error = "expected two meshes, SOURCE and TARGET (see --help)";
    return false;
  }
  commandLine.Source = positional[0];
  commandLine.Target = positional[1];
  if (commandLine.Output.empty())
  {
    error = "no output given: add -o OUT";
    return false;
  }
  return true;
}
