#include "CorrespondenceScore.h"

#include "ParallelFor.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace mobius
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();

double Quantile(const std::vector<double>& sorted, double q)
{
  const double position = q * static_cast<double>(sorted.size() - 1);
  const size_t below = static_cast<size_t>(std::floor(position));
  const double fraction = position - static_cast<double>(below);
  if (fraction == 0.0 || below + 1 >= sorted.size())
  {
    return sorted[below];
  }
  const double a = sorted[below], b = sorted[below + 1];
  if (std::isinf(a) || std::isinf(b))
  {
    return Infinity;
  }
  return a + fraction * (b - a);
}

bool SharesVertex(const Triangles& triangles, Index a, Index b)
{
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      if (triangles(a, i) == triangles(b, j))
      {
        return true;
      }
    }
  }
  return false;
}

bool CheckSurfacePoint(const SurfacePoint& point, Index triangles, const char* what, size_t vertex,
  std::string& error)
{
  if (point.Triangle < 0 || point.Triangle >= triangles)
  {
    std::ostringstream message;
    message << "source vertex " << vertex << ": " << what << " triangle " << point.Triangle
            << " is out of range (the target has " << triangles << " triangles)";
    error = message.str();
    return false;
  }
  if (!point.Barycentric.allFinite())
  {
    std::ostringstream message;
    message << "source vertex " << vertex << ": " << what << " barycentric weights are not finite";
    error = message.str();
    return false;
  }
  return true;
}

/// Everything but the true images' kind: `truePosition(i)` and `geodesic(i, workspace)`.
template <typename TruePosition, typename Geodesic>
bool Score(const EdgePathGeodesics& geodesics, const std::vector<SurfacePoint>& mapped,
  const CorrespondenceScoreOptions& options, TruePosition&& truePosition, Geodesic&& geodesic,
  CorrespondenceScore& score, std::string& error)
{
  score = CorrespondenceScore();
  score.TargetArea = geodesics.GetSurfaceArea();
  score.Scale = std::sqrt(score.TargetArea);
  if (!(score.Scale > 0.0) || !std::isfinite(score.Scale))
  {
    error = "the target has no surface area";
    return false;
  }
  const Index count = static_cast<Index>(mapped.size());
  if (count > std::numeric_limits<int>::max())
  {
    error = "too many source vertices";
    return false;
  }
  score.Euclidean.resize(count);
  for (Index i = 0; i < count; ++i)
  {
    score.Euclidean[i] =
      (geodesics.Position(mapped[i]) - truePosition(i)).norm() / score.Scale;
  }
  score.EuclideanSummary = SummarizeCorrespondenceErrors(score.Euclidean);

  score.Geodesic = Vector::Constant(count, std::numeric_limits<double>::quiet_NaN());
  if (!options.ComputeGeodesic || count == 0)
  {
    return true;
  }
  Index queries = count;
  if (options.MaximumGeodesicQueries > 0 && options.MaximumGeodesicQueries < count)
  {
    queries = options.MaximumGeodesicQueries;
  }
  const int threads = std::min<int>(ResolveThreadCount(options.NumberOfThreads), queries);
  std::vector<EdgePathGeodesics::Workspace> workspaces(threads);
  std::vector<Index> settled(threads, 0);
  ParallelFor(static_cast<int>(queries), threads, [&](int k, int thread) {
    // Even subsample: floor(k n / queries), exact in 128-bit-free arithmetic for n < 2^31.
    const Index i = queries == count ? k : (static_cast<Index>(k) * count) / queries;
    score.Geodesic[i] = geodesic(i, workspaces[thread]) / score.Scale;
    settled[thread] += workspaces[thread].GetLastSettledCount();
  });
  for (Index s : settled)
  {
    score.SettledVertices += s;
  }
  score.GeodesicSummary = SummarizeCorrespondenceErrors(score.Geodesic);
  return true;
}
}

//------------------------------------------------------------------------------
CorrespondenceErrorSummary SummarizeCorrespondenceErrors(const Vector& errors)
{
  CorrespondenceErrorSummary summary;
  std::vector<double> sorted;
  sorted.reserve(errors.size());
  for (Index i = 0; i < errors.size(); ++i)
  {
    if (!std::isnan(errors[i]))
    {
      sorted.push_back(errors[i]);
    }
  }
  if (sorted.empty())
  {
    return summary;
  }
  std::sort(sorted.begin(), sorted.end());
  summary.Count = static_cast<Index>(sorted.size());
  double sum = 0.0;
  for (double e : sorted)
  {
    sum += e;
    summary.Unreachable += std::isinf(e) ? 1 : 0;
  }
  summary.Mean = sum / static_cast<double>(sorted.size());
  summary.Median = Quantile(sorted, 0.5);
  summary.Percentile90 = Quantile(sorted, 0.9);
  for (size_t k = 0; k < CorrespondenceErrorThresholds.size(); ++k)
  {
    const auto end =
      std::upper_bound(sorted.begin(), sorted.end(), CorrespondenceErrorThresholds[k]);
    summary.Within[k] =
      static_cast<double>(end - sorted.begin()) / static_cast<double>(sorted.size());
  }
  return summary;
}

