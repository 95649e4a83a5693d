#include "DatasetScore.h"

#include "CommandLine.h"
#include "Dataset.h"
#include "MemoryReuse.h"
#include "RegistrationPipeline.h"
#include "SampleScore.h"
#include "ScoreInput.h"
#include "VTKMessages.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

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
  "  --no-polish, --candidates, --resolution, --smoothing, --transform, --degree,\n"
  "  --iterations, --tolerance, --no-center-flow, --fill-holes, --keep-largest-component,\n"
  "  --allow-poor-maps, --threads (also the threads of the scoring)\n"
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

struct PairScore
{
  ShapePair Pair;
  std::string Failure; // empty when scored
  double Error = NAN, MirrorError = NAN, EuclideanError = NAN; // percent of sqrt(area)
  double Seconds = NAN, ScoreSeconds = NAN;
  double KeptCandidate = NAN, Candidates = NAN, OrientationAgreement = NAN;
  mobius::Index Unmapped = 0;
  bool Shortened = false; // geodesics shortened (SampleGeodesics)
  bool Mirrored() const { return MirrorError < Error - mobius::MirroredMargin; }
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
  return 0;
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
    const std::vector<std::string> names = dataset.ShapeNames(options.ShapePattern);
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
  return true;
}

// Per source vertex (file numbering), the target vertex nearest to its image, from the
// pipeline's map; -1 for a vertex the map does not carry (merged or dropped by a repair).
bool ImagesFromPipeline(vtkPolyData* map, const DatasetShape& source, const DatasetShape& target,
  std::vector<mobius::Index>& images, std::string& error)
{
  vtkPointData* data = map->GetPointData();
  vtkDataArray* sourceIds = data->GetArray("InputPointId");
  vtkDataArray* targetIds = data->GetArray("TargetInputPointIds");
  vtkDataArray* weights = data->GetArray("TargetBarycentric");
  if (!sourceIds || !targetIds || !weights)
  {
    error = "the map lacks InputPointId, TargetInputPointIds or TargetBarycentric";
    return false;
  }
  images.assign(source.Points.rows(), -1);
  for (vtkIdType i = 0; i < map->GetNumberOfPoints(); ++i)
  {
    const auto vertex = static_cast<mobius::Index>(sourceIds->GetComponent(i, 0));
    std::array<mobius::Index, 3> corners;
    Eigen::Vector3d w;
    for (int k = 0; k < 3; ++k)
    {
      corners[k] = static_cast<mobius::Index>(targetIds->GetComponent(i, k));
      w[k] = weights->GetComponent(i, k);
    }
    if (vertex >= 0 && vertex < source.Points.rows())
    {
      images[vertex] = mobius::NearestCorner(target.Points, corners, w);
    }
  }
  return true;
}

// The same from a mobius-register CSV.
bool ImagesFromCsv(const std::string& path, const DatasetShape& source,
  const DatasetShape& target, std::vector<mobius::Index>& images, std::string& error)
{
  std::vector<mobius::SurfacePoint> mapped;
  if (!ReadMap(path, target.Points, target.Triangles, mapped, error))
  {
    return false;
  }
  if (static_cast<mobius::Index>(mapped.size()) != source.Points.rows())
  {
    error = path + ": " + std::to_string(mapped.size()) + " rows, but " + source.MeshPath +
      " has " + std::to_string(source.Points.rows()) + " vertices";
    return false;
  }
  images.resize(mapped.size());
  for (size_t i = 0; i < mapped.size(); ++i)
  {
    const auto& row = target.Triangles.row(mapped[i].Triangle);
    images[i] = mobius::NearestCorner(target.Points, { row[0], row[1], row[2] }, mapped[i].Barycentric);
  }
  return true;
}

// A source vertex the map does not carry takes the image of the nearest one it does
// (a merged duplicate: the one at the same place). Returns how many were filled.
mobius::Index FillUnmapped(const mobius::Points& points, std::vector<mobius::Index>& images)
{
  std::vector<mobius::Index> missing;
  for (size_t v = 0; v < images.size(); ++v)
  {
    if (images[v] < 0)
    {
      missing.push_back(static_cast<mobius::Index>(v));
    }
  }
  for (mobius::Index v : missing)
  {
    double best = INFINITY;
    for (size_t u = 0; u < images.size(); ++u)
    {
      const double d = (points.row(u) - points.row(v)).squaredNorm();
      if (images[u] >= 0 && d < best)
      {
        best = d;
        images[v] = images[u];
      }
    }
  }
  return static_cast<mobius::Index>(missing.size());
}

