#include "SphericalPointLocator.h"

#include "ParallelFor.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <queue>
#include <sstream>
#include <utility>

namespace mobius
{
namespace
{
/// Triangles per leaf: few enough that a leaf is a handful of cheap tests, many enough that the
/// tree (and its traversal) stays shallow.
constexpr std::int32_t LeafSize = 4;

/// A chord radius that no two unit vectors exceed: the cap of the whole sphere.
constexpr double WholeSphere = 3.0;

/// A cap {x : |x - C| <= R} is bounded by the plane x . C >= 1 - R^2 / 2. Only while that plane
/// does not pass behind the origin (R <= sqrt 2, at most a hemisphere) does a cap that holds the
/// three vertices of a triangle also hold the whole spherical triangle: a positive combination
/// x of the vertices has x . C >= (1 - R^2/2) * (sum of weights) >= (1 - R^2/2) |x|.
constexpr double LargestTriangleSafeChord = 1.4142135623730950; // slightly below sqrt(2)

/// Widens a computed chord radius to cover round-off in |p - C| (unit vectors carry ~1e-16
/// absolute error per component), so that a point on the boundary of a triangle is never culled.
double Pad(double chordRadius)
{
  if (chordRadius > LargestTriangleSafeChord)
  {
    return WholeSphere;
  }
  return chordRadius * (1.0 + 1e-12) + 1e-15;
}

double ChordToAngle(double chord)
{
  return 2.0 * std::asin(std::min(1.0, 0.5 * chord));
}

/// Nearest point to p on the great-circle arc from u to w (the shorter one), returned as its
/// chord distance to p and its weights (s, t) on u and w: the point is (s u + t w) normalized.
double NearestOnArc(const Eigen::Vector3d& p, const Eigen::Vector3d& u, const Eigen::Vector3d& w,
  double& s, double& t)
{
  double best = (p - u).norm();
  s = 1.0;
  t = 0.0;
  const double toW = (p - w).norm();
  if (toW < best)
  {
    best = toW;
    s = 0.0;
    t = 1.0;
  }
  // u x (w - u) equals u x w but keeps its accuracy for very short edges.
  const Eigen::Vector3d normal = u.cross(w - u);
  const double normalSquared = normal.squaredNorm();
  if (!(normalSquared > 0.0))
  {
    return best; // u and w coincide or are antipodal: no unique arc, the ends will do
  }
  const Eigen::Vector3d inPlane = p - (p.dot(normal) / normalSquared) * normal;
  const double inPlaneNorm = inPlane.norm();
  if (!(inPlaneNorm > 0.0))
  {
    return best; // p is a pole of the arc's great circle: every point of the arc is as near
  }
  const Eigen::Vector3d foot = inPlane / inPlaneNorm;
  // foot = su u + tw w by Cramer's rule in the plane of the arc; it lies on the arc when both
  // weights are non-negative.
  const double su = foot.cross(w).dot(normal) / normalSquared;
  const double tw = u.cross(foot).dot(normal) / normalSquared;
  if (su >= 0.0 && tw >= 0.0 && su + tw > 0.0)
  {
    const double distance = (p - foot).norm();
    if (distance < best)
    {
      best = distance;
      s = su / (su + tw);
      t = tw / (su + tw);
    }
  }
  return best;
}
}

/// What the top-down build sorts: one triangle's bounding cap.
struct SphericalPointLocator::Primitive
{
  Eigen::Vector3d Center;
  double ChordRadius;
  std::int32_t Slot; // index into the unsorted LeafTriangles
};

bool SphericalPointLocator::Build(
  const Points& spherePoints, const Triangles& triangles, std::string& error)
{
  this->SpherePoints.resize(0, 3);
  this->Nodes.clear();
  this->LeafTriangles.clear();
  this->Depth = 0;
  error.clear();

  const Index numberOfPoints = spherePoints.rows();
  const Index numberOfTriangles = triangles.rows();
  if (numberOfPoints == 0 || numberOfTriangles == 0)
  {
    error = "SphericalPointLocator: the spherical mesh is empty (" +
      std::to_string(numberOfPoints) + " points, " + std::to_string(numberOfTriangles) +
      " triangles).";
    return false;
  }
  if (numberOfTriangles >= std::numeric_limits<std::int32_t>::max() / 2)
  {
    error = "SphericalPointLocator: too many triangles (" + std::to_string(numberOfTriangles) +
      ").";
    return false;
  }
  Points normalized(numberOfPoints, 3);
  for (Index i = 0; i < numberOfPoints; ++i)
  {
    const Eigen::Vector3d x = spherePoints.row(i).transpose();
    if (!x.allFinite())
    {
      error = "SphericalPointLocator: point " + std::to_string(i) +
        " has a non-finite coordinate.";
      return false;
    }
    const double norm = x.norm();
    if (!(std::abs(norm - 1.0) <= 1e-6))
    {
      std::ostringstream message;
      message.precision(17);
      message << "SphericalPointLocator: point " << i << " is not on the unit sphere (|x| = "
              << norm << ", tolerance 1e-6).";
      error = message.str();
      return false;
    }
    normalized.row(i) = (x / norm).transpose();
  }

  std::vector<LeafTriangle> unsorted(static_cast<std::size_t>(numberOfTriangles));
  std::vector<Primitive> primitives(unsorted.size());
  for (Index t = 0; t < numberOfTriangles; ++t)
  {
    LeafTriangle& triangle = unsorted[static_cast<std::size_t>(t)];
    for (int k = 0; k < 3; ++k)
    {
      const Index v = triangles(t, k);
      if (v < 0 || v >= numberOfPoints)
      {
        error = "SphericalPointLocator: triangle " + std::to_string(t) + " has vertex index " +
          std::to_string(v) + ", out of range [0, " + std::to_string(numberOfPoints) + ").";
        return false;
      }
      triangle.Vertices[static_cast<std::size_t>(k)] = v;
    }
    triangle.Id = t;
    const Eigen::Vector3d a = normalized.row(triangle.Vertices[0]).transpose();
    const Eigen::Vector3d b = normalized.row(triangle.Vertices[1]).transpose();
    const Eigen::Vector3d c = normalized.row(triangle.Vertices[2]).transpose();
    // det(a, b, c) = a . ((b - a) x (c - a)): accurate for tiny triangles, whose edge vectors
    // are nearly orthogonal to a.
    const double volume = a.dot((b - a).cross(c - a));
    triangle.Orientation = volume > 0.0 ? 1 : (volume < 0.0 ? -1 : 0);

    Primitive& primitive = primitives[static_cast<std::size_t>(t)];
    const Eigen::Vector3d sum = a + b + c;
    const double sumNorm = sum.norm();
    primitive.Center = sumNorm > 0.0 ? Eigen::Vector3d(sum / sumNorm) : a;
    primitive.ChordRadius = std::max({ (a - primitive.Center).norm(),
      (b - primitive.Center).norm(), (c - primitive.Center).norm() });
    primitive.Slot = static_cast<std::int32_t>(t);
  }

  this->SpherePoints = std::move(normalized);
  this->Nodes.reserve(static_cast<std::size_t>(2 * numberOfTriangles / (LeafSize / 2) + 1));
  this->Nodes.emplace_back();
  this->Depth = this->BuildNode(0, primitives, 0, static_cast<std::int32_t>(primitives.size()));

  // Store the triangles in leaf order, so a leaf's triangles are contiguous in memory.
  this->LeafTriangles.resize(unsorted.size());
  for (std::size_t i = 0; i < primitives.size(); ++i)
  {
    this->LeafTriangles[i] = unsorted[static_cast<std::size_t>(primitives[i].Slot)];
  }
  // A leaf's exact distance to its vertices is tighter than the triangle-inequality bound.
  for (Node& node : this->Nodes)
  {
    if (node.TriangleCount == 0)
    {
      continue;
    }
    double radius = 0.0;
    for (std::int32_t i = node.First; i < node.First + node.TriangleCount; ++i)
    {
      for (const Index v : this->LeafTriangles[static_cast<std::size_t>(i)].Vertices)
      {
        radius = std::max(radius, (this->SpherePoints.row(v).transpose() - node.Center).norm());
      }
    }
    node.ChordRadius = std::min(node.ChordRadius, Pad(radius));
  }
  return true;
}

int SphericalPointLocator::BuildNode(
  std::int32_t node, std::vector<Primitive>& primitives, std::int32_t begin, std::int32_t end)
{
  // Cap center: the normalized mean of the triangle centers. Radius: by the triangle inequality
  // of chord distances, no vertex is farther than |center_t - C| + radius_t.
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Vector3d lower = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d upper = -lower;
  for (std::int32_t i = begin; i < end; ++i)
  {
    const Eigen::Vector3d& center = primitives[static_cast<std::size_t>(i)].Center;
    sum += center;
    lower = lower.cwiseMin(center);
    upper = upper.cwiseMax(center);
  }
  const double sumNorm = sum.norm();
  Eigen::Vector3d center = primitives[static_cast<std::size_t>(begin)].Center;
  if (sumNorm > 1e-9 * (end - begin))
  {
    center = sum / sumNorm;
  }
  double radius = 0.0;
  for (std::int32_t i = begin; i < end; ++i)
  {
    const Primitive& primitive = primitives[static_cast<std::size_t>(i)];
    radius = std::max(radius, (primitive.Center - center).norm() + primitive.ChordRadius);
  }

  if (end - begin <= LeafSize)
  {
    Node& leaf = this->Nodes[static_cast<std::size_t>(node)];
    leaf.Center = center;
    leaf.ChordRadius = Pad(radius);
    leaf.First = begin;
    leaf.TriangleCount = end - begin;
    return 1;
  }

  {
    Node& inner = this->Nodes[static_cast<std::size_t>(node)];
    inner.Center = center;
    inner.ChordRadius = Pad(radius);
    inner.TriangleCount = 0;
    inner.First = static_cast<std::int32_t>(this->Nodes.size());
  }
  const std::int32_t firstChild = static_cast<std::int32_t>(this->Nodes.size());
  this->Nodes.emplace_back();
  this->Nodes.emplace_back();

  // Median split along the axis in which the triangle centers spread most: balanced, so the
  // depth is log2(n / LeafSize) however non-uniform the triangle sizes are.
  int axis = 0;
  (upper - lower).maxCoeff(&axis);
  const std::int32_t middle = begin + (end - begin) / 2;
  std::nth_element(primitives.begin() + begin, primitives.begin() + middle,
    primitives.begin() + end, [axis](const Primitive& x, const Primitive& y) {
      return x.Center[axis] < y.Center[axis];
    });
  const int left = this->BuildNode(firstChild, primitives, begin, middle);
  const int right = this->BuildNode(firstChild + 1, primitives, middle, end);
  return 1 + std::max(left, right);
}

bool SphericalPointLocator::Contains(
  const LeafTriangle& triangle, const Eigen::Vector3d& p, Eigen::Vector3d& barycentric) const
{
  if (triangle.Orientation == 0)
  {
    return false; // a degenerate triangle covers nothing; its neighbours cover its points
  }
  const Eigen::Vector3d toA = this->SpherePoints.row(triangle.Vertices[0]).transpose() - p;
  const Eigen::Vector3d toB = this->SpherePoints.row(triangle.Vertices[1]).transpose() - p;
  const Eigen::Vector3d toC = this->SpherePoints.row(triangle.Vertices[2]).transpose() - p;
  // det(p, b, c), det(a, p, c), det(a, b, p). Each is computed from the directed edge alone, so
  // the neighbour across an edge computes exactly its negative.
  const double alpha = p.dot(toB.cross(toC));
  const double beta = p.dot(toC.cross(toA));
  const double gamma = p.dot(toA.cross(toB));
  // p = (alpha a + beta b + gamma c) / det(a, b, c): p is in the cone of the triangle iff all
  // three have the sign of det(a, b, c). Checking that sign (not merely equal signs) rejects
  // the antipodal cone.
  if (triangle.Orientation > 0 ? (alpha < 0.0 || beta < 0.0 || gamma < 0.0)
                               : (alpha > 0.0 || beta > 0.0 || gamma > 0.0))
  {
    return false;
  }
  const double sum = alpha + beta + gamma;
  if (sum == 0.0)
  {
    return false;
  }
  barycentric = Eigen::Vector3d(alpha, beta, gamma) / sum;
  return true;
}

SphericalLocation SphericalPointLocator::Locate(const Eigen::Vector3d& query) const
{
  SphericalLocation location;
  const double norm = query.norm();
  if (this->Nodes.empty() || !std::isfinite(norm) || !(norm > 0.0))
  {
    return location;
  }
  const Eigen::Vector3d p = query / norm;

  // Depth-first search of every leaf whose cap holds p. The tree is balanced, so its depth is
  // about log2(n / 2); 64 levels of pending siblings are more than any mesh can need.
  std::int32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0)
  {
    const Node& node = this->Nodes[static_cast<std::size_t>(stack[--top])];
    if ((p - node.Center).squaredNorm() > node.ChordRadius * node.ChordRadius)
    {
      continue;
    }
    if (node.TriangleCount > 0)
    {
      for (std::int32_t i = node.First; i < node.First + node.TriangleCount; ++i)
      {
        const LeafTriangle& triangle = this->LeafTriangles[static_cast<std::size_t>(i)];
        if (this->Contains(triangle, p, location.Barycentric))
        {
          location.Triangle = triangle.Id;
          return location;
        }
      }
      continue;
    }
    stack[top++] = node.First + 1;
    stack[top++] = node.First;
  }
  return this->LocateNearest(p);
}

