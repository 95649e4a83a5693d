#include "CommandLine.h"

#include "LandmarkFile.h"
#include "ParameterRules.h"
#include "vtkSO3Register.h"

#include <cmath>
#include <cstdlib>
#include <functional>
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

std::string Format(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}

using Values = std::vector<std::string>;
// Applies an option's values to the command line; false with `error` set if they are wrong.
using Apply = std::function<bool(const Values&, CommandLine&, std::string& error)>;

// One row of the option table: an option, or (no Names) a heading of --help.
struct Option
{
  std::vector<std::string> Names; // as typed, e.g. { "-o", "--output" }
  std::string Label;              // as --help shows it, e.g. "-o, --output OUT"
  std::string Help;               // --help's text, one line per '\n'
  int NumberOfValues = 0;
  Apply Set;
  bool Pipeline = false; // shared with mobius-score (ParsePipelineOption)
  std::string MissingValues; // the message when values are missing ("" : "X needs a value")
};

Option Heading(const std::string& text)
{
  Option heading;
  heading.Label = text;
  return heading;
}

// An option of the job (PipelineOptions) that takes no value.
Option PipelineFlag(const std::string& name, const std::string& help,
  bool PipelineOptions::*member, bool value)
{
  return { { name }, name, help, 0,
    [member, value](const Values&, CommandLine& line, std::string&) {
      line.Pipeline.*member = value;
      return true;
    },
    true };
}

// An option of the job taking an integer. Its allowed values are checked with the others
// once every option is read (CheckRegistrationParameters), as Python and the filters do.
Option PipelineInteger(const std::string& name, const std::string& label, const std::string& help,
  int PipelineOptions::*member)
{
  return { { name }, label, help, 1,
    [=](const Values& values, CommandLine& line, std::string& error) {
      if (!ParseInteger(values[0], line.Pipeline.*member))
      {
        error = name + " needs an integer, not '" + values[0] + "'";
        return false;
      }
      return true;
    },
    true };
}

// A range as --help gives it: "2 to 500".
std::string IntegerRangeWords(const mobius::IntegerRange& range)
{
  return std::to_string(range.Minimum) + " to " + std::to_string(range.Maximum);
}

std::string NumberRangeWords(const mobius::NumberRange& range)
{
  return Format(range.Minimum) + " to " + Format(range.Maximum);
}

// An option of the job taking a number (checked as PipelineInteger's are; NaN and
// infinities are read as numbers and refused there).
Option PipelineNumber(const std::string& name, const std::string& label, const std::string& help,
  double PipelineOptions::*member)
{
  return { { name }, label, help, 1,
    [=](const Values& values, CommandLine& line, std::string& error) {
      if (!ParseNumber(values[0], line.Pipeline.*member))
      {
        error = name + " needs a number, not '" + values[0] + "'";
        return false;
      }
      return true;
    },
    true };
}

// An option of the job naming one of `words`; sets the word's position.
Option PipelineChoice(const std::string& name, const std::string& label, const std::string& help,
  const std::vector<std::string>& words, const std::function<void(PipelineOptions&, int)>& set)
{
  std::string list;
  for (size_t w = 0; w < words.size(); ++w)
  {
    list += (w == 0 ? "" : w + 1 == words.size() ? " or " : ", ") + words[w];
  }
  return { { name }, label, help, 1,
    [=](const Values& values, CommandLine& line, std::string& error) {
      for (size_t w = 0; w < words.size(); ++w)
      {
        if (values[0] == words[w])
        {
          set(line.Pipeline, static_cast<int>(w));
          return true;
        }
      }
      error = name + " must be " + list + ", not '" + values[0] + "'";
      return false;
    },
    true };
}

// An option of mobius-register alone that takes no value.
Option Flag(const std::vector<std::string>& names, const std::string& label,
  const std::string& help, bool CommandLine::*member)
{
  return { names, label, help, 0, [member](const Values&, CommandLine& line, std::string&) {
            line.*member = true;
            return true;
          } };
}

// An option of mobius-register alone that takes a file name.
Option FileName(const std::vector<std::string>& names, const std::string& label,
  const std::string& help, std::string CommandLine::*member)
{
  return { names, label, help, 1,
    [member](const Values& values, CommandLine& line, std::string&) {
      line.*member = values[0];
      return true;
    } };
}

