#include "SpectralSearch.h"

#include "ParallelFor.h"

#include <algorithm>
#include <limits>

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