SphericalLocation SphericalPointLocator::LocateNearest(const Eigen::Vector3d& p) const
{
  // Best-first branch and bound: a node's cap is at chord distance >= |p - C| - R from p.
  using Entry = std::pair<double, std::int32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  queue.emplace(0.0, 0);
  double best = std::numeric_limits<double>::infinity();
  SphericalLocation location;
  location.Clamped = true;
  while (!queue.empty())
  {
    const Entry entry = queue.top();
    queue.pop();
    if (entry.first >= best)
    {
      break;
    }
    const Node& node = this->Nodes[static_cast<std::size_t>(entry.second)];
    if (node.TriangleCount == 0)
    {
      for (std::int32_t child = node.First; child <= node.First + 1; ++child)
      {
        const Node& c = this->Nodes[static_cast<std::size_t>(child)];
        queue.emplace(std::max(0.0, (p - c.Center).norm() - c.ChordRadius), child);
      }
      continue;
    }
    for (std::int32_t i = node.First; i < node.First + node.TriangleCount; ++i)
    {
      const LeafTriangle& triangle = this->LeafTriangles[static_cast<std::size_t>(i)];
      const std::array<Eigen::Vector3d, 3> vertex = { this->SpherePoints.row(triangle.Vertices[0]).transpose(),
        this->SpherePoints.row(triangle.Vertices[1]).transpose(),
        this->SpherePoints.row(triangle.Vertices[2]).transpose() };
      // The nearest point of a triangle that does not hold p lies on its boundary.
      for (int edge = 0; edge < 3; ++edge)
      {
        const int from = (edge + 1) % 3;
        const int to = (edge + 2) % 3;
        double s = 0.0;
        double t = 0.0;
        const double distance = NearestOnArc(p, vertex[from], vertex[to], s, t);
        if (distance < best)
        {
          best = distance;
          location.Triangle = triangle.Id;
          location.Barycentric.setZero();
          location.Barycentric[from] = s;
          location.Barycentric[to] = t;
        }
      }
    }
  }
  location.AngularDistance = ChordToAngle(best);
  return location;
}

