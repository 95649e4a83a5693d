#include "SpectralSearch.h"

#include "ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace mobius
{
namespace
{
// |p|^2 - 2 q.p between rows `first` .. `first + rows - 1` of `queries` and every row of
// `points` (norms `pointNorms`), one column per query, in single precision: the squared
// distances less |q|^2, which does not change an argmin over the points. One column per
// query keeps each argmin scan contiguous.
Eigen::MatrixXf DistancesLessQueryNorm(const Eigen::MatrixXf& points,
  const Eigen::VectorXf& pointNorms, const RowMatrix& queries, Index first, Index rows)
{
  Eigen::MatrixXf distances =
    points * (-2.0f * queries.middleRows(first, rows).transpose().cast<float>());
  distances.colwise() += pointNorms;
  return distances;
}
}

std::vector<Index> NearestRows(const RowMatrix& queries, const RowMatrix& points,
  int numberOfThreads)
{
  const Index blockSize = 256;
  const Index m = queries.rows();
  // Single precision halves the cost of the products; an argmin between embedding rows
  // (entries of order 1, distances compared at 1e-3 relative or coarser) does not need more.
  const Eigen::MatrixXf pointsF = points.cast<float>();
  const Eigen::VectorXf pointNorms = pointsF.rowwise().squaredNorm();
  std::vector<Index> nearest(static_cast<size_t>(m), 0);
  const int blocks = static_cast<int>((m + blockSize - 1) / blockSize);
  ParallelFor(blocks, ResolveThreadCount(numberOfThreads), [&](int block, int) {
    const Index begin = block * blockSize, rows = std::min(blockSize, m - begin);
    const Eigen::MatrixXf distances =
      DistancesLessQueryNorm(pointsF, pointNorms, queries, begin, rows);
    for (Index r = 0; r < rows; ++r)
    {
      Index best = 0;
      distances.col(r).minCoeff(&best);
      nearest[begin + r] = best;
    }
  });
  return nearest;
}

namespace
{
// Parts of a cluster hold at most this many rows: a large cluster (a sample cell of a fine
// mesh holds 20-100 vertices) is scanned part by part, each only if it can hold a nearer row.
constexpr Index kPartSize = 12;

// Points grouped by cluster: each cluster's rows contiguous (a scan reads one block), with
// its centre and radius; each cluster split into parts of nearby rows, with theirs.
struct PointClusters
{
  std::vector<Index> Begin;   ///< cluster c: parts Begin[c] .. Begin[c + 1] - 1
  std::vector<Index> PartBegin; ///< part p: rows PartBegin[p] .. PartBegin[p + 1] - 1 of Rows
  std::vector<Index> Members; ///< per row of Rows, the point's index
  RowMatrix Rows;
  Eigen::MatrixXf Centers;    ///< one row per cluster (single precision: the products)
  Eigen::VectorXf CenterNorms;
  Eigen::VectorXd Radius;     ///< largest distance of a member from the centre
  RowMatrix PartCenters;
  Eigen::VectorXd PartRadius;
};

// Centre (mean) and radius (largest distance from it) of rows.
template <typename Rows>
double CenterAndRadius(const Rows& rows, Eigen::Ref<Eigen::RowVectorXd> center)
{
  center = rows.colwise().mean();
  return (rows.rowwise() - center).rowwise().norm().maxCoeff();
}

// Orders members[first, last) into parts of at most kPartSize rows, each half of its range
// split at the median of the coordinate that spreads most; appends the parts' ends.
void SplitIntoParts(const RowMatrix& points, std::vector<Index>& members, Index first,
  Index last, std::vector<Index>& partEnds)
{
  if (last - first <= kPartSize)
  {
    partEnds.push_back(last);
    return;
  }
  Eigen::RowVectorXd low = points.row(members[first]), high = low;
  for (Index m = first + 1; m < last; ++m)
  {
    low = low.cwiseMin(points.row(members[m]));
    high = high.cwiseMax(points.row(members[m]));
  }
  Index column = 0;
  (high - low).maxCoeff(&column);
  const Index middle = first + (last - first) / 2;
  std::nth_element(members.begin() + first, members.begin() + middle, members.begin() + last,
    [&](Index a, Index b) { return points(a, column) < points(b, column); });
  SplitIntoParts(points, members, first, middle, partEnds);
  SplitIntoParts(points, members, middle, last, partEnds);
}

PointClusters GroupPoints(const RowMatrix& points, const std::vector<Index>& cluster)
{
  std::vector<Index> owner(cluster.begin(), cluster.end());
  Index count = owner.empty() ? 0 : *std::max_element(owner.begin(), owner.end()) + 1;
  for (Index& c : owner)
  {
    c = c >= 0 ? c : count++;
  }
  std::vector<Index> rowBegin(static_cast<size_t>(count) + 1, 0);
  for (Index c : owner)
  {
    ++rowBegin[static_cast<size_t>(c) + 1];
  }
  for (Index c = 0; c < count; ++c)
  {
    rowBegin[c + 1] += rowBegin[c];
  }
  PointClusters groups;
  groups.Members.resize(owner.size());
  std::vector<Index> next(rowBegin.begin(), rowBegin.end() - 1);
  for (Index p = 0; p < static_cast<Index>(owner.size()); ++p)
  {
    groups.Members[next[owner[p]]++] = p;
  }
  groups.Begin.assign(1, 0);
  groups.PartBegin.assign(1, 0);
  for (Index c = 0; c < count; ++c)
  {
    SplitIntoParts(points, groups.Members, rowBegin[c], rowBegin[c + 1], groups.PartBegin);
    groups.Begin.push_back(static_cast<Index>(groups.PartBegin.size()) - 1);
  }
  groups.Rows.resize(points.rows(), points.cols());
  for (Index m = 0; m < static_cast<Index>(groups.Members.size()); ++m)
  {
    groups.Rows.row(m) = points.row(groups.Members[m]);
  }
  const Index parts = static_cast<Index>(groups.PartBegin.size()) - 1;
  groups.PartCenters.resize(parts, points.cols());
  groups.PartRadius.resize(parts);
  for (Index p = 0; p < parts; ++p)
  {
    const Index first = groups.PartBegin[p], size = groups.PartBegin[p + 1] - first;
    groups.PartRadius[p] =
      CenterAndRadius(groups.Rows.middleRows(first, size), groups.PartCenters.row(p));
  }
  RowMatrix centers(count, points.cols());
  groups.Radius.resize(count);
  for (Index c = 0; c < count; ++c)
  {
    const Index first = rowBegin[c], size = rowBegin[c + 1] - first;
    groups.Radius[c] = CenterAndRadius(groups.Rows.middleRows(first, size), centers.row(c));
  }
  groups.Centers = centers.cast<float>();
  groups.CenterNorms = groups.Centers.rowwise().squaredNorm();
  return groups;
}

// Squared distance between two rows, summed in spans that stop once the sum reaches `limit`
// (the caller only needs to know it is that far).
double SquaredDistanceUpTo(const double* row, const Eigen::Ref<const Eigen::RowVectorXd>& query,
  double limit)
{
  const Index width = query.size();
  double d = 0;
  for (Index j = 0; j < width && d < limit; j += 16)
  {
    const Index span = std::min<Index>(16, width - j);
    d += (Eigen::Map<const Eigen::RowVectorXd>(row + j, span) - query.segment(j, span))
           .squaredNorm();
  }
  return d;
}

// Scans the rows of cluster c for one nearer to `query` than `best` (squared distance),
// part by part: a part whose centre is farther than sqrt(best) plus its radius is skipped
// (a cluster of one part was checked as a whole already).
void ScanCluster(const PointClusters& groups, Index c,
  const Eigen::Ref<const Eigen::RowVectorXd>& query, double& best, Index& nearest)
{
  const Index width = groups.Rows.cols();
  const bool oneTest = groups.Begin[c + 1] - groups.Begin[c] == 1;
  for (Index p = groups.Begin[c]; p < groups.Begin[c + 1]; ++p)
  {
    if (!oneTest)
    {
      const double reach = std::sqrt(best) + groups.PartRadius[p];
      if (SquaredDistanceUpTo(groups.PartCenters.row(p).data(), query, reach * reach) >=
        reach * reach)
      {
        continue;
      }
    }
    for (Index m = groups.PartBegin[p]; m < groups.PartBegin[p + 1]; ++m)
    {
      const double d = SquaredDistanceUpTo(groups.Rows.data() + m * width, query, best);
      if (d < best)
      {
        best = d;
        nearest = groups.Members[m];
      }
    }
  }
}
}

std::vector<Index> NearestRowsByClusters(const RowMatrix& queries, const RowMatrix& points,
  const std::vector<Index>& cluster, int numberOfThreads)
{
  const Index n = queries.rows();
  std::vector<Index> nearest(static_cast<size_t>(n), 0);
  if (points.rows() == 0)
  {
    return nearest;
  }
  const PointClusters groups = GroupPoints(points, cluster);
  const Index count = groups.Centers.rows();
  // The single-precision centre distances (|c|^2 - 2 q.c + |q|^2) are lowered by more than
  // their rounding error (1e-5 of |c|^2 + |q|^2) and the radii raised: a cluster is skipped
  // only when it surely holds no nearer point.
  const Eigen::ArrayXf radius = (groups.Radius.array() * (1.0 + 1e-6)).cast<float>();
  const Index blockSize = 256;
  const int blocks = static_cast<int>((n + blockSize - 1) / blockSize);
  ParallelFor(blocks, ResolveThreadCount(numberOfThreads), [&](int block, int) {
    const Index first = block * blockSize, rows = std::min(blockSize, n - first);
    const Eigen::MatrixXf distances =
      DistancesLessQueryNorm(groups.Centers, groups.CenterNorms, queries, first, rows);
    std::vector<std::pair<float, Index>> candidates;
    for (Index r = 0; r < rows; ++r)
    {
      const auto query = queries.row(first + r);
      const float queryNorm = static_cast<float>(query.squaredNorm());
      const Eigen::ArrayXf centerDistance2 =
        distances.col(r).array() + queryNorm - 1e-5f * (groups.CenterNorms.array() + queryNorm);
      Index closest = 0;
      centerDistance2.minCoeff(&closest);
      double best = std::numeric_limits<double>::infinity();
      Index bestPoint = 0;
      ScanCluster(groups, closest, query, best, bestPoint);
      // The clusters within reach of the first best, nearest lower bound first (the best
      // then tightens soonest), each checked again against the best so far before its scan.
      double reach = std::sqrt(best);
      const Eigen::ArrayXf limit = static_cast<float>(reach) + radius;
      candidates.clear();
      for (Index c = 0; c < count; ++c)
      {
        if (c != closest && centerDistance2[c] <= limit[c] * limit[c])
        {
          const float lower = std::sqrt(std::max(0.0f, centerDistance2[c])) - radius[c];
          candidates.emplace_back(lower, c);
        }
      }
      std::sort(candidates.begin(), candidates.end());
      for (const auto& candidate : candidates)
      {
        const Index c = candidate.second;
        const double bound = reach + groups.Radius[c];
        if (static_cast<double>(centerDistance2[c]) <= bound * bound)
        {
          ScanCluster(groups, c, query, best, bestPoint);
          reach = std::sqrt(best);
        }
      }
      nearest[first + r] = bestPoint;
    }
  });
  return nearest;
}

Index DescendToNearestVertex(const Eigen::Ref<const Eigen::RowVectorXd>& query,
  const RowMatrix& embedding, const VertexLists& neighbors, Index start)
{
  Index current = start;
  double best = (embedding.row(current) - query).squaredNorm();
  for (;;)
  {
    Index next = current;
    for (Index k = neighbors.Begin(current); k < neighbors.End(current); ++k)
    {
      const Index u = neighbors.Items[k];
      const double d = (embedding.row(u) - query).squaredNorm();
      if (d < best)
      {
        best = d;
        next = u;
      }
    }
    if (next == current)
    {
      return current;
    }
    current = next;
  }
}

namespace
{
// Nearest point to q on segment a + s (b - a), s in [0, 1]: returns s.
double ClosestOnSegment(const Eigen::RowVectorXd& a, const Eigen::RowVectorXd& b,
  const Eigen::Ref<const Eigen::RowVectorXd>& q)
{
  const Eigen::RowVectorXd d = b - a;
  const double length2 = d.squaredNorm();
  return length2 > 0 ? std::clamp((q - a).dot(d) / length2, 0.0, 1.0) : 0.0;
}
}

void ProjectOntoIncidentTriangles(const Eigen::Ref<const Eigen::RowVectorXd>& query,
  const RowMatrix& embedding, const Triangles& triangles, const VertexLists& vertexTriangles,
  Index vertex, Index& triangle, Eigen::Vector3d& barycentric)
{
  double best = std::numeric_limits<double>::infinity();
  triangle = -1;
  for (Index k = vertexTriangles.Begin(vertex); k < vertexTriangles.End(vertex); ++k)
  {
    const Index t = vertexTriangles.Items[k];
    const Eigen::RowVectorXd a = embedding.row(triangles(t, 0)), b = embedding.row(triangles(t, 1)),
                             c = embedding.row(triangles(t, 2));
    // Minimize |a + s (b - a) + u (c - a) - q|^2 over the triangle: the unconstrained
    // 2 x 2 normal equations, then the edges if the solution falls outside.
    const Eigen::RowVectorXd e1 = b - a, e2 = c - a, r = query - a;
    const double g11 = e1.squaredNorm(), g12 = e1.dot(e2), g22 = e2.squaredNorm();
    const double h1 = e1.dot(r), h2 = e2.dot(r);
    const double det = g11 * g22 - g12 * g12;
    Eigen::Vector3d w(1, 0, 0);
    bool inside = false;
    if (det > 1e-14 * g11 * g22)
    {
      const double s = (g22 * h1 - g12 * h2) / det, u = (g11 * h2 - g12 * h1) / det;
      if (s >= 0 && u >= 0 && s + u <= 1)
      {
        w << 1 - s - u, s, u;
        inside = true;
      }
    }
    if (!inside)
    {
      double edgeBest = std::numeric_limits<double>::infinity();
      const Eigen::RowVectorXd* corners[3] = { &a, &b, &c };
      for (int e = 0; e < 3; ++e)
      {
        const Eigen::RowVectorXd& p = *corners[e];
        const Eigen::RowVectorXd& q = *corners[(e + 1) % 3];
        const double s = ClosestOnSegment(p, q, query);
        const double d = (p + s * (q - p) - query).squaredNorm();
        if (d < edgeBest)
        {
          edgeBest = d;
          w.setZero();
          w[e] = 1 - s;
          w[(e + 1) % 3] = s;
        }
      }
    }
    const double d = (w[0] * a + w[1] * b + w[2] * c - query).squaredNorm();
    if (d < best)
    {
      best = d;
      triangle = t;
      barycentric = w;
    }
  }
}
}
