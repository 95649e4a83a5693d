#include "SurfaceWalk.h"

namespace mobius
{
// The Voronoi regions of the corners and edges are tested first (the interior solution
// of the 2 x 2 normal equations is valid only when no region test applies). An edge of zero
// length (two corners at one position; its squared length is the denominator) has no
// region of its own: the triangle is then a segment, found by the other edges' tests.
double ClosestOnTriangle(const Eigen::Vector3d& q, const Eigen::Vector3d& a,
  const Eigen::Vector3d& b, const Eigen::Vector3d& c, Eigen::Vector3d& weights)
{
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = q - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0)
  {
    weights << 1, 0, 0;
    return ap.squaredNorm();
  }
  const Eigen::Vector3d bp = q - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3)
  {
    weights << 0, 1, 0;
    return bp.squaredNorm();
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0 && d1 - d3 > 0)
  {
    const double s = d1 / (d1 - d3);
    weights << 1 - s, s, 0;
    return (a + s * ab - q).squaredNorm();
  }
  const Eigen::Vector3d cp = q - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6)
  {
    weights << 0, 0, 1;
    return cp.squaredNorm();
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0 && d2 - d6 > 0)
  {
    const double s = d2 / (d2 - d6);
    weights << 1 - s, 0, s;
    return (a + s * ac - q).squaredNorm();
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0 && (d4 - d3) + (d5 - d6) > 0)
  {
    const double s = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    weights << 0, 1 - s, s;
    return (b + s * (c - b) - q).squaredNorm();
  }
  const double sum = va + vb + vc;
  if (!(sum > 0))
  {
    weights << 1, 0, 0; // degenerate triangle: its first corner
    return ap.squaredNorm();
  }
  weights << va / sum, vb / sum, vc / sum;
  return (weights[0] * a + weights[1] * b + weights[2] * c - q).squaredNorm();
}

double SurfaceWalker::Closest(const Eigen::Vector3d& q, Index t, Eigen::Vector3d& weights) const
{
  return ClosestOnTriangle(q, this->Positions.row(this->Faces(t, 0)).transpose(),
    this->Positions.row(this->Faces(t, 1)).transpose(),
    this->Positions.row(this->Faces(t, 2)).transpose(), weights);
}

double SurfaceWalker::Walk(
  const Eigen::Vector3d& q, Index& t, Eigen::Vector3d& weights, bool insideIsEnough) const
{
  double best = this->Closest(q, t, weights);
  if (insideIsEnough)
  {
    return this->QuickWalk(q, t, weights, best);
  }
  for (int step = 0; step < kMaximumWalkSteps; ++step)
  {
    Index next = t;
    for (int k = 0; k < 3; ++k)
    {
      this->CloserAround(q, this->Faces(t, k), t, best, next, weights);
    }
    if (next == t)
    {
      break;
    }
    t = next;
  }
  return best;
}

void SurfaceWalker::CloserAround(const Eigen::Vector3d& q, Index v, Index t, double& best,
  Index& next, Eigen::Vector3d& weights) const
{
  for (Index j = this->VertexFaces.Begin(v); j < this->VertexFaces.End(v); ++j)
  {
    const Index u = this->VertexFaces.Items[j];
    if (u == t)
    {
      continue;
    }
    Eigen::Vector3d w;
    const double d = this->Closest(q, u, w);
    if (d < best)
    {
      best = d;
      next = u;
      weights = w;
    }
  }
}

double SurfaceWalker::QuickWalk(
  const Eigen::Vector3d& q, Index& t, Eigen::Vector3d& weights, double best) const
{
  for (int step = 0; step < kMaximumWalkSteps && weights.minCoeff() <= 0; ++step)
  {
    Index next = t;
    const int zeros = (weights.array() <= 0).count();
    if (zeros == 1)
    {
      // On an edge: the triangles around its ends.
      int k = 0;
      weights.minCoeff(&k);
      this->CloserAround(q, this->Faces(t, (k + 1) % 3), t, best, next, weights);
      this->CloserAround(q, this->Faces(t, (k + 2) % 3), t, best, next, weights);
    }
    else
    {
      // At a corner: the triangles around it.
      int k = 0;
      weights.maxCoeff(&k);
      this->CloserAround(q, this->Faces(t, k), t, best, next, weights);
    }
    if (next == t)
    {
      break;
    }
    t = next;
  }
  return best;
}

Eigen::Vector3d SurfaceWalker::Point(Index t, const Eigen::Vector3d& weights) const
{
  return weights[0] * this->Positions.row(this->Faces(t, 0)).transpose() +
    weights[1] * this->Positions.row(this->Faces(t, 1)).transpose() +
    weights[2] * this->Positions.row(this->Faces(t, 2)).transpose();
}

double MeanEdgeLength(const Points& points, const Triangles& triangles)
{
  double sum = 0;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      sum += (points.row(triangles(t, k)) - points.row(triangles(t, (k + 1) % 3))).norm();
    }
  }
  return triangles.rows() > 0 ? sum / (3.0 * triangles.rows()) : 0.0;
}
}
