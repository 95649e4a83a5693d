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
/// Caps wider than this (about 89 degrees) are treated as the whole sphere, with a margin for
/// round-off.
constexpr double LargestTriangleSafeChord = 1.4;

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

/// Spreads the low 21 bits of x so that two zero bits follow each one (for a 3D Morton code).
std::uint64_t SpreadBits(std::uint64_t x)
{
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

/// Position of a direction on a Z-order curve through the cube [-1, 1]^3: nearby directions
/// mostly get nearby keys. Non-finite or zero queries get key 0 (they are not located anyway).
std::uint64_t MortonKey(const Eigen::Vector3d& x)
{
  const double norm = x.norm();
  if (!std::isfinite(norm) || !(norm > 0.0))
  {
    return 0;
  }
  std::uint64_t key = 0;
  for (int k = 0; k < 3; ++k)
  {
    const double unit = std::min(1.0, std::max(0.0, 0.5 * (x[k] / norm + 1.0)));
    key |= SpreadBits(static_cast<std::uint64_t>(unit * 2097151.0)) << k;
  }
  return key;
}

double ChordToAngle(double chord)
{
  return 2.0 * std::asin(std::min(1.0, 0.5 * chord));
}

/// A cap holding the caps (c1, r1) and (c2, r2) (chord radii), nearly the smallest one: its
/// center is that of the smallest enclosing cap, its radius bounds both caps by the triangle
/// inequality of chord distances, so round-off in the center cannot make it too small.
void MergeCaps(const Eigen::Vector3d& c1, double r1, const Eigen::Vector3d& c2, double r2,
  Eigen::Vector3d& center, double& radius)
{
  if (r1 >= WholeSphere || r2 >= WholeSphere)
  {
    center = c1;
    radius = WholeSphere;
    return;
  }
  const double angle1 = ChordToAngle(r1);
  const double angle2 = ChordToAngle(r2);
  const Eigen::Vector3d axis = c1.cross(c2);
  const double between = std::atan2(axis.norm(), c1.dot(c2));
  if (between + angle2 <= angle1)
  {
    center = c1;
  }
  else if (between + angle1 <= angle2)
  {
    center = c2;
  }
  else
  {
    // The smallest enclosing cap has angular radius (between + angle1 + angle2) / 2 and its
    // center on the great circle from c1 toward c2, (radius - angle1) away from c1.
    const double angle = 0.5 * (between + angle1 + angle2);
    if (angle >= 0.5 * M_PI)
    {
      center = c1;
      radius = WholeSphere;
      return;
    }
    const Eigen::Vector3d toward = axis.cross(c1).normalized();
    const double shift = angle - angle1;
    center = (std::cos(shift) * c1 + std::sin(shift) * toward).normalized();
  }
  radius = Pad(std::max((c1 - center).norm() + r1, (c2 - center).norm() + r2));
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

/// What the top-down build sorts: one triangle, represented by its normalized centroid.
struct SphericalPointLocator::Primitive
{
  Eigen::Vector3d Center;
  std::int32_t Id;
  std::int32_t Orientation;
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
  if (numberOfTriangles >= std::numeric_limits<std::int32_t>::max() / 2 ||
    numberOfPoints >= std::numeric_limits<std::int32_t>::max())
  {
    error = "SphericalPointLocator: the mesh is too large for 32-bit indices (" +
      std::to_string(numberOfPoints) + " points, " + std::to_string(numberOfTriangles) +
      " triangles).";
    return false;
  }
  Points normalized(numberOfPoints, 3);
  for (Index i = 0; i < numberOfPoints; ++i)
  {
    const Eigen::Vector3d x = spherePoints.row(i).transpose();
    if (!x.allFinite())
    {
      error = "SphericalPointLocator: point " + std::to_string(i) + " has a non-finite coordinate.";
      return false;
    }
    const double norm = x.norm();
    if (!(std::abs(norm - 1.0) <= 1e-6))
    {
      std::ostringstream message;
      message.precision(17);
      message << "SphericalPointLocator: point " << i
              << " is not on the unit sphere (|x| = " << norm << ", tolerance 1e-6).";
      error = message.str();
      return false;
    }
    normalized.row(i) = (x / norm).transpose();
  }

  std::vector<Primitive> primitives(static_cast<std::size_t>(numberOfTriangles));
  for (Index t = 0; t < numberOfTriangles; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index v = triangles(t, k);
      if (v < 0 || v >= numberOfPoints)
      {
        error = "SphericalPointLocator: triangle " + std::to_string(t) + " has vertex index " +
          std::to_string(v) + ", out of range [0, " + std::to_string(numberOfPoints) + ").";
        return false;
      }
    }
    const Eigen::Vector3d a = normalized.row(triangles(t, 0)).transpose();
    const Eigen::Vector3d b = normalized.row(triangles(t, 1)).transpose();
    const Eigen::Vector3d c = normalized.row(triangles(t, 2)).transpose();
    Primitive& primitive = primitives[static_cast<std::size_t>(t)];
    const Eigen::Vector3d sum = a + b + c;
    const double sumNorm = sum.norm();
    primitive.Center = sumNorm > 0.0 ? Eigen::Vector3d(sum / sumNorm) : a;
    primitive.Id = static_cast<std::int32_t>(t);
    // det(a, b, c) = a . ((b - a) x (c - a)): accurate for tiny triangles, whose edge vectors
    // are nearly orthogonal to a. Computed from the points as given, like containment.
    const Eigen::Vector3d givenA = spherePoints.row(triangles(t, 0)).transpose();
    const double volume =
      givenA.dot((Eigen::Vector3d(spherePoints.row(triangles(t, 1)).transpose()) - givenA)
                   .cross(Eigen::Vector3d(spherePoints.row(triangles(t, 2)).transpose()) - givenA));
    primitive.Orientation = volume > 0.0 ? 1 : (volume < 0.0 ? -1 : 0);
  }

  // Containment and barycentric coordinates use the points exactly as given: the cone of a
  // triangle does not change when its vertices are rescaled, but renormalizing would move the
  // vertices of a 1e-11-wide triangle by a relative 1e-5, and the coordinates would no longer
  // be those of the caller's triangle. The caps are built from the normalized points.
  this->SpherePoints = spherePoints;
  this->LeafTriangles.resize(primitives.size());
  this->Nodes.reserve(static_cast<std::size_t>(2 * numberOfTriangles / (LeafSize / 2) + 1));
  this->Nodes.emplace_back();
  this->Depth = this->BuildNode(
    0, primitives, triangles, normalized, 0, static_cast<std::int32_t>(primitives.size()));
  return true;
}

int SphericalPointLocator::BuildNode(std::int32_t node, std::vector<Primitive>& primitives,
  const Triangles& triangles, const Points& unitPoints, std::int32_t begin, std::int32_t end)
{
  if (end - begin <= LeafSize)
  {
    // A leaf's cap: centered at the normalized mean of its triangle centers, just large enough
    // for all their vertices.
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::int32_t i = begin; i < end; ++i)
    {
      sum += primitives[static_cast<std::size_t>(i)].Center;
    }
    const double sumNorm = sum.norm();
    const Eigen::Vector3d center = sumNorm > 1e-3
      ? Eigen::Vector3d(sum / sumNorm)
      : primitives[static_cast<std::size_t>(begin)].Center;
    double radius = 0.0;
    for (std::int32_t i = begin; i < end; ++i)
    {
      const Primitive& primitive = primitives[static_cast<std::size_t>(i)];
      LeafTriangle& triangle = this->LeafTriangles[static_cast<std::size_t>(i)];
      triangle.Id = primitive.Id;
      triangle.Orientation = primitive.Orientation;
      for (int k = 0; k < 3; ++k)
      {
        const Index v = triangles(primitive.Id, k);
        triangle.Vertices[static_cast<std::size_t>(k)] = static_cast<std::int32_t>(v);
        radius = std::max(radius, (unitPoints.row(v).transpose() - center).norm());
      }
    }
    Node& leaf = this->Nodes[static_cast<std::size_t>(node)];
    leaf.Center = center;
    leaf.ChordRadius = Pad(radius);
    leaf.First = begin;
    leaf.TriangleCount = end - begin;
    return 1;
  }

  // Median split along the axis in which the triangle centers spread most: balanced, so the
  // depth is log2(n / LeafSize) however non-uniform the triangle sizes are.
  Eigen::Vector3d lower = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d upper = -lower;
  for (std::int32_t i = begin; i < end; ++i)
  {
    const Eigen::Vector3d& center = primitives[static_cast<std::size_t>(i)].Center;
    lower = lower.cwiseMin(center);
    upper = upper.cwiseMax(center);
  }
  int axis = 0;
  (upper - lower).maxCoeff(&axis);
  const std::int32_t middle = begin + (end - begin) / 2;
  std::nth_element(primitives.begin() + begin, primitives.begin() + middle,
    primitives.begin() + end,
    [axis](const Primitive& x, const Primitive& y) { return x.Center[axis] < y.Center[axis]; });

  const std::int32_t firstChild = static_cast<std::int32_t>(this->Nodes.size());
  this->Nodes.emplace_back();
  this->Nodes.emplace_back();
  const int left = this->BuildNode(firstChild, primitives, triangles, unitPoints, begin, middle);
  const int right = this->BuildNode(firstChild + 1, primitives, triangles, unitPoints, middle, end);

  // The cap enclosing the two child caps is quick but loosens at every level; bounding the
  // descendant leaves' caps instead (they occupy the nodes allocated since firstChild) keeps the
  // slack of one level only, for O(n log n) work in all.
  const Node& leftNode = this->Nodes[static_cast<std::size_t>(firstChild)];
  const Node& rightNode = this->Nodes[static_cast<std::size_t>(firstChild + 1)];
  Eigen::Vector3d center;
  double radius = 0.0;
  MergeCaps(
    leftNode.Center, leftNode.ChordRadius, rightNode.Center, rightNode.ChordRadius, center, radius);
  if (radius < WholeSphere)
  {
    double leafBound = 0.0;
    for (std::size_t i = static_cast<std::size_t>(firstChild); i < this->Nodes.size(); ++i)
    {
      const Node& descendant = this->Nodes[i];
      if (descendant.TriangleCount > 0)
      {
        leafBound =
          std::max(leafBound, (descendant.Center - center).norm() + descendant.ChordRadius);
      }
    }
    radius = std::min(radius, Pad(leafBound));
  }
  Node& inner = this->Nodes[static_cast<std::size_t>(node)];
  inner.Center = center;
  inner.ChordRadius = radius;
  inner.First = firstChild;
  inner.TriangleCount = 0;
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
  // The caps are tested with the unit vector p. Containment does not depend on the length of
  // the query, so a query already on the sphere up to round-off is tested exactly as given:
  // renormalizing it would move it by an ulp, a relative 1e-5 of a 1e-11-wide triangle, and a
  // vertex or edge point would no longer be exactly on its vertex or edge.
  const Eigen::Vector3d p = query / norm;
  const Eigen::Vector3d& tested = std::abs(norm - 1.0) <= 1e-14 ? query : p;

  // Depth-first search of every leaf whose cap holds p. The tree is balanced, so its depth is
  // about log2(n / 2); 64 levels of pending siblings are more than any mesh can need.
  std::int32_t stack[64];
  int top = 0;
  const Node& root = this->Nodes.front();
  if ((p - root.Center).squaredNorm() <= root.ChordRadius * root.ChordRadius)
  {
    stack[top++] = 0;
  }
  while (top > 0)
  {
    // Every node on the stack holds p in its cap.
    const Node& node = this->Nodes[static_cast<std::size_t>(stack[--top])];
    if (node.TriangleCount > 0)
    {
      for (std::int32_t i = node.First; i < node.First + node.TriangleCount; ++i)
      {
        const LeafTriangle& triangle = this->LeafTriangles[static_cast<std::size_t>(i)];
        if (this->Contains(triangle, tested, location.Barycentric))
        {
          location.Triangle = triangle.Id;
          return location;
        }
      }
      continue;
    }
    // Descend first into the child in whose cap p lies deeper (relative to its radius): that
    // is usually where the containing triangle is, so the search stops early.
    const Node& first = this->Nodes[static_cast<std::size_t>(node.First)];
    const Node& second = this->Nodes[static_cast<std::size_t>(node.First + 1)];
    const double firstRadius = first.ChordRadius * first.ChordRadius;
    const double secondRadius = second.ChordRadius * second.ChordRadius;
    const double toFirst = (p - first.Center).squaredNorm();
    const double toSecond = (p - second.Center).squaredNorm();
    const bool inFirst = toFirst <= firstRadius;
    const bool inSecond = toSecond <= secondRadius;
    if (inFirst && inSecond)
    {
      const bool firstIsDeeper = toFirst * secondRadius < toSecond * firstRadius;
      stack[top++] = firstIsDeeper ? node.First + 1 : node.First;
      stack[top++] = firstIsDeeper ? node.First : node.First + 1;
    }
    else if (inFirst)
    {
      stack[top++] = node.First;
    }
    else if (inSecond)
    {
      stack[top++] = node.First + 1;
    }
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
      // Distances are measured on the sphere, so between the normalized vertices; the weights
      // are converted back to the vertices as given (weight / |vertex|).
      std::array<Eigen::Vector3d, 3> vertex;
      std::array<double, 3> length;
      for (int k = 0; k < 3; ++k)
      {
        vertex[k] = this->SpherePoints.row(triangle.Vertices[k]).transpose();
        length[k] = vertex[k].norm();
        vertex[k] /= length[k];
      }
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
          location.Barycentric[from] = s / length[from];
          location.Barycentric[to] = t / length[to];
          location.Barycentric /= location.Barycentric.sum();
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
  // Visiting the queries in Z-order makes consecutive queries walk the same part of the tree,
  // which then stays in cache: several times faster for unordered (e.g. random) queries.
  std::vector<std::pair<std::uint64_t, Index>> order(static_cast<std::size_t>(queries.rows()));
  for (Index i = 0; i < queries.rows(); ++i)
  {
    order[static_cast<std::size_t>(i)] = { MortonKey(queries.row(i).transpose()), i };
  }
  std::sort(order.begin(), order.end());
  std::atomic<Index> done(0);
  std::atomic<bool> aborted(false);
  ParallelFor(static_cast<int>(numberOfChunks), ResolveThreadCount(numberOfThreads),
    [&](int chunk, int thread)
    {
      if (aborted)
      {
        return;
      }
      const Index begin = chunk * ChunkSize;
      const Index end = std::min(queries.rows(), begin + ChunkSize);
      for (Index i = begin; i < end; ++i)
      {
        const Index query = order[static_cast<std::size_t>(i)].second;
        locations[static_cast<std::size_t>(query)] = this->Locate(queries.row(query).transpose());
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