double MeanPercent(const std::vector<double>& errors)
{
  double sum = 0;
  for (double e : errors)
  {
    sum += e;
  }
  return 100.0 * sum / static_cast<double>(errors.size());
}

// The mirror errors only flag a map that is mirrored or turned: edge paths (about 5% long)
// are enough, and the long paths of a correct map's mirror errors would make shortening
// them the dearest part of the scoring.
mobius::SampleGeodesics EdgePathsOnly()
{
  mobius::SampleGeodesics edges;
  edges.SteinerPoints = 0;
  return edges;
}

// Per sample of a pair: the target vertex it was mapped to and its errors (fractions of
// sqrt(area); mirror errors empty without a mirror truth).
struct SampleErrors
{
  std::vector<mobius::Index> Mapped;
  std::vector<double> Errors, MirrorErrors;
};

// Scores per-source-vertex images against the samples of the pair.
bool ScorePair(const DatasetShape& x, const DatasetShape& y, std::vector<mobius::Index> images,
  int threads, PairScore& score, SampleErrors& samples, std::string& error)
{
  const auto start = std::chrono::steady_clock::now();
  score.Unmapped = 0;
  for (mobius::Index s : x.Samples)
  {
    score.Unmapped += images[s] < 0 ? 1 : 0;
  }
  if (score.Unmapped > 0)
  {
    FillUnmapped(x.Points, images);
  }
  samples = SampleErrors();
  for (mobius::Index s : x.Samples)
  {
    samples.Mapped.push_back(images[s]);
  }
  mobius::EdgePathGeodesics geodesics;
  bool mirrorShortened = false;
  const bool built = geodesics.Build(y.Points, y.Triangles, error);
  geodesics.BuildLandmarks(mobius::SampleScoreLandmarks);
  if (!built ||
    !mobius::ScoreSamples(geodesics, samples.Mapped, y.Samples, {}, threads, samples.Errors,
      score.Shortened, error) ||
    (!y.MirrorSamples.empty() &&
      !mobius::ScoreSamples(geodesics, samples.Mapped, y.MirrorSamples, EdgePathsOnly(), threads,
        samples.MirrorErrors, mirrorShortened, error)))
  {
    error = y.MeshPath + ": " + error;
    return false;
  }
  score.Error = MeanPercent(samples.Errors);
  score.MirrorError = samples.MirrorErrors.empty() ? NAN : MeanPercent(samples.MirrorErrors);
  double euclidean = 0;
  for (size_t k = 0; k < samples.Mapped.size(); ++k)
  {
    euclidean += (y.Points.row(samples.Mapped[k]) - y.Points.row(y.Samples[k])).norm();
  }
  score.EuclideanError =
    100.0 * euclidean / samples.Mapped.size() / std::sqrt(geodesics.GetSurfaceArea());
  score.ScoreSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}

// --errors DIR: DIR/X-Y.csv, one row per sample.
bool WriteSampleErrors(const std::string& path, const DatasetShape& x, const DatasetShape& y,
  const SampleErrors& samples, std::string& error)
{
  std::ofstream csv(path);
  csv << "sample,source_vertex,mapped_vertex,true_vertex,error,mirror_vertex,mirror_error\n";
  csv.precision(8);
  for (size_t k = 0; k < samples.Mapped.size(); ++k)
  {
    csv << k + 1 << ',' << x.Samples[k] << ',' << samples.Mapped[k] << ',' << y.Samples[k] << ','
        << 100 * samples.Errors[k] << ',';
    if (!samples.MirrorErrors.empty())
    {
      csv << y.MirrorSamples[k] << ',' << 100 * samples.MirrorErrors[k];
    }
    else
    {
      csv << ',';
    }
    csv << '\n';
  }
  if (!csv)
  {
    error = path + ": cannot write the file";
    return false;
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
    if (!ImagesFromCsv(options.MapsFolder + "/" + x.Name + "-" + y.Name + ".csv", x, y, images,
          error))
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
      !ImagesFromPipeline(result.Correspondence, x, y, images, error))
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
      !WriteSampleErrors(options.ErrorsFolder + "/" + x.Name + "-" + y.Name + ".csv", x, y, samples, error)))
  {
    score.Failure = error;
  }
}

