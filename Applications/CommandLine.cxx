#include "CommandLine.h"

#include "LandmarkFile.h"
#include "ParameterRules.h"
#include "vtkSO3Register.h"

#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <sstream>
#include <utility>
#include <variant>
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

// Replaces every `placeholder` in `text` by `value`.
std::string Fill(std::string text, const std::string& placeholder, const std::string& value)
{
  for (size_t at = text.find(placeholder); at != std::string::npos;
       at = text.find(placeholder, at + value.size()))
  {
    text.replace(at, placeholder.size(), value);
  }
  return text;
}

// The copies of an orbifold map: the cyclic coverings SphericalOrbifoldMap builds.
constexpr mobius::IntegerRange OrbifoldCopyRange{ 2, 8 };
const std::string OrbifoldCopyWords =
  std::to_string(OrbifoldCopyRange.Minimum) + ".." + std::to_string(OrbifoldCopyRange.Maximum);

using Values = std::vector<std::string>;

// The field an option's value goes to: one of mobius-register's own, or one of the job's
// (PipelineOptions), whose defaults --help shows.
using Field = std::variant<std::monostate, bool CommandLine::*, std::string CommandLine::*,
  bool PipelineOptions::*, int PipelineOptions::*, double PipelineOptions::*>;

// The values --help says an option allows ("{range}" in its help). The job's are checked
// with the same ranges by CheckRegistrationParameters once every option is read, as Python
// and the filters do: one place for the rules of every interface.
using AllowedRange = std::variant<std::monostate, mobius::IntegerRange, mobius::NumberRange>;

// A word an option takes and the value it stores in the option's field.
struct Choice
{
  std::string Word;
  int Value;
};

// Applies the values of an option that a field alone cannot hold (two fields, a file, a
// pair); false with `error` set if they are wrong.
using Action = std::function<bool(const Values&, CommandLine&, std::string& error)>;

// A check of a stored value that cannot wait until every option is read.
using Check = std::function<bool(const CommandLine&, std::string& error)>;

// One row of the option table: an option, or (no Names) a heading of --help. Parsing,
// --help and the checks of each value's type all come from the rows.
struct Option
{
  std::string Label;              // as --help shows it: names, then values ("-o, --output OUT")
  std::vector<std::string> Names; // as typed: the words of Label that start with '-'
  int NumberOfValues = 0;         // the other words of Label
  std::string Help;               // one line per '\n'; {range} and {default} are filled in
  Field Into;                     // where the value goes (a flag stores FlagValue)
  bool FlagValue = true;
  AllowedRange Range;
  std::vector<Choice> Choices; // when not empty, the words the option takes
  Action Custom;               // instead of storing into Into
  Check CheckAtOnce;
  bool RegisterOnly = false;   // a job's option that mobius-score does not take
  std::string MissingValues;   // the message when values are missing ("": "X needs a value")

  Option(const std::string& label, const std::string& help, Field into = {});

  Option& Sets(bool value) { FlagValue = value; return *this; }
  Option& Allows(AllowedRange range) { Range = range; return *this; }
  Option& Takes(std::vector<Choice> choices) { Choices = std::move(choices); return *this; }
  Option& Does(Action action) { Custom = std::move(action); return *this; }
  Option& ChecksAtOnce(Check check) { CheckAtOnce = std::move(check); return *this; }
  Option& ForRegisterOnly() { RegisterOnly = true; return *this; }
  Option& WhenMissing(std::string message) { MissingValues = std::move(message); return *this; }

  // Shared with mobius-score (ParsePipelineOption): the job's options.
  bool IsPipelineOption() const;
};

Option::Option(const std::string& label, const std::string& help, Field into)
  : Label(label)
  , Help(help)
  , Into(into)
{
  std::istringstream words(label);
  for (std::string word; words >> word;)
  {
    if (word[0] == '-')
    {
      Names.push_back(word.back() == ',' ? word.substr(0, word.size() - 1) : word);
    }
    else
    {
      ++NumberOfValues;
    }
  }
}

bool Option::IsPipelineOption() const
{
  return !RegisterOnly &&
    (std::holds_alternative<bool PipelineOptions::*>(Into) ||
      std::holds_alternative<int PipelineOptions::*>(Into) ||
      std::holds_alternative<double PipelineOptions::*>(Into));
}