bool SetResolution(const Values& values, CommandLine& line, std::string& error)
{
  int number = 0;
  if (!ParseInteger(values[0], number))
  {
    error = "--resolution needs an integer, not '" + values[0] + "'";
    return false;
  }
  // Even and large enough: CheckRegistrationParameters. Said now, not after minutes of conformal maps (vtkSO3Register checks it too).
  if (number > vtkSO3Register::LargestResolution())
  {
    std::ostringstream message;
    message << "--resolution " << number << " needs about "
            << vtkSO3Register::EstimateMemory(number) / 1e9
            << " GB, more than this machine's memory; at most "
            << vtkSO3Register::LargestResolution() << " fits";
    error = message.str();
    return false;
  }
  line.Pipeline.Resolution = number;
  return true;
}

bool SetSymmetry(const Values& values, CommandLine& line, std::string& error)
{
  if (line.Symmetry)
  {
    error = "--symmetry takes one mesh and may be given once";
    return false;
  }
  line.Symmetry = true;
  line.Source = values[0];
  return true;
}

bool SetOrbifold(const Values& values, CommandLine& line, std::string& error)
{
  if (!ParseInteger(values[0], line.OrbifoldCopies) || line.OrbifoldCopies < 2 ||
    line.OrbifoldCopies > 8)
  {
    error = "--orbifold N: N must be an integer from 2 to 8, not '" + values[0] + "'";
    return false;
  }
  line.Source = values[1];
  return true;
}

bool SetLandmarks(const Values& values, CommandLine& line, std::string& error)
{
  if (!line.Pipeline.Landmarks.empty())
  {
    error = "--landmarks may be given once";
    return false;
  }
  line.Pipeline.LandmarksFile = values[0];
  return ReadLandmarkFile(values[0], line.Pipeline.Landmarks, error);
}

bool SetCones(const Values& values, CommandLine& line, std::string& error)
{
  const std::string& text = values[0];
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
  line.Cones[0] = cone0;
  line.Cones[1] = cone1;
  return true;
}