std::string Fixed(double value, int digits)
{
  if (std::isnan(value))
  {
    return "";
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

void PrintRow(const PairScore& s)
{
  std::cout << "| " << s.Pair.first << " | " << s.Pair.second << " | ";
  if (!s.Failure.empty())
  {
    std::cout << "FAILED | | | | | | |\n";
    return;
  }
  std::cout << Fixed(s.Error, 2) << " | " << Fixed(s.MirrorError, 2) << " | "
            << (std::isnan(s.MirrorError) ? "" : s.Mirrored() ? "yes" : "no") << " | "
            << Fixed(s.Seconds, 2) << " | " << Fixed(s.KeptCandidate, 0) << " | "
            << Fixed(s.Candidates, 0) << " | " << Fixed(s.OrientationAgreement, 2) << " |\n";
}

const char* PathKind(bool shortened)
{
  return shortened ? "shortened" : "edge paths";
}

bool WriteCsv(const std::string& path, const std::vector<PairScore>& scores, std::string& error)
{
  std::ofstream csv(path);
  csv << "source,target,error,mirror_error,mirrored,euclidean_error,seconds,score_seconds,"
         "kept_candidate,candidates,orientation_agreement,unmapped_samples,geodesics,failure\n";
  for (const PairScore& s : scores)
  {
    std::string failure = s.Failure;
    for (char& c : failure)
    {
      c = c == '"' ? '\'' : c;
    }
    csv << s.Pair.first << ',' << s.Pair.second << ',' << Fixed(s.Error, 4) << ','
        << Fixed(s.MirrorError, 4) << ','
        << (!s.Failure.empty() || std::isnan(s.MirrorError) ? "" : s.Mirrored() ? "1" : "0") << ','
        << Fixed(s.EuclideanError, 4) << ',' << Fixed(s.Seconds, 3) << ','
        << Fixed(s.ScoreSeconds, 3) << ',' << Fixed(s.KeptCandidate, 0) << ','
        << Fixed(s.Candidates, 0) << ',' << Fixed(s.OrientationAgreement, 4) << ','
        << (s.Failure.empty() ? std::to_string(s.Unmapped) : "") << ','
        << (s.Failure.empty() ? PathKind(s.Shortened) : "") << ",\"" << failure << "\"\n";
  }
  if (!csv)
  {
    error = path + ": cannot write the file";
    return false;
  }
  return true;
}

double Median(std::vector<double> values)
{
  std::vector<double> kept;
  for (double v : values)
  {
    if (!std::isnan(v))
    {
      kept.push_back(v);
    }
  }
  return mobius::SummarizePairErrors(kept).Median;
}

void PrintSummary(const std::vector<PairScore>& scores, bool fromCsv)
{
  std::vector<double> errors, mirrorErrors, seconds, scoreSeconds;
  size_t failed = 0, mirrored = 0, withMirror = 0;
  for (const PairScore& s : scores)
  {
    if (!s.Failure.empty())
    {
      ++failed;
      continue;
    }
    errors.push_back(s.Error);
    seconds.push_back(s.Seconds);
    scoreSeconds.push_back(s.ScoreSeconds);
    if (!std::isnan(s.MirrorError))
    {
      ++withMirror;
      mirrored += s.Mirrored() ? 1 : 0;
    }
  }
  const mobius::PairErrorSummary summary = mobius::SummarizePairErrors(errors);
  std::cout << "\n| pairs | mean | median | > 10 | mirrored | s/pair (median) | scoring s/pair |\n"
            << "|---:|---:|---:|---:|---:|---:|---:|\n"
            << "| " << summary.Pairs << " | " << Fixed(summary.Mean, 2) << " | "
            << Fixed(summary.Median, 2) << " | " << Fixed(100 * summary.ShareFailed, 1) << "% | "
            << (withMirror ? std::to_string(mirrored) + " of " + std::to_string(withMirror) : "")
            << " | " << (fromCsv ? "" : Fixed(Median(seconds), 2)) << " | "
            << Fixed(Median(scoreSeconds), 3) << " |\n\n"
            << "Errors: mean geodesic distance at the .vts samples over sqrt(target area), x100.\n"
            << "Geodesics: shortest paths along the target's edges, shortened through 3 points\n"
            << "per edge for pairs whose edge-path error is at most 20 (within about 0.5% of\n"
            << "exact geodesics); edge paths, about 5% long, for pairs above 20 and for the\n"
            << "mirror errors.\n";
  if (failed)
  {
    std::cout << failed << " of " << scores.size() << " pairs FAILED (not in the figures).\n";
  }
}
}

bool IsDatasetScore(int argc, char* argv[])
{
  for (int i = 1; i < argc; ++i)
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
    PrintRow(scores[p]);
    std::cout.flush();
  }
  PrintSummary(scores, !options.MapsFolder.empty());
  if (!options.CsvPath.empty() && !WriteCsv(options.CsvPath, scores, error))
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