//------------------------------------------------------------------------------
bool EdgePathGeodesics::Build(const Points& points, const Triangles& triangles, std::string& error)
{
  this->FirstNeighbor.clear();
  this->Neighbor.clear();
  this->VertexCorner.clear();
  this->LandmarkDistance.clear();
  this->Landmarks = 0;
  this->EdgeLength.clear();
  this->SurfaceArea = 0.0;
  this->Points_.resize(0, 3);
  this->Triangles_.resize(0, 3);
  const Index n = points.rows();
  if (n == 0 || triangles.rows() == 0)
  {
    error = "the target mesh is empty";
    return false;
  }
  if (n >= std::numeric_limits<std::int32_t>::max() ||
    3 * triangles.rows() >= std::numeric_limits<std::int32_t>::max() / 2)
  {
    error = "the target mesh is too large (more than 2^31 vertices or edges)";
    return false;
  }
  if (!points.allFinite())
  {
    error = "the target mesh has a point with a non-finite coordinate";
    return false;
  }
  std::vector<std::pair<std::int32_t, std::int32_t>> edges;
  edges.reserve(6 * triangles.rows());
  double area = 0.0;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (triangles(t, k) < 0 || triangles(t, k) >= n)
      {
        std::ostringstream message;
        message << "target triangle " << t << " has the vertex index " << triangles(t, k)
                << ", out of range (the target has " << n << " points)";
        error = message.str();
        return false;
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      const auto a = static_cast<std::int32_t>(triangles(t, k));
      const auto b = static_cast<std::int32_t>(triangles(t, (k + 1) % 3));
      if (a != b)
      {
        edges.emplace_back(a, b);
        edges.emplace_back(b, a);
      }
    }
    const Eigen::Vector3d a = points.row(triangles(t, 0)), b = points.row(triangles(t, 1)),
                          c = points.row(triangles(t, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  this->FirstNeighbor.assign(n + 1, 0);
  this->Neighbor.resize(edges.size());
  this->EdgeLength.resize(edges.size());
  for (size_t e = 0; e < edges.size(); ++e)
  {
    ++this->FirstNeighbor[edges[e].first + 1];
    this->Neighbor[e] = edges[e].second;
    this->EdgeLength[e] = (points.row(edges[e].first) - points.row(edges[e].second)).norm();
  }
  for (Index i = 0; i < n; ++i)
  {
    this->FirstNeighbor[i + 1] += this->FirstNeighbor[i];
  }
  this->VertexCorner.assign(n, SurfacePoint());
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->VertexCorner[triangles(t, k)].Triangle = t;
      this->VertexCorner[triangles(t, k)].Barycentric = Eigen::Vector3d::Unit(k);
    }
  }
  this->Points_ = points;
  this->Triangles_ = triangles;
  this->SurfaceArea = area;
  return true;
}

//------------------------------------------------------------------------------
Eigen::Vector3d EdgePathGeodesics::Position(const SurfacePoint& point) const
{
  const auto t = point.Triangle;
  return point.Barycentric[0] * this->Points_.row(this->Triangles_(t, 0)).transpose() +
    point.Barycentric[1] * this->Points_.row(this->Triangles_(t, 1)).transpose() +
    point.Barycentric[2] * this->Points_.row(this->Triangles_(t, 2)).transpose();
}

//------------------------------------------------------------------------------
double EdgePathGeodesics::Distance(
  const SurfacePoint& from, const SurfacePoint& to, Workspace& workspace) const
{
  workspace.LastSettled = 0;
  workspace.LastSearched = false;
  if (!this->IsValid(from) || !this->IsValid(to))
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const Eigen::Vector3d q = this->Position(from);
  if (from.Triangle == to.Triangle || SharesVertex(this->Triangles_, from.Triangle, to.Triangle))
  {
    return (this->Position(to) - q).norm();
  }
  std::array<std::int32_t, 3> seeds;
  std::array<double, 3> distances;
  for (int k = 0; k < 3; ++k)
  {
    seeds[k] = static_cast<std::int32_t>(this->Triangles_(from.Triangle, k));
    distances[k] = (this->Points_.row(seeds[k]).transpose() - q).norm();
  }
  return this->Search(seeds, distances, 3, to, workspace);
}