// Every option of mobius-register, in the order of --help, which is made from it.
const std::vector<Option>& Options()
{
  static const std::vector<Option> options = [] {
    const PipelineOptions defaults;
    std::vector<Option> table = {
      Heading("Outputs (existing files are kept unless --force):"),
      FileName({ "-o", "--output" }, "-o, --output OUT",
        "OUT.vtp: the source mesh mapped onto the target, with point\n"
        "arrays TargetCellId, TargetBarycentric, MappedPoints and the\n"
        "target's point arrays; OUT.csv: per source vertex, the target\n"
        "triangle, its vertices and the barycentric coordinates.\n"
        "The demo writes mobius-demo/demo.{vtp,csv,png} by default.",
        &CommandLine::Output),
      FileName({ "--png" }, "--png FILE",
        "picture: source colored by position, and the target with\n"
        "the colors the map carries over (needs X; use xvfb-run)",
        &CommandLine::Picture),
      Heading("\nSymmetry (paper Section 7.3):"),
      { { "--symmetry" }, "--symmetry MESH",
        "bilateral symmetry of one mesh: its best orientation-\n"
        "reversing self-map. OUT.vtp: the mesh with the symmetric\n"
        "map (TargetCellId, TargetBarycentric, MappedPoints: each\n"
        "vertex's mirror image), Asymmetry per vertex and field data\n"
        "SymmetryDistance (0 symmetric .. 1), MirrorPlaneNormal,\n"
        "candidates; OUT.csv as for two meshes, the mesh against\n"
        "itself. Uses the options below except --transform.",
        1, SetSymmetry },
      { { "--no-centering" }, "--no-centering",
        "skip the Moebius centering (and the centering between flow\n"
        "steps): the paper's uncentered comparison; the flow then\n"
        "drifts and may need --allow-poor-maps",
        0,
        [](const Values&, CommandLine& line, std::string&) {
          line.Pipeline.Centering = false;
          return true;
        } },
      Heading("\nOrbifold map (paper Section 7.2):"),
      { { "--orbifold" }, "--orbifold N MESH",
        "n-fold spherical orbifold map (N = 2..8): cut MESH between\n"
        "two cone vertices, glue N copies into the cyclic covering,\n"
        "map and center it. OUT.vtp: one copy on its 1/N of the\n"
        "sphere (cones on the z axis), with SurfacePoints,\n"
        "InputPointId, field data SymmetryError, StdLogAreaRatio\n"
        "and PlainStdLogAreaRatio (area distortion of this map and\n"
        "of the plain one). Uses the conformal map options below.",
        2, SetOrbifold, false, "--orbifold takes N (2..8) and a mesh" },
      { { "--cones" }, "--cones I,J",
        "the cone vertices (vertex numbers in MESH; default two\n"
        "far-apart vertices)",
        1, SetCones },
      Flag({ "--covering" }, "--covering", "OUT.vtp holds the whole covering (all N copies)",
        &CommandLine::Covering),
      Heading("\nConformal map:"),
      PipelineInteger("--iterations", "--iterations N",
        "maximum flow steps (default " + std::to_string(defaults.FlowIterations) + ")",
        &PipelineOptions::FlowIterations),
      PipelineNumber("--tolerance", "--tolerance T",
        "flow convergence tolerance, " + NumberRangeWords(mobius::FlowToleranceRange) +
          " (default " + Format(defaults.FlowTolerance) + ")",
        &PipelineOptions::FlowTolerance),
      PipelineFlag("--no-center-flow", "plain CMCF: no Moebius centering between flow steps",
        &PipelineOptions::CenterBetweenSteps, false),
      PipelineFlag("--no-repair",
        "strict: refuse a mesh that is not a closed, connected,\n"
        "manifold, oriented genus-0 surface instead of repairing it\n"
        "into a genus-0 proxy (the default: duplicate triangles\n"
        "removed, non-manifold vertices split, triangles oriented,\n"
        "small loose parts dropped, holes filled, handles cut)",
        &PipelineOptions::Repair, false),
      PipelineFlag("--fill-holes", "with --no-repair: close holes instead of refusing open meshes",
        &PipelineOptions::FillHoles, true),
      PipelineFlag("--keep-largest-component",
        "map only the largest connected component (without it a\n"
        "loose part of a quarter of the largest one's area or more\n"
        "is refused; smaller ones are dropped unless --no-repair)",
        &PipelineOptions::KeepLargestComponent, true),
      PipelineFlag("--allow-poor-maps",
        "write the result even when a conformal map is degenerate\n"
        "(triangles flipped after repair, area collapsed or\n"
        "squashed, flow not converged, squeezed-region\n"
        "refinement failed)",
        &PipelineOptions::AllowPoorMaps, true),
      Heading("Centering:"),
      PipelineInteger("--degree", "--degree L",
        "centering degree for both meshes, " + IntegerRangeWords(mobius::CenteringDegreeRange) +
          " (default " +
          std::to_string(defaults.CenteringDegree) +
          "):\n"
          "1 is the paper's Moebius centering (conformal); 2..8 go on\n"
          "to its generalized centering (Section 5, Figure 5): no\n"
          "area moments of spherical-harmonic degree 1..L, area spread\n"
          "more evenly at the cost of conformality",
        &PipelineOptions::CenteringDegree),
      Heading("Registration:"),
      { { "--resolution" }, "--resolution N",
        "scale-factor grid size, even, from " + std::to_string(mobius::MinimumResolution) +
          " as memory allows\n(default " +
          std::to_string(defaults.Resolution) + ")",
        1, SetResolution, true },
      PipelineNumber("--smoothing", "--smoothing T",
        "heat-kernel smoothing time, " + NumberRangeWords(mobius::SmoothingTimeRange) +
          " (default " + Format(defaults.SmoothingTime) + ")",
        &PipelineOptions::SmoothingTime),
      PipelineChoice("--transform", "--transform MODE",
        "rotation | reflection | both (default rotation)", { "rotation", "reflection", "both" },
        [](PipelineOptions& pipeline, int mode) { pipeline.TransformMode = mode; }),
      PipelineInteger("--candidates", "--candidates K",
        "correlation peaks to report, " + IntegerRangeWords(mobius::CandidateCountRange) +
          " (default " + std::to_string(defaults.NumberOfCandidates) + ")",
        &PipelineOptions::NumberOfCandidates),
      PipelineInteger("--candidate", "--candidate K",
        "keep the refinement's map from candidate K (0..K-1 of\n"
        "--candidates; 0 the best peak) instead of the one it\n"
        "chooses: for a map that came out turned or mirrored\n"
        "while a warning named a near-equal runner-up",
        &PipelineOptions::Candidate),
      Heading("Landmarks:"),
      { { "--landmarks" }, "--landmarks FILE",
        "points whose images are known: per line a source vertex\n"
        "and its target vertex (0-based vertex numbers of the\n"
        "files, separated by a comma or spaces; # comments;\n"
        "a byte-order mark and CR LF or CR line ends are read).\n"
        "The rotation is chosen by them, the refinement maps them\n"
        "exactly; residuals in --json",
        1, SetLandmarks },
      PipelineInteger("--landmark-mode", "--landmark-mode M",
        "0: the rotation search chooses the transform that brings\n"
        "the landmarks together (default); 1: a Moebius transform\n"
        "sends the first 3 onto their targets (needs 3)",
        &PipelineOptions::LandmarkMode),
      Heading("Correspondence:"),
      PipelineChoice("--refine", "--refine METHOD",
        "spectral | none: refine the Moebius map (ZoomOut on the\n"
        "surfaces' Laplace-Beltrami bases, from every candidate\n"
        "rotation) or keep the paper's map (default spectral)",
        { "spectral", "none" },
        [](PipelineOptions& pipeline, int method) { pipeline.Refine = method == 0; }),
      PipelineInteger("--basis-size", "--basis-size K",
        "eigenfunctions of the refinement, " + IntegerRangeWords(mobius::BasisSizeRange) +
          " (default " + std::to_string(defaults.BasisSize) + ")",
        &PipelineOptions::BasisSize),
      PipelineFlag("--no-polish",
        "keep the spectral map: no geometric polish (ARAP\n"
        "non-rigid ICP of the source onto the target) after it",
        &PipelineOptions::GeometricPolish, false),
      PipelineFlag("--one-direction",
        "polish the map from source to target only; by default\n"
        "it is also polished the other way (a second thread)\n"
        "and each point averaged with its inverse (up to\n"
        "10,000 vertices, also every 10 iterations of the\n"
        "polishes): about 6% more accurate",
        &PipelineOptions::BothDirections, false),
      PipelineFlag("--both-directions", "the default (see --one-direction)",
        &PipelineOptions::BothDirections, true),
      PipelineChoice("--output-geometry", "--output-geometry G",
        "target | source: where OUT.vtp's points are (default target)", { "target", "source" },
        [](PipelineOptions& pipeline, int geometry) { pipeline.OutputGeometry = geometry; }),
      Heading("Other:"),
      PipelineInteger("--threads", "--threads N",
        "threads per threaded stage, " + IntegerRangeWords(mobius::ThreadCountRange) +
          "; 0: one per core\n"
          "this process may use (CPU affinity), at most\n"
          "VTK_SMP_MAX_THREADS if set (default " +
          std::to_string(defaults.NumberOfThreads) +
          "); results are the\n"
          "same for any N",
        &PipelineOptions::NumberOfThreads),
      Flag({ "--force" }, "--force", "overwrite existing output files", &CommandLine::Force),
      Flag({ "--quiet" }, "--quiet", "no progress or warnings", &CommandLine::Quiet),
      Flag({ "--json" }, "--json", "print a machine-readable summary on standard output",
        &CommandLine::Json),
      Flag({ "--version" }, "", "", &CommandLine::Version),
      Flag({ "-h", "--help" }, "--version, -h/--help", "", &CommandLine::Help),
    };
    return table;
  }();
  return options;
}