Option Heading(const std::string& text)
{
  Option heading("", "");
  heading.Label = text; // not parsed: a heading's words are not names
  return heading;
}

// The value of the word `text` given to option `name`; false with `error` if the option
// does not take it.
bool ChosenValue(
  const Option& option, const std::string& name, const std::string& text, int& value, std::string& error)
{
  std::string list;
  for (size_t w = 0; w < option.Choices.size(); ++w)
  {
    if (text == option.Choices[w].Word)
    {
      value = option.Choices[w].Value;
      return true;
    }
    list += (w == 0 ? "" : w + 1 == option.Choices.size() ? " or " : ", ") + option.Choices[w].Word;
  }
  error = name + " must be " + list + ", not '" + text + "'";
  return false;
}

// Stores an option's values into its field, read as the field's type (a flag stores its
// FlagValue, a choice its word's value); the message names the option as typed.
struct FieldWriter
{
  const Option& Row;
  const std::string& Name;
  const Values& Given;
  CommandLine& Line;
  std::string& Error;

  bool operator()(std::monostate) const { return true; }
  bool operator()(bool CommandLine::*field) const
  {
    Line.*field = Row.FlagValue;
    return true;
  }
  bool operator()(std::string CommandLine::*field) const
  {
    Line.*field = Given[0];
    return true;
  }
  bool operator()(bool PipelineOptions::*field) const
  {
    int value = Row.FlagValue;
    if (!Row.Choices.empty() && !ChosenValue(Row, Name, Given[0], value, Error))
    {
      return false;
    }
    Line.Pipeline.*field = value != 0;
    return true;
  }
  bool operator()(int PipelineOptions::*field) const
  {
    if (!Row.Choices.empty())
    {
      return ChosenValue(Row, Name, Given[0], Line.Pipeline.*field, Error);
    }
    if (!ParseInteger(Given[0], Line.Pipeline.*field))
    {
      Error = Name + " needs an integer, not '" + Given[0] + "'";
      return false;
    }
    return true;
  }
  // NaN and infinities are read as numbers; CheckRegistrationParameters refuses them.
  bool operator()(double PipelineOptions::*field) const
  {
    if (!ParseNumber(Given[0], Line.Pipeline.*field))
    {
      Error = Name + " needs a number, not '" + Given[0] + "'";
      return false;
    }
    return true;
  }
};

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
  const bool stored = option.Custom
    ? option.Custom(values, commandLine, error)
    : std::visit(FieldWriter{ option, name, values, commandLine, error }, option.Into);
  return stored && (!option.CheckAtOnce || option.CheckAtOnce(commandLine, error));
}

// The default of a job's option as --help gives it: its number, or the word that stores it.
std::string DefaultWords(const Option& option)
{
  static const PipelineOptions defaults;
  int value = 0;
  if (const auto field = std::get_if<int PipelineOptions::*>(&option.Into))
  {
    value = defaults.**field;
  }
  else if (const auto field = std::get_if<bool PipelineOptions::*>(&option.Into))
  {
    value = defaults.**field;
  }
  else if (const auto field = std::get_if<double PipelineOptions::*>(&option.Into))
  {
    return Format(defaults.**field);
  }
  for (const Choice& choice : option.Choices)
  {
    if (choice.Value == value)
    {
      return choice.Word;
    }
  }
  return std::to_string(value);
}

// An option's allowed values as --help gives them: "2 to 500".
std::string RangeWords(const AllowedRange& range)
{
  if (const auto integers = std::get_if<mobius::IntegerRange>(&range))
  {
    return std::to_string(integers->Minimum) + " to " + std::to_string(integers->Maximum);
  }
  if (const auto numbers = std::get_if<mobius::NumberRange>(&range))
  {
    return Format(numbers->Minimum) + " to " + Format(numbers->Maximum);
  }
  return "";
}

