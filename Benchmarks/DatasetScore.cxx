#include "DatasetScore.h"

#include "CommandLine.h"
#include "Dataset.h"
#include "MemoryReuse.h"
#include "PairScore.h"
#include "RegistrationPipeline.h"
#include "ScoreInput.h"
#include "ParameterRules.h"
#include "VTKMessages.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"

#include <iostream>
#include <map>
#include <memory>

const char* const DatasetUsage =
  "usage: mobius-score --dataset DIR (--pairs FILE | --all | --random N)... [options]\n"
  "\n"
  "Runs the registration on pairs of shapes of a benchmark folder laid out as FAUST_r,\n"
  "SCAPE_r, SHREC'19_r, TOSCA and DT4D-H are (DIR/off/NAME.off; DIR/corres/NAME.vts, line k\n"
  "the 1-based vertex of NAME for reference sample k; optional DIR/corres/NAME.sym.vts, the\n"
  "mirror ground truth) and scores each map X -> Y by the published protocol: the error of\n"
  "sample k is the geodesic distance on Y between the vertex of Y nearest to the image of\n"
  "vertex X.vts[k] and vertex Y.vts[k], over sqrt(area of Y), x100; a pair scores the mean\n"
  "over its samples. Geodesics are shortest paths along Y's edges, about 5% longer than\n"
  "exact ones; for a pair whose error so measured is at most 20 they are then shortened\n"
  "through 3 points per edge of the triangles around them, to within about 0.5% of exact\n"
  "geodesics (the csv's geodesics column says which; errors against the mirror truth keep\n"
  "the edge paths). Prints a Markdown row per pair (error; error against the mirror truth\n"
  "where NAME.sym.vts exists, and 'yes' under 'mirrored' when the map is closer to the\n"
  "mirror truth by more than 10: left sent to right, or front to back; seconds of the\n"
  "registration; the refinement's kept candidate, of how many, and its orientation\n"
  "agreement), then the mean, the median and the share of pairs above 10. The vertex\n"
  "nearest to an image is the nearest corner of the triangle the image lies in.\n"
  "\n"
  "dataset options:\n"
  "  --dataset DIR       the benchmark folder\n"
  "  --pairs FILE        pairs to run, one 'X Y' or 'X,Y' per line (# comments)\n"
  "  --all               every pair X, Y of the shapes (X before Y in name order)\n"
  "  --random N          N distinct pairs among those, drawn with --seed (default 1)\n"
  "  --shapes PATTERN    --all and --random use the shapes whose names match this shell\n"
  "                      pattern (default *), e.g. 'tr_reg_0[0-7]?'\n"
  "  --maps DIR          score maps computed before instead of running the registration:\n"
  "                      DIR/X-Y.csv, as 'mobius-register off/X.off off/Y.off -o DIR/X-Y'\n"
  "                      writes them\n"
  "  --csv FILE          also write one row per pair: source, target, error, mirror_error,\n"
  "                      mirrored, euclidean_error, seconds, score_seconds, kept_candidate,\n"
  "                      candidates, orientation_agreement, unmapped_samples, geodesics,\n"
  "                      failure\n"
  "  --errors DIR        also write DIR/X-Y.csv per pair, one row per sample: sample,\n"
  "                      source_vertex, mapped_vertex, true_vertex, error, mirror_vertex,\n"
  "                      mirror_error (vertices 0-based as in mobius-register's CSV, errors\n"
  "                      x100)\n"
  "  --quiet             no progress and no pipeline warnings on standard error\n"
  "  registration options, passed to the pipeline as mobius-register takes them (see\n"
  "  mobius-register --help; defaults are mobius-register's): --refine, --basis-size,\n"
  "  --no-polish, --one-direction, --candidates, --candidate-separation, --resolution,\n"
  "  --smoothing, --transform, --degree, --iterations, --tolerance, --no-center-flow,\n"
  "  --fill-holes, --keep-largest-component, --allow-poor-maps, --threads (also the\n"
  "  threads of the scoring)\n"
  "\n"
  "Text inputs may start with a UTF-8 byte-order mark and end their lines with LF, CR LF or\n"
  "CR. Two pairs whose --maps or --errors files would be one (shapes a-b and c, a and b-c)\n"
  "are refused; --errors never writes over a --maps file, nor through a link or a device in\n"
  "its folder; --csv quotes names that hold commas. Shapes matching --shapes without a .vts\n"
  "file are named in a warning.\n"
  "\n"
  "Exit status: 0 when every pair was scored; 1 for input that cannot be read or does not\n"
  "fit together (a missing file, a vertex out of range, .vts files of different lengths),\n"
  "checked for every pair before any registration runs, or when a pair failed (the table\n"
  "is printed first); 2 for a usage error.\n";

