// Ground-truth scoring of a dense map, the project's measurement protocol (Kim, Lipman &
// Funkhouser, Blended Intrinsic Maps, SIGGRAPH 2011): the error of a source vertex is the
// distance ON THE TARGET between the point the map sends it to and its true image, divided by
// the square root of the target's surface area. Reported both as the Euclidean (straight-line)
// distance and as a geodesic distance, each summarized by the mean, the median, the 90th
// percentile and the share of source vertices whose error is within 0.025, 0.05, 0.1 and 0.25.
//
// The geodesic distance is an EDGE-PATH distance: a shortest path along the target's edges from
// the true image to the mapped point (Dijkstra's algorithm over the edge graph, with straight
// segments inside the two end triangles). Edge paths zigzag, so they overestimate the true
// geodesic distance: by a few percent over long distances on a well-shaped triangulation (6%
// between antipodes of a 2562-vertex icosphere, up to 8% on a regular grid), more over a few
// edges (10% over about 8 edges of the icosphere), and they are never shorter than the
// Euclidean distance. Compare figures measured with the same triangulation.
//
// Each query is a search from the true image q towards the mapped point p:
// - q a target vertex: the search starts there at distance 0; q inside a triangle: its three
//   vertices start at their straight-line distances |v - q|;
// - the result is min over the three vertices v of p's triangle of dist(v) + |v - p|, where
//   dist is the edge-path distance from q; the search ends as soon as no vertex still in the
//   queue can improve on that minimum, i.e. at the latest when p's three vertices are settled;
// - if p and q lie in the same triangle, or their triangles (or q, a vertex) share a vertex,
//   the straight segment |p - q| is used. (So a true image given as a point of a triangle may
//   score a little lower than the same point given as a vertex: for a vertex, only a mapped
//   triangle that holds the vertex counts.)
// The search is an A* search: vertices are taken in the order of dist(v) + |v - p|, a lower
// bound of the length of any path to p through v (edges are straight segments, so the bound is
// consistent). It returns exactly what plain Dijkstra with the same stopping rule returns, after
// settling far fewer vertices (the ball around q shrinks to an ellipsoid-like region around the
// segment from q to p). Each thread keeps its own buffers, reset through a list of the vertices
// it touched, so a query costs only what it explores.
#ifndef mobius_CorrespondenceScore_h
#define mobius_CorrespondenceScore_h