// Said at once, not after minutes of conformal maps (vtkSO3Register checks it too); even
// and large enough is CheckRegistrationParameters'.
bool ResolutionFitsMemory(const CommandLine& line, std::string& error)
{
  const int resolution = line.Pipeline.Resolution;
  if (resolution <= vtkSO3Register::LargestResolution())
  {
    return true;
  }
  std::ostringstream message;
  message << "--resolution " << resolution << " needs about "
          << vtkSO3Register::EstimateMemory(resolution) / 1e9
          << " GB, more than this machine's memory; at most "
          << vtkSO3Register::LargestResolution() << " fits";
  error = message.str();
  return false;
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
  if (!ParseInteger(values[0], line.OrbifoldCopies) ||
    !OrbifoldCopyRange.Contains(line.OrbifoldCopies))
  {
    error = "--orbifold N: N must be an integer from " + std::to_string(OrbifoldCopyRange.Minimum) +
      " to " + std::to_string(OrbifoldCopyRange.Maximum) + ", not '" + values[0] + "'";
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

// The table of options, in the order of --help, one function per part of it.
std::vector<Option> OutputOptions()
{
  return {
    Heading("Outputs (existing files are kept unless --force):"),
    Option("-o, --output OUT",
      "OUT.vtp: the source mesh mapped onto the target, with point\n"
      "arrays TargetCellId, TargetBarycentric, MappedPoints and the\n"
      "target's point arrays; OUT.csv: per source vertex, the target\n"
      "triangle, its vertices and the barycentric coordinates.\n"
      "The demo writes mobius-demo/demo.{vtp,csv,png} by default.",
      &CommandLine::Output),
    Option("--png FILE",
      "picture: source colored by position, and the target with\n"
      "the colors the map carries over (needs X; use xvfb-run)",
      &CommandLine::Picture),
  };
}

std::vector<Option> SymmetryAndOrbifoldOptions()
{
  return {
    Heading("\nSymmetry (paper Section 7.3):"),
    Option("--symmetry MESH",
      "bilateral symmetry of one mesh: its best orientation-\n"
      "reversing self-map. OUT.vtp: the mesh with the symmetric\n"
      "map (TargetCellId, TargetBarycentric, MappedPoints: each\n"
      "vertex's mirror image), Asymmetry per vertex and field data\n"
      "SymmetryDistance (0 symmetric .. 1), MirrorPlaneNormal,\n"
      "candidates; OUT.csv as for two meshes, the mesh against\n"
      "itself. Uses the options below except --transform.")
      .Does(SetSymmetry),
    // mobius-score registers pairs: it has no symmetry detection to uncenter.
    Option("--no-centering",
      "skip the Moebius centering (and the centering between flow\n"
      "steps): the paper's uncentered comparison; the flow then\n"
      "drifts and may need --allow-poor-maps",
      &PipelineOptions::Centering)
      .Sets(false)
      .ForRegisterOnly(),
    Heading("\nOrbifold map (paper Section 7.2):"),
    Option("--orbifold N MESH",
      "n-fold spherical orbifold map (N = " + OrbifoldCopyWords + "): cut MESH between\n"
      "two cone vertices, glue N copies into the cyclic covering,\n"
      "map and center it. OUT.vtp: one copy on its 1/N of the\n"
      "sphere (cones on the z axis), with SurfacePoints,\n"
      "InputPointId, field data SymmetryError, StdLogAreaRatio\n"
      "and PlainStdLogAreaRatio (area distortion of this map and\n"
      "of the plain one). Uses the conformal map options below.")
      .Does(SetOrbifold)
      .WhenMissing("--orbifold takes N (" + OrbifoldCopyWords + ") and a mesh"),
    Option("--cones I,J",
      "the cone vertices (vertex numbers in MESH; default two\n"
      "far-apart vertices)")
      .Does(SetCones),
    Option("--covering", "OUT.vtp holds the whole covering (all N copies)", &CommandLine::Covering),
  };
}

std::vector<Option> ConformalMapOptions()
{
  return {
    Heading("\nConformal map:"),
    Option("--iterations N", "maximum flow steps (default {default})", &PipelineOptions::FlowIterations),
    Option("--tolerance T", "flow convergence tolerance, {range} (default {default})",
      &PipelineOptions::FlowTolerance)
      .Allows(mobius::FlowToleranceRange),
    Option("--no-center-flow", "plain CMCF: no Moebius centering between flow steps",
      &PipelineOptions::CenterBetweenSteps)
      .Sets(false),
    Option("--no-repair",
      "strict: refuse a mesh that is not a closed, connected,\n"
      "manifold, oriented genus-0 surface instead of repairing it\n"
      "into a genus-0 proxy (the default: duplicate triangles\n"
      "removed, non-manifold vertices split, triangles oriented,\n"
      "small loose parts dropped, holes filled, handles cut)",
      &PipelineOptions::Repair)
      .Sets(false),
    Option("--fill-holes", "with --no-repair: close holes instead of refusing open meshes",
      &PipelineOptions::FillHoles),
    Option("--keep-largest-component",
      "map only the largest connected component (without it a\n"
      "loose part of a quarter of the largest one's area or more\n"
      "is refused; smaller ones are dropped unless --no-repair)",
      &PipelineOptions::KeepLargestComponent),
    Option("--allow-poor-maps",
      "write the result even when a conformal map is degenerate\n"
      "(triangles flipped after repair, area collapsed or\n"
      "squashed, flow not converged, squeezed-region\n"
      "refinement failed)",
      &PipelineOptions::AllowPoorMaps),
    Heading("Centering:"),
    Option("--degree L",
      "centering degree for both meshes, {range} (default {default}):\n"
      "1 is the paper's Moebius centering (conformal); 2..8 go on\n"
      "to its generalized centering (Section 5, Figure 5): no\n"
      "area moments of spherical-harmonic degree 1..L, area spread\n"
      "more evenly at the cost of conformality",
      &PipelineOptions::CenteringDegree)
      .Allows(mobius::CenteringDegreeRange),
  };
}

std::vector<Option> RegistrationOptions()
{
  return {
    Heading("Registration:"),
    Option("--resolution N",
      "scale-factor grid size, even, from " + std::to_string(mobius::MinimumResolution) +
        " as memory allows\n(default {default})",
      &PipelineOptions::Resolution)
      .ChecksAtOnce(ResolutionFitsMemory),
    Option("--smoothing T", "heat-kernel smoothing time, {range} (default {default})",
      &PipelineOptions::SmoothingTime)
      .Allows(mobius::SmoothingTimeRange),
    Option("--transform MODE", "rotation | reflection | both (default {default})",
      &PipelineOptions::TransformMode)
      .Takes({ { "rotation", 0 }, { "reflection", 1 }, { "both", 2 } }),
    Option("--candidates K", "correlation peaks to report, {range} (default {default})",
      &PipelineOptions::NumberOfCandidates)
      .Allows(mobius::CandidateCountRange),
    Option("--candidate-separation DEG",
      "smallest angle between two candidates, {range} degrees\n"
      "(default {default}): peaks nearer a better one are not\n"
      "reported; lower it to see near neighbours of a peak",
      &PipelineOptions::CandidateSeparation)
      .Allows(mobius::CandidateSeparationRange),
    Option("--candidate K",
      "keep the refinement's map from candidate K (0..K-1 of\n"
      "--candidates; 0 the best peak) instead of the one it\n"
      "chooses: for a map that came out turned or mirrored\n"
      "while a warning named a near-equal runner-up",
      &PipelineOptions::Candidate),
    Heading("Landmarks:"),
    Option("--landmarks FILE",
      "points whose images are known: per line a source vertex\n"
      "and its target vertex (0-based vertex numbers of the\n"
      "files, separated by a comma or spaces; # comments;\n"
      "a byte-order mark and CR LF or CR line ends are read).\n"
      "The rotation is chosen by them, the refinement maps them\n"
      "exactly; residuals in --json")
      .Does(SetLandmarks),
    Option("--landmark-mode M",
      "0: the rotation search chooses the transform that brings\n"
      "the landmarks together (default); 1: a Moebius transform\n"
      "sends the first 3 onto their targets (needs 3)",
      &PipelineOptions::LandmarkMode),
  };
}

std::vector<Option> CorrespondenceOptions()
{
  return {
    Heading("Correspondence:"),
    Option("--refine METHOD",
      "spectral | none: refine the Moebius map (ZoomOut on the\n"
      "surfaces' Laplace-Beltrami bases, from every candidate\n"
      "rotation) or keep the paper's map (default {default})",
      &PipelineOptions::Refine)
      .Takes({ { "spectral", true }, { "none", false } }),
    Option("--basis-size K", "eigenfunctions of the refinement, {range} (default {default})",
      &PipelineOptions::BasisSize)
      .Allows(mobius::BasisSizeRange),
    Option("--no-polish",
      "keep the spectral map: no geometric polish (ARAP\n"
      "non-rigid ICP of the source onto the target) after it",
      &PipelineOptions::GeometricPolish)
      .Sets(false),
    Option("--one-direction",
      "polish the map from source to target only; by default\n"
      "it is also polished the other way (a second thread)\n"
      "and each point averaged with its inverse (up to\n"
      "10,000 vertices, also every 10 iterations of the\n"
      "polishes): about 6% more accurate",
      &PipelineOptions::BothDirections)
      .Sets(false),
    Option("--both-directions", "the default (see --one-direction)", &PipelineOptions::BothDirections),
    Option("--output-geometry G", "target | source: where OUT.vtp's points are (default {default})",
      &PipelineOptions::OutputGeometry)
      .Takes({ { "target", 0 }, { "source", 1 } }),
  };
}

std::vector<Option> OtherOptions()
{
  return {
    Heading("Other:"),
    Option("--threads N",
      "threads per threaded stage, {range}; 0: one per core\n"
      "this process may use (CPU affinity), at most\n"
      "VTK_SMP_MAX_THREADS if set (default {default}); results are the\n"
      "same for any N",
      &PipelineOptions::NumberOfThreads)
      .Allows(mobius::ThreadCountRange),
    Option("--force", "overwrite existing output files", &CommandLine::Force),
    Option("--quiet", "no progress or warnings", &CommandLine::Quiet),
    Option("--json", "print a machine-readable summary on standard output", &CommandLine::Json),
    Option("--version", "print the program's and VTK's versions", &CommandLine::Version),
    Option("-h, --help", "print this help", &CommandLine::Help),
  };
}

// Every option of mobius-register, in the order of --help, which is made from it.
const std::vector<Option>& Options()
{
  static const std::vector<Option> options = [] {
    std::vector<Option> table;
    for (auto part : { OutputOptions, SymmetryAndOrbifoldOptions, ConformalMapOptions,
           RegistrationOptions, CorrespondenceOptions, OtherOptions })
    {
      for (Option& option : part())
      {
        table.push_back(std::move(option));
      }
    }
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

// The rules of --orbifold and --symmetry, which map one mesh.
bool CheckOneMeshJob(
  const CommandLine& commandLine, const std::vector<std::string>& positional, std::string& error)
{
  // Symmetry detection and the orbifold map center with the Möbius centering only.
  if (commandLine.Pipeline.CenteringDegree != 1)
  {
    error = "--degree is for registering two meshes; --symmetry and --orbifold use the Moebius "
            "centering (degree 1)";
    return false;
  }
  if (!commandLine.Pipeline.Landmarks.empty())
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
    return true;
  }
  if (commandLine.Cones[0] >= 0 || commandLine.Covering)
  {
    error = "--cones and --covering are for --orbifold only";
    return false;
  }
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
  return true;
}

// The rules of registering two meshes, SOURCE and TARGET, or of the demo when none is given.
bool TakeMeshPair(
  CommandLine& commandLine, const std::vector<std::string>& positional, std::string& error)
{
  if (commandLine.Cones[0] >= 0 || commandLine.Covering)
  {
    error = "--cones and --covering are for --orbifold only";
    return false;
  }
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
  return true;
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
  const bool oneMesh = commandLine.OrbifoldCopies > 0 || commandLine.Symmetry;
  if (!(oneMesh ? CheckOneMeshJob(commandLine, positional, error)
                : TakeMeshPair(commandLine, positional, error)))
  {
    return false;
  }
  // The demo names its own outputs.
  if (!commandLine.Demo && commandLine.Output.empty())
  {
    error = "no output given: add -o OUT";
    return false;
  }
  return true;
}

// An option as --help lists it: the label, then the help from column 25 (or two spaces
// after a longer label); a heading as it is.
std::string HelpEntry(const Option& option)
{
  if (option.Names.empty())
  {
    return option.Label + "\n";
  }
  const size_t column = 23;
  std::ostringstream text;
  text << "  " << option.Label;
  const std::string help = Fill(
    Fill(option.Help, "{range}", RangeWords(option.Range)), "{default}", DefaultWords(option));
  std::istringstream lines(help);
  std::string line;
  for (bool first = true; std::getline(lines, line); first = false)
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
  return text.str();
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
  for (const auto& option : Options())
  {
    text << HelpEntry(option);
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
  recognized = option && option->IsPipelineOption();
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
