// Scoring at ground-truth samples, the protocol of the published shape-correspondence tables
// (FAUST_r, SCAPE_r, SHREC'19_r, TOSCA, DT4D-H; Ren et al. 2018 and later): each shape X
// names, for every reference sample k, the vertex vts_X[k] that stands for it. For a map
// X -> Y, the error of sample k is the geodesic distance on Y between the vertex of Y
// nearest to the image of vts_X[k] and vts_Y[k], divided by sqrt(area(Y)); a pair scores the
// mean over its samples, a benchmark the mean (and median) over its pairs, in percent.
//
// Geodesics: edge paths (EdgePathGeodesics, CorrespondenceScore.h), shortened through Steiner
// points (CorridorGeodesics) to within about half a percent of exact geodesics for pairs
// that do not fail; see SampleGeodesics.
#ifndef mobius_SampleScore_h
#define mobius_SampleScore_h

#include "CorrespondenceScore.h"
#include "CorridorGeodesics.h"

#include <array>
#include <string>
#include <vector>

namespace mobius
{
/// The corner of a triangle (vertex indices `corners`, some may be -1: not a vertex the
/// caller can name) nearest to the point with these barycentric weights, by Euclidean
/// distance; -1 if no corner is valid.
Index NearestCorner(
  const Points& points, const std::array<Index, 3>& corners, const Eigen::Vector3d& weights);

/// How the sample errors measure geodesics. Every sample first by its edge path
/// (EdgePathGeodesics); then, if the pair's mean error is at most ShortenPairsUpTo, every
/// sample again by its edge path shortened through a corridor of Steiner points
/// (CorridorGeodesics). Measured against exact polyhedral geodesics (CGAL's
/// Surface_mesh_shortest_path) on 500 samples of 20 FAUST_r training pairs: edge paths
/// 4.5% long on the 16 pairs below 10, 5.0% on the 4 above; shortened with 3 Steiner points
/// 0.4% and 0.6% (1 point: 1.0%, 1.5%; 5 points: 0.3%). The pairs that fail keep their edge
/// paths: their errors are long paths (a limb or the body on the wrong side), whose corridors
/// are large, and shortening them made such a pair take 10 to 30 times longer to score, to
/// move a figure above 10 by 5%. The bound is twice the failure threshold, so that no pair
/// near it is counted as failed for want of shortening.
struct SampleGeodesics
{
  int SteinerPoints = 3;         ///< per edge; 0: edge paths only
  double ShortenPairsUpTo = 0.2; ///< mean error (units of sqrt(area)) up to which to shorten
};

/// Landmarks the sample scoring gives the edge-path searches (EdgePathGeodesics::
/// BuildLandmarks): they keep the long searches of a turned map to a corridor (README,
/// Accuracy). On pairs of about 5,000 vertices and samples, 8 scored faster than 4 or 16.
constexpr int SampleScoreLandmarks = 8;

/// Per sample k: the geodesic distance (see SampleGeodesics) on the target from vertex
/// mapped[k] to vertex truth[k], over sqrt(target area); `shortened` tells whether the
/// paths were shortened. The vectors must be as long; a negative mapped[k] (a sample the map
/// does not reach) gives NaN. Returns false with a message for an index out of range.
/// Threads: 0 for one per core.
bool ScoreSamples(const EdgePathGeodesics& target, const std::vector<Index>& mapped,
  const std::vector<Index>& truth, const SampleGeodesics& geodesics, int numberOfThreads,
  std::vector<double>& errors, bool& shortened, std::string& error);

/// A map is reported as mirrored or turned when its error against the mirror ground truth
/// is below its error against the direct one by more than this (errors in percent of
/// sqrt(area), the unit of the published tables). A correct map is far from the mirror
/// truth; a map that sends left to right, or front to back, is closer to it. The margin is
/// the benchmarks' failure threshold (a pair above 10 counts as failed), so that maps that
/// are poor everywhere, nearly as far from both truths, are not flagged.
constexpr double MirroredMargin = 10.0;

/// The pair threshold of the published "share of failed pairs": error above 10 (percent).
constexpr double FailedPairThreshold = 10.0;

struct PairErrorSummary
{
  Index Pairs = 0;
  double Mean = 0.0;
  double Median = 0.0;
  /// Share in [0, 1] of pairs whose error is above FailedPairThreshold.
  double ShareFailed = 0.0;
};

/// Mean, median (the mean of the two middle values for an even count) and share of failed
/// pairs of per-pair errors (in percent); NaN entries are left out.
PairErrorSummary SummarizePairErrors(const std::vector<double>& pairErrors);
}

#endif