//------------------------------------------------------------------------------
double EdgePathGeodesics::Distance(
  Index fromVertex, const SurfacePoint& to, Workspace& workspace) const
{
  workspace.LastSettled = 0;
  workspace.LastSearched = false;
  if (fromVertex < 0 || fromVertex >= this->Points_.rows() || !this->IsValid(to))
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  for (int k = 0; k < 3; ++k)
  {
    if (this->Triangles_(to.Triangle, k) == fromVertex)
    {
      return (this->Position(to) - this->Points_.row(fromVertex).transpose()).norm();
    }
  }
  return this->Search({ static_cast<std::int32_t>(fromVertex), 0, 0 }, { 0.0, 0.0, 0.0 }, 1, to,
    workspace);
}

//------------------------------------------------------------------------------
double EdgePathGeodesics::Distance(Index fromVertex, Index toVertex, Workspace& workspace) const
{
  workspace.LastSettled = 0;
  workspace.LastSearched = false;
  const Index n = this->Points_.rows();
  if (fromVertex < 0 || fromVertex >= n || toVertex < 0 || toVertex >= n)
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  if (fromVertex == toVertex)
  {
    return 0.0;
  }
  const SurfacePoint& to = this->VertexCorner[toVertex];
  if (to.Triangle < 0 || this->VertexCorner[fromVertex].Triangle < 0)
  {
    return Infinity;
  }
  return this->Distance(fromVertex, to, workspace);
}

//------------------------------------------------------------------------------
bool EdgePathGeodesics::LastPath(
  Index toVertex, const Workspace& workspace, std::vector<Index>& path) const
{
  path.clear();
  if (!workspace.LastSearched || toVertex < 0 ||
    toVertex >= static_cast<Index>(workspace.Parent.size()))
  {
    return false;
  }
  // The chain of parents set by the last search (a vertex it never reached has none: the
  // chain from toVertex must end at a seed within as many steps as there are vertices).
  for (Index v = toVertex; v >= 0; v = workspace.Parent[v])
  {
    path.push_back(v);
    if (static_cast<Index>(path.size()) > this->Points_.rows())
    {
      path.clear();
      return false;
    }
  }
  std::reverse(path.begin(), path.end());
  return true;
}

//------------------------------------------------------------------------------
void EdgePathGeodesics::SearchAll(const std::array<std::int32_t, 3>& seeds, int seedCount,
  std::vector<double>& distance) const
{
  using Entry = std::pair<double, std::int32_t>;
  std::vector<Entry> heap;
  const auto greater = [](const Entry& a, const Entry& b) { return a.first > b.first; };
  distance.assign(this->Points_.rows(), Infinity);
  for (int s = 0; s < seedCount; ++s)
  {
    distance[seeds[s]] = 0.0;
    heap.emplace_back(0.0, seeds[s]);
  }
  std::make_heap(heap.begin(), heap.end(), greater);
  while (!heap.empty())
  {
    std::pop_heap(heap.begin(), heap.end(), greater);
    const auto [g, v] = heap.back();
    heap.pop_back();
    if (g > distance[v])
    {
      continue;
    }
    for (std::int32_t e = this->FirstNeighbor[v]; e < this->FirstNeighbor[v + 1]; ++e)
    {
      const std::int32_t u = this->Neighbor[e];
      if (g + this->EdgeLength[e] < distance[u])
      {
        distance[u] = g + this->EdgeLength[e];
        heap.emplace_back(distance[u], u);
        std::push_heap(heap.begin(), heap.end(), greater);
      }
    }
  }
}

//------------------------------------------------------------------------------
void EdgePathGeodesics::BuildLandmarks(int count)
{
  const Index n = this->Points_.rows();
  this->LandmarkDistance.clear();
  this->Landmarks = 0;
  if (count <= 0 || n == 0)
  {
    return;
  }
  count = static_cast<int>(std::min<Index>(count, n));
  this->LandmarkDistance.resize(static_cast<size_t>(count) * n);
  // Farthest-point sampling: the first landmark is the vertex farthest from vertex 0, each
  // next one the vertex farthest from those chosen (a vertex another component holds is
  // infinitely far, so every component gets one while landmarks last).
  std::vector<double> distance, nearest(n, Infinity);
  this->SearchAll({ 0, 0, 0 }, 1, distance);
  auto farthest = [&](const std::vector<double>& from) {
    std::int32_t best = 0;
    for (Index v = 1; v < n; ++v)
    {
      best = from[v] > from[best] ? static_cast<std::int32_t>(v) : best;
    }
    return best;
  };
  std::int32_t next = farthest(distance);
  for (int l = 0; l < count; ++l)
  {
    this->SearchAll({ next, 0, 0 }, 1, distance);
    for (Index v = 0; v < n; ++v)
    {
      this->LandmarkDistance[v * count + l] = distance[v];
      nearest[v] = std::min(nearest[v], distance[v]);
    }
    next = farthest(nearest);
  }
  this->Landmarks = count;
}