namespace
{
const char* const Program = "mobius-score";

struct DatasetOptions
{
  std::string Folder, PairsPath, MapsFolder, CsvPath, ErrorsFolder, ShapePattern = "*";
  bool AllPairs = false;
  long long RandomCount = 0;
  unsigned long long Seed = 1;
  bool Quiet = false;
  PipelineOptions Pipeline;
  std::string RegistrationOption; // the first one given (not --threads), for the --maps check
};

int Fail(const std::string& message, int status = 1)
{
  std::cerr << Program << ": " << message << std::endl;
  return status;
}

int UsageError(const std::string& message)
{
  return Fail(message + " (see mobius-score --help)", 2);
}

// Returns 0 when parsed, else the exit status (after printing the message).
int ParseOptions(int argc, char* argv[], DatasetOptions& options)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string argument = argv[i];
    std::string error;
    bool pipelineOption = false;
    if (!ParsePipelineOption(argc, argv, i, options.Pipeline, pipelineOption, error))
    {
      return UsageError(error);
    }
    if (pipelineOption)
    {
      if (argument != "--threads" && options.RegistrationOption.empty())
      {
        options.RegistrationOption = argument;
      }
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
    std::string* path = argument == "--dataset" ? &options.Folder
      : argument == "--pairs"                   ? &options.PairsPath
      : argument == "--maps"                    ? &options.MapsFolder
      : argument == "--csv"                     ? &options.CsvPath
      : argument == "--errors"                  ? &options.ErrorsFolder
      : argument == "--shapes"                  ? &options.ShapePattern
                                                : nullptr;
    if (path)
    {
      if (!value(*path) || path->empty())
      {
        return UsageError(argument + " needs a value");
      }
    }
    else if (argument == "--all")
    {
      options.AllPairs = true;
    }
    else if (argument == "--")
    {
      continue; // the end of the options: nothing may follow (no positional arguments here)
    }
    else if (argument == "--quiet")
    {
      options.Quiet = true;
    }
    else if (argument == "--random" || argument == "--seed")
    {
      if (!count(number) || (argument == "--random" && number == 0))
      {
        return UsageError(argument + " needs a " +
          (argument == "--random" ? "positive count" : "non-negative integer"));
      }
      if (argument == "--random")
      {
        options.RandomCount = number;
      }
      else
      {
        options.Seed = static_cast<unsigned long long>(number);
      }
    }
    else
    {
      return UsageError(
        (argument[0] == '-' ? "unknown option " : "unexpected argument ") + argument +
        " with --dataset");
    }
  }
  const std::string outOfRange =
    mobius::CheckRegistrationParameters(options.Pipeline, mobius::ParameterNaming::CommandLine);
  if (!outOfRange.empty())
  {
    return UsageError(outOfRange);
  }
  if (options.PairsPath.empty() && !options.AllPairs && options.RandomCount == 0)
  {
    return UsageError("--dataset needs pairs: --pairs FILE, --all or --random N");
  }
  if (!options.MapsFolder.empty() && !options.RegistrationOption.empty())
  {
    return UsageError(options.RegistrationOption +
      " has no effect with --maps: the maps were computed before");
  }
  if (options.AllPairs && options.RandomCount > 0)
  {
    return UsageError("--all and --random exclude each other");
  }
  // The program's outputs never go over its inputs.
  if (!options.ErrorsFolder.empty() && !options.MapsFolder.empty() &&
    SameFile(options.ErrorsFolder, options.MapsFolder))
  {
    return UsageError("--errors and --maps name the same folder: the maps would be overwritten");
  }
  if (!options.CsvPath.empty() && !options.PairsPath.empty() &&
    SameFile(options.CsvPath, options.PairsPath))
  {
    return UsageError("--csv " + options.CsvPath + " is the --pairs file: it would be overwritten");
  }
  return 0;
}

