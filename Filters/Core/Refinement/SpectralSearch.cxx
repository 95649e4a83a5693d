#include "SpectralSearch.h"

#include "ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace mobius
{
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
    // |q - p|^2 = |p|^2 - 2 q.p + |q|^2; the last term does not change the argmin. One
    // column per query keeps each argmin scan contiguous.
    Eigen::MatrixXf distances =
      pointsF * (-2.0f * queries.middleRows(begin, rows).transpose().cast<float>());
    distances.colwise() += pointNorms;
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
// Points grouped by cluster: each cluster's rows contiguous (a scan reads one block), with
// its centre and radius.
struct PointClusters
{
  std::vector<Index> Begin;   ///< cluster c: rows Begin[c] .. Begin[c + 1] - 1 of Rows
  std::vector<Index> Members; ///< per row of Rows, the point's index
  RowMatrix Rows;
  Eigen::MatrixXf Centers;    ///< one row per cluster (single precision: the products)
  Eigen::VectorXf CenterNorms;
  Eigen::VectorXd Radius;     ///< largest distance of a member from the centre
};

PointClusters GroupPoints(const RowMatrix& points, const std::vector<Index>& cluster)
{
  std::vector<Index> owner(cluster.begin(), cluster.end());
  Index count = owner.empty() ? 0 : *std::max_element(owner.begin(), owner.end()) + 1;
  for (Index& c : owner)
  {
    c = c >= 0 ? c : count++;
  }
  PointClusters groups;
  groups.Begin.assign(static_cast<size_t>(count) + 1, 0);
  for (Index c : owner)
  {
    ++groups.Begin[static_cast<size_t>(c) + 1];
  }
  for (Index c = 0; c < count; ++c)
  {
    groups.Begin[c + 1] += groups.Begin[c];
  }
  groups.Members.resize(owner.size());
  std::vector<Index> next(groups.Begin.begin(), groups.Begin.end() - 1);
  for (Index p = 0; p < static_cast<Index>(owner.size()); ++p)
  {
    groups.Members[next[owner[p]]++] = p;
  }
  groups.Rows.resize(points.rows(), points.cols());
  RowMatrix centers = RowMatrix::Zero(count, points.cols());
  groups.Radius = Eigen::VectorXd::Zero(count);
  for (Index c = 0; c < count; ++c)
  {
    const Index first = groups.Begin[c], size = groups.Begin[c + 1] - first;
    for (Index m = first; m < first + size; ++m)
    {
      groups.Rows.row(m) = points.row(groups.Members[m]);
    }
    centers.row(c) = groups.Rows.middleRows(first, size).colwise().mean();
    groups.Radius[c] = (groups.Rows.middleRows(first, size).rowwise() - centers.row(c))
                         .rowwise()
                         .norm()
                         .maxCoeff();
  }
  groups.Centers = centers.cast<float>();
  groups.CenterNorms = groups.Centers.rowwise().squaredNorm();
  return groups;
}

// Scans the rows of cluster c for one nearer to `query` than `best` (squared distance);
// partial sums stop once they pass it, as they do for most rows.
void ScanCluster(const PointClusters& groups, Index c,
  const Eigen::Ref<const Eigen::RowVectorXd>& query, double& best, Index& nearest)
{
  const Index width = groups.Rows.cols();
  for (Index m = groups.Begin[c]; m < groups.Begin[c + 1]; ++m)
  {
    const double* row = groups.Rows.data() + m * width;
    double d = 0;
    for (Index j = 0; j < width && d < best; j += 16)
    {
      const Index span = std::min<Index>(16, width - j);
      d += (Eigen::Map<const Eigen::RowVectorXd>(row + j, span) - query.segment(j, span))
             .squaredNorm();
    }
    if (d < best)
    {
      best = d;
      nearest = groups.Members[m];
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
    Eigen::MatrixXf distances =
      groups.Centers * (-2.0f * queries.middleRows(first, rows).transpose().cast<float>());
    distances.colwise() += groups.CenterNorms;
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