bool SphericalPointLocator::LocateAll(const Points& queries,
  std::vector<SphericalLocation>& locations, int numberOfThreads,
  const ProgressCallback& progress) const
{
  locations.assign(static_cast<std::size_t>(queries.rows()), SphericalLocation());
  if (this->Nodes.empty())
  {
    return false;
  }
  // Chunks large enough to make the scheduling cost negligible, small enough to balance the
  // threads and to report progress often.
  constexpr Index ChunkSize = 4096;
  const Index numberOfChunks = (queries.rows() + ChunkSize - 1) / ChunkSize;
  std::atomic<Index> done(0);
  std::atomic<bool> aborted(false);
  ParallelFor(static_cast<int>(numberOfChunks), ResolveThreadCount(numberOfThreads),
    [&](int chunk, int thread) {
      if (aborted)
      {
        return;
      }
      const Index begin = chunk * ChunkSize;
      const Index end = std::min(queries.rows(), begin + ChunkSize);
      for (Index i = begin; i < end; ++i)
      {
        locations[static_cast<std::size_t>(i)] = this->Locate(queries.row(i).transpose());
      }
      const Index finished = ++done;
      // Only the calling thread reports: VTK progress and abort handlers are not thread-safe.
      if (thread == 0 && progress &&
        !progress(static_cast<double>(finished) / static_cast<double>(numberOfChunks)))
      {
        aborted = true;
      }
    });
  return !aborted;
}
}
