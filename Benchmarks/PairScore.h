// One pair of a benchmark run (mobius-score --dataset): the map as the target vertex
// nearest to each source vertex's image, from the pipeline or from a mobius-register CSV,
// scored at the pair's samples (SampleScore.h); and the run's report: the Markdown rows
// and summary, the --csv and --errors files.
#ifndef PairScore_h
#define PairScore_h

#include "Dataset.h"
#include "SampleScore.h"

#include "vtkPolyData.h"

#include <cmath>
#include <string>
#include <vector>

/// What the run reports for one pair.
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

/// Per sample of a pair: the target vertex it was mapped to and its errors (fractions of
/// sqrt(area); mirror errors empty without a mirror truth).
struct SampleErrors
{
  std::vector<mobius::Index> Mapped;
  std::vector<double> Errors, MirrorErrors;
};

/// Per source vertex (file numbering), the target vertex nearest to its image, from the
/// pipeline's map; -1 for a vertex the map does not carry (merged or dropped by a repair).
bool ImagesFromPipeline(vtkPolyData* map, const DatasetShape& source, const DatasetShape& target,
  std::vector<mobius::Index>& images, std::string& error);

/// The same from a mobius-register CSV.
bool ImagesFromCsv(const std::string& path, const DatasetShape& source,
  const DatasetShape& target, std::vector<mobius::Index>& images, std::string& error);

/// Scores per-source-vertex images against the samples of the pair (errors, mirror errors,
/// Euclidean errors, unmapped samples, scoring seconds into `score`).
bool ScorePair(const DatasetShape& x, const DatasetShape& y, std::vector<mobius::Index> images,
  int threads, PairScore& score, SampleErrors& samples, std::string& error);

/// --errors DIR: DIR/X-Y.csv, one row per sample.
bool WriteSampleErrors(const std::string& path, const DatasetShape& x, const DatasetShape& y,
  const SampleErrors& samples, std::string& error);

/// The Markdown row of a pair.
void PrintPairRow(const PairScore& score);
/// The summary table over the pairs (fromCsv: no registration seconds).
void PrintSummary(const std::vector<PairScore>& scores, bool fromCsv);
/// --csv FILE: one row per pair.
bool WritePairCsv(const std::string& path, const std::vector<PairScore>& scores, std::string& error);

#endif