// The table's row for `name`, or null.
const Option* FindOption(const std::string& name)
{
  for (const auto& option : Options())
  {
    for (const auto& known : option.Names)
    {
      if (known == name)
      {
        return &option;
      }
    }
  }
  return nullptr;
}

// Applies `option` to argv[i] onwards, advancing i past its values.
bool ApplyOption(const Option& option, int argc, char* argv[], int& i, CommandLine& commandLine,
  std::string& error)
{
  const std::string name = argv[i];
  Values values;
  while (static_cast<int>(values.size()) < option.NumberOfValues)
  {
    if (i + 1 >= argc)
    {
      error = option.MissingValues.empty() ? name + " needs a value" : option.MissingValues;
      return false;
    }
    values.push_back(argv[++i]);
  }
  return option.Set(values, commandLine, error);
}

// The rules between options, checked once they are all read.
bool CheckCombination(
  CommandLine& commandLine, const std::vector<std::string>& positional, std::string& error)
{
  error = mobius::CheckRegistrationParameters(commandLine.Pipeline, mobius::ParameterNaming::CommandLine);
  if (!error.empty())
  {
    return false;
  }
  // Symmetry detection and the orbifold map center with the Möbius centering only.
  if (commandLine.Pipeline.CenteringDegree != 1 &&
    (commandLine.OrbifoldCopies > 0 || commandLine.Symmetry))
  {
    error = "--degree is for registering two meshes; --symmetry and --orbifold use the Moebius "
            "centering (degree 1)";
    return false;
  }
  if ((commandLine.OrbifoldCopies > 0 || commandLine.Symmetry) &&
    !commandLine.Pipeline.Landmarks.empty())
  {
    error = "--landmarks is for registering two meshes, not for --symmetry or --orbifold";
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
  }
  else if (commandLine.Cones[0] >= 0 || commandLine.Covering)
  {
    error = "--cones and --covering are for --orbifold only";
    return false;
  }
  else if (commandLine.Symmetry)
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
  }
  else
  {
    if (!commandLine.Pipeline.Centering)
    {
      error = "--no-centering is for --symmetry only";
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
  }
  if (commandLine.Output.empty())
  {
    error = "no output given: add -o OUT";
    return false;
  }
  return true;
}
}