//------------------------------------------------------------------------------
double EdgePathGeodesics::Search(const std::array<std::int32_t, 3>& seeds,
  const std::array<double, 3>& seedDistance, int seedCount, const SurfacePoint& to,
  Workspace& workspace) const
{
  const Index n = this->Points_.rows();
  if (static_cast<Index>(workspace.Distance.size()) != n)
  {
    workspace.Distance.assign(n, Infinity);
    workspace.Parent.assign(n, -1);
    workspace.Touched.clear();
    workspace.Heap.clear();
  }
  workspace.LastSearched = true;
  std::vector<std::int32_t>& parent = workspace.Parent;
  std::vector<double>& distance = workspace.Distance;
  std::vector<std::int32_t>& touched = workspace.Touched;
  std::vector<Workspace::HeapEntry>& heap = workspace.Heap;

  const Eigen::Vector3d p = this->Position(to);
  std::array<std::int32_t, 3> goal;
  std::array<double, 3> goalOffset;
  std::array<bool, 3> goalSettled = { false, false, false };
  int goalsLeft = 0;
  for (int k = 0; k < 3; ++k)
  {
    goal[k] = static_cast<std::int32_t>(this->Triangles_(to.Triangle, k));
    goalOffset[k] = (this->Points_.row(goal[k]).transpose() - p).norm();
    bool repeated = false;
    for (int j = 0; j < k; ++j)
    {
      repeated = repeated || goal[j] == goal[k];
    }
    goalSettled[k] = repeated; // a repeated vertex counts once
    goalsLeft += repeated ? 0 : 1;
  }
  const bool aStar = this->UseAStar;
  // With landmarks, also min over the goal corners k of (max over landmarks l of
  // |d(l, k) - d(l, v)|) + |k - p|: a lower bound of the rest of any path through v (the
  // search's distance to p is min over k of d(v, k) + |k - p|); the max of two consistent
  // bounds, and the min over corners of consistent bounds, are consistent.
  const int landmarks = aStar ? this->Landmarks : 0;
  const double* landmarkDistance = this->LandmarkDistance.data();
  // Corners by increasing offset: a corner whose offset alone reaches the bound so far
  // cannot lower it (for a goal at a vertex, only that vertex is looked at).
  std::array<int, 3> byOffset = { 0, 1, 2 };
  std::sort(byOffset.begin(), byOffset.end(),
    [&](int a, int b) { return goalOffset[a] < goalOffset[b]; });
  auto landmarkBound = [&](std::int32_t v) {
    const double* atV = landmarkDistance + static_cast<size_t>(v) * landmarks;
    double bound = Infinity;
    for (int k : byOffset)
    {
      if (goalOffset[k] >= bound)
      {
        break;
      }
      const double* atGoal = landmarkDistance + static_cast<size_t>(goal[k]) * landmarks;
      double largest = 0.0;
      for (int l = 0; l < landmarks; ++l)
      {
        const double difference = std::abs(atGoal[l] - atV[l]);
        largest = std::isfinite(difference) ? std::max(largest, difference) : largest;
      }
      bound = std::min(bound, largest + goalOffset[k]);
    }
    return bound;
  };
  auto heuristic = [&](std::int32_t v) {
    if (!aStar)
    {
      return 0.0;
    }
    const double straight = (this->Points_.row(v).transpose() - p).norm();
    return landmarks ? std::max(straight, landmarkBound(v)) : straight;
  };
  const auto greater = [](const Workspace::HeapEntry& a, const Workspace::HeapEntry& b) {
    return a.Key > b.Key;
  };

  for (int s = 0; s < seedCount; ++s)
  {
    const std::int32_t v = seeds[s];
    if (seedDistance[s] < distance[v])
    {
      if (distance[v] == Infinity)
      {
        touched.push_back(v);
      }
      distance[v] = seedDistance[s];
      parent[v] = -1;
      heap.push_back({ seedDistance[s] + heuristic(v), seedDistance[s], v });
      std::push_heap(heap.begin(), heap.end(), greater);
    }
  }

  double best = Infinity;
  Index settled = 0;
  while (!heap.empty())
  {
    std::pop_heap(heap.begin(), heap.end(), greater);
    const Workspace::HeapEntry entry = heap.back();
    heap.pop_back();
    if (entry.Key >= best)
    {
      break; // no path through what is left can be shorter
    }
    if (entry.Distance > distance[entry.Vertex])
    {
      continue; // stale
    }
    ++settled;
    const std::int32_t v = entry.Vertex;
    const double g = entry.Distance;
    for (int k = 0; k < 3; ++k)
    {
      if (goal[k] == v)
      {
        best = std::min(best, g + goalOffset[k]);
        if (!goalSettled[k])
        {
          goalSettled[k] = true;
          --goalsLeft;
        }
      }
    }
    if (goalsLeft == 0)
    {
      break; // the three vertices of the mapped point's triangle are final
    }
    for (std::int32_t e = this->FirstNeighbor[v]; e < this->FirstNeighbor[v + 1]; ++e)
    {
      const std::int32_t u = this->Neighbor[e];
      const double candidate = g + this->EdgeLength[e];
      if (candidate < distance[u])
      {
        if (distance[u] == Infinity)
        {
          touched.push_back(u);
        }
        distance[u] = candidate;
        parent[u] = v;
        const double key = candidate + heuristic(u);
        if (key < best)
        {
          heap.push_back({ key, candidate, u });
          std::push_heap(heap.begin(), heap.end(), greater);
        }
      }
    }
  }

  for (std::int32_t v : touched)
  {
    distance[v] = Infinity;
  }
  touched.clear();
  heap.clear();
  workspace.LastSettled = settled;
  return best;
}