// "a, b, c" (the first ten, then how many more).
std::string NameList(const std::vector<std::string>& names)
{
  std::string list;
  for (size_t k = 0; k < names.size() && k < 10; ++k)
  {
    list += (k ? ", " : "") + names[k];
  }
  return names.size() > 10 ? list + " and " + std::to_string(names.size() - 10) + " more" : list;
}

// The file of a pair in the --maps and --errors folders: FOLDER/X-Y.csv.
std::string PairFile(const std::string& folder, const ShapePair& pair)
{
  return folder + "/" + pair.first + "-" + pair.second + ".csv";
}

// Two different pairs whose files would be one (shapes a-b and c, a and b-c) are refused.
bool CheckPairFileNames(
  const std::string& folder, const std::vector<ShapePair>& pairs, std::string& error)
{
  std::map<std::string, ShapePair> used;
  for (const ShapePair& pair : pairs)
  {
    const auto [at, added] = used.emplace(PairFile(folder, pair), pair);
    if (!added && at->second != pair)
    {
      error = "the pairs " + at->second.first + " " + at->second.second + " and " + pair.first +
        " " + pair.second + " would both use " + at->first + "; rename a shape";
      return false;
    }
  }
  return true;
}

// The pairs asked for, and every shape they name loaded and checked.
bool CollectPairs(const DatasetOptions& options, const Dataset& dataset,
  std::vector<ShapePair>& pairs, std::map<std::string, std::shared_ptr<DatasetShape>>& shapes,
  std::string& error)
{
  if (!options.PairsPath.empty() && !ReadPairList(options.PairsPath, pairs, error))
  {
    return false;
  }
  if (options.AllPairs || options.RandomCount > 0)
  {
    std::vector<std::string> withoutSamples;
    const std::vector<std::string> names = dataset.ShapeNames(options.ShapePattern, withoutSamples);
    if (!withoutSamples.empty())
    {
      std::cerr << Program << ": warning: " << withoutSamples.size() << " shape(s) matching '"
                << options.ShapePattern << "' have no " << dataset.SamplesPath("NAME")
                << " and are left out: " << NameList(withoutSamples) << std::endl;
    }
    if (names.size() < 2)
    {
      error = options.Folder + ": " + std::to_string(names.size()) + " shape(s) match '" +
        options.ShapePattern + "' with both off/NAME.off and corres/NAME.vts; pairs need two";
      return false;
    }
    const std::vector<ShapePair> generated = options.AllPairs
      ? AllPairs(names)
      : RandomPairs(names, static_cast<std::size_t>(options.RandomCount), options.Seed);
    if (options.RandomCount > static_cast<long long>(generated.size()))
    {
      error = "--random " + std::to_string(options.RandomCount) + ": only " +
        std::to_string(generated.size()) + " pairs among the shapes matching '" +
        options.ShapePattern + "'";
      return false;
    }
    pairs.insert(pairs.end(), generated.begin(), generated.end());
  }
  if (pairs.empty())
  {
    error = options.PairsPath + ": no pairs";
    return false;
  }
  for (const ShapePair& pair : pairs)
  {
    for (const std::string& name : { pair.first, pair.second })
    {
      if (!shapes.count(name))
      {
        auto shape = std::make_shared<DatasetShape>();
        if (!dataset.Load(name, *shape, error))
        {
          return false;
        }
        shapes[name] = shape;
      }
    }
    const DatasetShape& x = *shapes[pair.first];
    const DatasetShape& y = *shapes[pair.second];
    if (x.Samples.size() != y.Samples.size())
    {
      error = "pair " + x.Name + " " + y.Name + ": " + dataset.SamplesPath(x.Name) + " has " +
        std::to_string(x.Samples.size()) + " samples, " + dataset.SamplesPath(y.Name) + " " +
        std::to_string(y.Samples.size());
      return false;
    }
  }
  for (const std::string* folder : { &options.MapsFolder, &options.ErrorsFolder })
  {
    if (!folder->empty() && !CheckPairFileNames(*folder, pairs, error))
    {
      return false;
    }
  }
  return true;
}