#include "MeshTypes.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace mobius
{
/// A point on a triangle mesh: row `Triangle` of the triangle array and barycentric weights
/// (w0, w1, w2) of that row's vertices in the order the row lists them; the point is
/// w0 a + w1 b + w2 c. Weights are used as given (not clamped or renormalized).
struct SurfacePoint
{
  Index Triangle = -1;
  Eigen::Vector3d Barycentric = Eigen::Vector3d::Zero();
};

/// The error thresholds (in units of sqrt(target area)) whose shares are reported.
constexpr std::array<double, 4> CorrespondenceErrorThresholds = { 0.025, 0.05, 0.1, 0.25 };

/// Statistics of a set of errors (NaN entries, i.e. vertices that were not scored, are left
/// out). Quantiles interpolate linearly between order statistics (position q (n - 1) in the
/// sorted errors, as numpy's default), so the median of an even count is the mean of the two
/// middle values.
struct CorrespondenceErrorSummary
{
  Index Count = 0;       ///< errors summarized
  Index Unreachable = 0; ///< infinite errors (true image and mapped point in different components)
  double Mean = 0.0;     ///< infinite if any error is
  double Median = 0.0;
  double Percentile90 = 0.0;
  /// Share in [0, 1] of the errors <= CorrespondenceErrorThresholds[k].
  std::array<double, 4> Within = { 0.0, 0.0, 0.0, 0.0 };
};

/// Summarizes `errors` (see CorrespondenceErrorSummary); all zeros for no finite-or-infinite
/// entry.
CorrespondenceErrorSummary SummarizeCorrespondenceErrors(const Vector& errors);

/// Edge-path geodesic distances between points of one triangle mesh (see the file comment).
class EdgePathGeodesics
{
public:
  /// Per-thread search state: distances, a heap and the list of touched vertices. Sized on
  /// first use and then reused; reset costs O(touched vertices) per query.
  class Workspace
  {
  public:
    /// Vertices whose distance was finalized by the last query (a measure of its cost).
    Index GetLastSettledCount() const { return this->LastSettled; }

  private:
    friend class EdgePathGeodesics;
    /// Key = distance + heuristic (the order); the distance it was pushed with, to recognize
    /// stale entries.
    struct HeapEntry
    {
      double Key;
      double Distance;
      std::int32_t Vertex;
    };
    std::vector<double> Distance;
    std::vector<std::int32_t> Touched;
    std::vector<HeapEntry> Heap;
    /// The vertex each touched vertex was reached from (-1 for a seed), for LastPath.
    std::vector<std::int32_t> Parent;
    bool LastSearched = false; // false: the last query took the straight segment
    Index LastSettled = 0;
  };

  /// Builds the edge graph (O(triangles log)). Returns false with a message for an empty
  /// mesh, an index out of range, a non-finite coordinate, or a mesh too large for 32-bit
  /// vertex indices.
  bool Build(const Points& points, const Triangles& triangles, std::string& error);

  /// Edge-path distance from `from` to `to`; +infinity if no edge path joins them, NaN if a
  /// triangle or vertex index is out of range or a weight is not finite. Thread-safe with one
  /// Workspace per thread.
  double Distance(const SurfacePoint& from, const SurfacePoint& to, Workspace& workspace) const;
  /// From a vertex of the mesh.
  double Distance(Index fromVertex, const SurfacePoint& to, Workspace& workspace) const;
  /// Between two vertices of the mesh: the shortest edge path (0 for one vertex; +infinity
  /// for a vertex in no triangle, or in another component; NaN for an index out of range).
  double Distance(Index fromVertex, Index toVertex, Workspace& workspace) const;

  /// A* (true, the default) or plain Dijkstra (false) with the same stopping rule; both give
  /// the same distances, Dijkstra settles more vertices. For tests and measurements.
  void SetUseAStar(bool useAStar) { this->UseAStar = useAStar; }

  /// The vertices of the edge path the last query to vertex `toVertex` found, from its start
  /// to toVertex. False if the last query searched nothing (its ends shared a triangle, and
  /// the straight segment was the answer) or did not reach toVertex.
  bool LastPath(Index toVertex, const Workspace& workspace, std::vector<Index>& path) const;

  const Points& GetPoints() const { return this->Points_; }
  const Triangles& GetTriangles() const { return this->Triangles_; }

  /// Landmarks for the A* bound (ALT, Goldberg & Harrelson 2005): `count` vertices chosen by
  /// farthest-point sampling along edge paths, with their edge-path distances to every
  /// vertex (count searches over the whole mesh, kept: count x vertices doubles). A query
  /// then also bounds the rest of a path from v by max over landmarks l of
  /// |d(l, goal) - d(l, v)| (the triangle inequality), which on a body is far tighter than the
  /// straight line for long paths (hand to hand): such a query settles a corridor instead of
  /// most of the mesh. Distances are unchanged. Call after Build; 0 removes them.
  void BuildLandmarks(int count);

  /// The point a SurfacePoint stands for.
  Eigen::Vector3d Position(const SurfacePoint& point) const;

  Index GetNumberOfPoints() const { return static_cast<Index>(this->Points_.rows()); }
  Index GetNumberOfTriangles() const { return static_cast<Index>(this->Triangles_.rows()); }
  /// Sum of the triangle areas.
  double GetSurfaceArea() const { return this->SurfaceArea; }

private:
  bool IsValid(const SurfacePoint& point) const
  {
    return point.Triangle >= 0 && point.Triangle < this->Triangles_.rows() &&
      point.Barycentric.allFinite();
  }

  /// Edge-path distances from the seeds to every vertex (a full Dijkstra search).
  void SearchAll(const std::array<std::int32_t, 3>& seeds, int seedCount,
    std::vector<double>& distance) const;

  /// Seeds: up to three vertices with their starting distances.
  double Search(const std::array<std::int32_t, 3>& seeds, const std::array<double, 3>& seedDistance,
    int seedCount, const SurfacePoint& to, Workspace& workspace) const;

  Points Points_;
  Triangles Triangles_;
  std::vector<std::int32_t> FirstNeighbor; // CSR offsets, size points + 1
  std::vector<std::int32_t> Neighbor;
  std::vector<double> EdgeLength;
  /// Landmark l's distance to vertex v at [v * Landmarks + l] (BuildLandmarks): a vertex's
  /// distances side by side, one cache line for 8 landmarks.
  std::vector<double> LandmarkDistance;
  int Landmarks = 0;
  /// Per vertex, a triangle that holds it and the vertex's place in it (-1: in none).
  std::vector<SurfacePoint> VertexCorner;
  double SurfaceArea = 0.0;
  bool UseAStar = true;
};

struct CorrespondenceScoreOptions
{
  /// Threads for the geodesic queries; 0: one per core.
  int NumberOfThreads = 0;
  /// At most this many geodesic queries (0: every source vertex). When the cap is below the
  /// number of source vertices, vertices floor(k n / cap), k = 0 .. cap - 1, are scored: an
  /// even, deterministic subsample. Euclidean errors are always computed for every vertex.
  Index MaximumGeodesicQueries = 0;
  /// Skip the geodesic errors altogether (they are then all NaN and the summary empty).
  bool ComputeGeodesic = true;
};

struct CorrespondenceScore
{
  double TargetArea = 0.0;
  /// sqrt(TargetArea): the unit of every error below.
  double Scale = 0.0;
  /// Per source vertex: |mapped - true| / Scale.
  Vector Euclidean;
  /// Per source vertex: edge-path geodesic distance / Scale; NaN for vertices left out by
  /// MaximumGeodesicQueries, +infinity where no edge path exists.
  Vector Geodesic;
  CorrespondenceErrorSummary EuclideanSummary;
  CorrespondenceErrorSummary GeodesicSummary;
  /// Vertices the geodesic searches settled, summed over the queries (a measure of cost).
  Index SettledVertices = 0;
};

/// Scores a map against the truth on the target mesh (points + triangles). mapped[i] is where
/// the map sends source vertex i; truth[i] its true image. Both vectors must have the same
/// size. Returns false with a message naming the first offending source vertex for a bad
/// triangle index or a non-finite weight, or a message about the target mesh.
bool ScoreCorrespondence(const Points& targetPoints, const Triangles& targetTriangles,
  const std::vector<SurfacePoint>& mapped, const std::vector<SurfacePoint>& truth,
  const CorrespondenceScoreOptions& options, CorrespondenceScore& score, std::string& error);

/// The same with each true image a target vertex (truth[i] in [0, target points)).
bool ScoreCorrespondence(const Points& targetPoints, const Triangles& targetTriangles,
  const std::vector<SurfacePoint>& mapped, const std::vector<Index>& truth,
  const CorrespondenceScoreOptions& options, CorrespondenceScore& score, std::string& error);
}

#endif