//------------------------------------------------------------------------------
bool ScoreCorrespondence(const Points& targetPoints, const Triangles& targetTriangles,
  const std::vector<SurfacePoint>& mapped, const std::vector<SurfacePoint>& truth,
  const CorrespondenceScoreOptions& options, CorrespondenceScore& score, std::string& error)
{
  EdgePathGeodesics geodesics;
  if (!geodesics.Build(targetPoints, targetTriangles, error))
  {
    return false;
  }
  if (mapped.size() != truth.size())
  {
    error = "the map has " + std::to_string(mapped.size()) + " source vertices, the truth " +
      std::to_string(truth.size());
    return false;
  }
  for (size_t i = 0; i < mapped.size(); ++i)
  {
    if (!CheckSurfacePoint(mapped[i], targetTriangles.rows(), "mapped", i, error) ||
      !CheckSurfacePoint(truth[i], targetTriangles.rows(), "true", i, error))
    {
      return false;
    }
  }
  return Score(
    geodesics, mapped, options, [&](Index i) { return geodesics.Position(truth[i]); },
    [&](Index i, EdgePathGeodesics::Workspace& workspace) {
      return geodesics.Distance(truth[i], mapped[i], workspace);
    },
    score, error);
}

//------------------------------------------------------------------------------
bool ScoreCorrespondence(const Points& targetPoints, const Triangles& targetTriangles,
  const std::vector<SurfacePoint>& mapped, const std::vector<Index>& truth,
  const CorrespondenceScoreOptions& options, CorrespondenceScore& score, std::string& error)
{
  EdgePathGeodesics geodesics;
  if (!geodesics.Build(targetPoints, targetTriangles, error))
  {
    return false;
  }
  if (mapped.size() != truth.size())
  {
    error = "the map has " + std::to_string(mapped.size()) + " source vertices, the truth " +
      std::to_string(truth.size());
    return false;
  }
  for (size_t i = 0; i < mapped.size(); ++i)
  {
    if (!CheckSurfacePoint(mapped[i], targetTriangles.rows(), "mapped", i, error))
    {
      return false;
    }
    if (truth[i] < 0 || truth[i] >= targetPoints.rows())
    {
      std::ostringstream message;
      message << "source vertex " << i << ": true image " << truth[i]
              << " is out of range (the target has " << targetPoints.rows() << " vertices)";
      error = message.str();
      return false;
    }
  }
  return Score(
    geodesics, mapped, options,
    [&](Index i) -> Eigen::Vector3d { return targetPoints.row(truth[i]).transpose(); },
    [&](Index i, EdgePathGeodesics::Workspace& workspace) {
      return geodesics.Distance(truth[i], mapped[i], workspace);
    },
    score, error);
}
}
