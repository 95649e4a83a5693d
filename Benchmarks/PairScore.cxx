#include "PairScore.h"

#include "ScoreInput.h"

#include "PublishOutputs.h"
#include "TextFormats.h"

#include "vtkDataArray.h"
#include "vtkPointData.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace
{
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
  const std::vector<mobius::Index> carried = images;
  for (mobius::Index v : missing)
  {
    double best = INFINITY;
    for (size_t u = 0; u < carried.size(); ++u)
    {
      const double d = (points.row(u) - points.row(v)).squaredNorm();
      if (carried[u] >= 0 && d < best)
      {
        best = d;
        images[v] = carried[u];
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

const char* PathKind(bool shortened)
{
  return shortened ? "shortened" : "edge paths";
}

double Median(const std::vector<double>& values)
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
}

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

bool WriteSampleErrors(const std::string& path, const DatasetShape& x, const DatasetShape& y,
  const SampleErrors& samples, std::string& error)
{
  std::ostringstream csv;
  // A file the program names itself is replaced, never written through (a link planted in
  // the folder would send the rows anywhere).
  if (IsNotRegularFile(path))
  {
    error = path + " exists and is not a regular file (a link, a device or a folder): not written";
    return false;
  }
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
  return ReplaceFile(path, csv.str(), error);
}

void PrintPairRow(const PairScore& s)
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

bool WritePairCsv(const std::string& path, const std::vector<PairScore>& scores, std::string& error)
{
  std::ostringstream csv;
  csv << "source,target,error,mirror_error,mirrored,euclidean_error,seconds,score_seconds,"
         "kept_candidate,candidates,orientation_agreement,unmapped_samples,geodesics,failure\n";
  for (const PairScore& s : scores)
  {
    csv << CsvField(s.Pair.first) << ',' << CsvField(s.Pair.second) << ',' << Fixed(s.Error, 4)
        << ',' << Fixed(s.MirrorError, 4) << ','
        << (!s.Failure.empty() || std::isnan(s.MirrorError) ? "" : s.Mirrored() ? "1" : "0") << ','
        << Fixed(s.EuclideanError, 4) << ',' << Fixed(s.Seconds, 3) << ','
        << Fixed(s.ScoreSeconds, 3) << ',' << Fixed(s.KeptCandidate, 0) << ','
        << Fixed(s.Candidates, 0) << ',' << Fixed(s.OrientationAgreement, 4) << ','
        << (s.Failure.empty() ? std::to_string(s.Unmapped) : "") << ','
        << (s.Failure.empty() ? PathKind(s.Shortened) : "") << ',' << CsvField(s.Failure) << "\n";
  }
  return ReplaceFile(path, csv.str(), error);
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