// Runs the registration (or reads the map) and scores one pair; a failure is recorded.
void RunPair(
  const DatasetOptions& options, const DatasetShape& x, const DatasetShape& y, PairScore& score)
{
  std::string error;
  std::vector<mobius::Index> images;
  if (!options.MapsFolder.empty())
  {
    if (!ImagesFromCsv(PairFile(options.MapsFolder, { x.Name, y.Name }), x, y, images, error))
    {
      score.Failure = error;
      return;
    }
  }
  else
  {
    vtkSmartPointer<vtkPolyData> source, target;
    PipelineResult result;
    if (!ReadMesh(x.MeshPath, source, error) || !ReadMesh(y.MeshPath, target, error) ||
      !RunRegistration(source, target, x.MeshPath, y.MeshPath, options.Pipeline, result, error) ||
      !ImagesFromPipeline(result.InputCorrespondence, x, y, images, error))
    {
      score.Failure = error;
      return;
    }
    score.Seconds = result.WallSeconds;
    if (result.Correspondence != result.MobiusCorrespondence)
    {
      vtkPolyData* refined = result.Correspondence;
      score.KeptCandidate = FieldValue(refined, "RefinementCandidate");
      score.OrientationAgreement = FieldValue(refined, "RefinementOrientationAgreement");
      vtkDataArray* candidates = refined->GetFieldData()->GetArray("CandidateOrthogonalityResiduals");
      score.Candidates = candidates ? candidates->GetNumberOfTuples() : NAN;
    }
    if (!options.Quiet)
    {
      for (const std::string& warning : result.Warnings)
      {
        std::cerr << Program << ": warning: " << warning << "\n";
      }
      for (const std::string& message : TakeVTKMessages())
      {
        std::cerr << Program << ": warning: VTK: " << message << "\n";
      }
    }
  }
  SampleErrors samples;
  if (!ScorePair(x, y, images, options.Pipeline.NumberOfThreads, score, samples, error) ||
    (!options.ErrorsFolder.empty() &&
      !WriteSampleErrors(PairFile(options.ErrorsFolder, { x.Name, y.Name }), x, y, samples, error)))
  {
    score.Failure = error;
  }
}
}

bool IsDatasetScore(int argc, char* argv[])
{
  for (int i = 1; i < argc && std::string(argv[i]) != "--"; ++i)
  {
    if (std::string(argv[i]) == "--dataset")
    {
      return true;
    }
  }
  return false;
}

int RunDatasetScore(int argc, char* argv[])
{
  DatasetOptions options;
  if (const int status = ParseOptions(argc, argv, options))
  {
    return status;
  }
  // As mobius-register runs: VTK's messages become warnings, freed memory is kept.
  CaptureVTKMessages();
  KeepFreedMemoryForReuse();
  std::string error;
  Dataset dataset;
  std::vector<ShapePair> pairs;
  std::map<std::string, std::shared_ptr<DatasetShape>> shapes;
  for (const std::string* folder : { &options.MapsFolder, &options.ErrorsFolder })
  {
    if (!folder->empty() && !IsDirectory(*folder))
    {
      return Fail(*folder + ": no such folder");
    }
  }
  if (!dataset.Open(options.Folder, error) ||
    !CollectPairs(options, dataset, pairs, shapes, error))
  {
    return Fail(error);
  }
  std::cout << "| source | target | error | mirror error | mirrored | seconds | candidate | of | "
               "orientation |\n|---|---|---:|---:|---|---:|---:|---:|---:|\n";
  std::vector<PairScore> scores(pairs.size());
  for (size_t p = 0; p < pairs.size(); ++p)
  {
    scores[p].Pair = pairs[p];
    if (!options.Quiet)
    {
      std::cerr << "[" << p + 1 << "/" << pairs.size() << "] " << pairs[p].first << " -> "
                << pairs[p].second << std::endl;
    }
    RunPair(options, *shapes[pairs[p].first], *shapes[pairs[p].second], scores[p]);
    if (!scores[p].Failure.empty())
    {
      std::cerr << Program << ": " << pairs[p].first << " -> " << pairs[p].second << ": "
                << scores[p].Failure << std::endl;
    }
    PrintPairRow(scores[p]);
    std::cout.flush();
  }
  PrintSummary(scores, !options.MapsFolder.empty());
  if (!options.CsvPath.empty() && !WritePairCsv(options.CsvPath, scores, error))
  {
    return Fail(error);
  }
  for (const PairScore& s : scores)
  {
    if (!s.Failure.empty())
    {
      return 1;
    }
  }
  return 0;
}