std::string UsageText()
{
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
          "\n";
  // Options: the label, then the help from column 25 (or two spaces after a longer label).
  const size_t column = 23;
  for (const auto& option : Options())
  {
    if (option.Names.empty())
    {
      text << option.Label << "\n";
      continue;
    }
    if (option.Label.empty())
    {
      continue; // listed with another row (--version with -h/--help)
    }
    text << "  " << option.Label;
    std::istringstream help(option.Help);
    std::string line;
    for (bool first = true; std::getline(help, line); first = false)
    {
      if (first)
      {
        text << std::string(option.Label.size() + 2 <= column ? column - option.Label.size() : 2, ' ');
      }
      else
      {
        text << "\n" << std::string(column + 2, ' ');
      }
      text << line;
    }
    text << "\n";
  }
  text << "\n"
          "Exit status: 0 on success; 1 if a mesh cannot be read or mapped (a degenerate map\n"
          "included, unless --allow-poor-maps), a landmark names a vertex a mesh does not\n"
          "have or its repair removed, or an output cannot be written (an existing file\n"
          "without --force included); 2 for usage errors (unknown options, values out of\n"
          "range, wrong number of meshes, no -o, a landmarks file that cannot be read, is a\n"
          "folder, holds a malformed line or no landmark, or gives a vertex twice).\n"
          "\n"
          "'--' ends the options: the arguments after it are meshes, also one whose name\n"
          "starts with '-'.\n";
  return text.str();
}

bool ParsePipelineOption(
  int argc, char* argv[], int& i, PipelineOptions& pipeline, bool& recognized, std::string& error)
{
  const Option* option = FindOption(argv[i]);
  recognized = option && option->Pipeline;
  if (!recognized)
  {
    return true;
  }
  CommandLine commandLine;
  commandLine.Pipeline = pipeline;
  if (!ApplyOption(*option, argc, argv, i, commandLine, error))
  {
    return false;
  }
  pipeline = commandLine.Pipeline;
  return true;
}

bool ParseCommandLine(int argc, char* argv[], CommandLine& commandLine, std::string& error)
{
  std::vector<std::string> positional;
  bool optionsEnded = false; // after "--" every argument is a file, "-name" included
  for (int i = 1; i < argc; ++i)
  {
    const std::string argument = argv[i];
    if (optionsEnded)
    {
      positional.push_back(argument);
    }
    else if (argument == "--")
    {
      optionsEnded = true;
    }
    else if (const Option* option = FindOption(argument))
    {
      if (!ApplyOption(*option, argc, argv, i, commandLine, error))
      {
        return false;
      }
    }
    else if (argument.size() > 1 && argument[0] == '-')
    {
      error = "unknown option " + argument + " (see --help)";
      return false;
    }
    else
    {
      positional.push_back(argument);
    }
  }
  if (commandLine.Help || commandLine.Version)
  {
    return true;
  }
  return CheckCombination(commandLine, positional, error);
}
