#include "IntrinsicDelaunay.h"

#include "StableSortRun.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace mobius
{
namespace
{
inline Index Next(Index h)
{
  return h % 3 == 2 ? h - 2 : h + 1;
}

// tan(A/2) for the angle A opposite side a of a triangle with sides a, b, c (half-angle
// formula). Stays accurate for needles and tends to +inf as A tends to pi, where the
// cosine-based cotangent would divide by a vanishing area.
double HalfAngleTangent(double a, double b, double c)
{
  const double s = 0.5 * (a + b + c);
  const double num = (s - b) * (s - c);
  const double den = s * (s - a);
  if (den <= 0.0)
  {
    return std::numeric_limits<double>::infinity();
  }
  return std::sqrt(std::max(num, 0.0) / den);
}

// Area from side lengths, Kahan's stable form of Heron's formula.
double TriangleArea(double a, double b, double c)
{
  if (a < b)
  {
    std::swap(a, b);
  }
  if (a < c)
  {
    std::swap(a, c);
  }
  if (b < c)
  {
    std::swap(b, c);
  }
  const double p = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
  return 0.25 * std::sqrt(std::max(p, 0.0));
}

// The edge of half-edge h is locally Delaunay when the opposite angles alpha, beta satisfy
// alpha + beta <= pi, i.e. tan(alpha/2) tan(beta/2) <= 1. The small slack keeps nearly
// co-circular quads (every flat grid) from flipping back and forth.
bool IsDelaunay(const IntrinsicTriangulation& m, Index h)
{
  const Index t = m.Twin[h];
  if (t < 0)
  {
    return true;
  }
  const Index h1 = Next(h), h2 = Next(h1), t1 = Next(t), t2 = Next(t1);
  const double alpha = HalfAngleTangent(m.Length[h], m.Length[h1], m.Length[h2]);
  const double beta = HalfAngleTangent(m.Length[t], m.Length[t1], m.Length[t2]);
  return alpha * beta <= 1.0 + 1e-10;
}

// Replaces the diagonal a-b of the quad (a, d, b, c) formed by h's and its twin's
// triangles by the diagonal c-d. Returns false (changing nothing) if the two triangles are
// the same or the new diagonal would not make two proper triangles.
bool Flip(IntrinsicTriangulation& m, Index h)
{
  const Index t = m.Twin[h];
  const Index f0 = h / 3, f1 = t / 3;
  if (t < 0 || f0 == f1)
  {
    return false;
  }
  const Index h1 = Next(h), h2 = Next(h1), t1 = Next(t), t2 = Next(t1);
  // Triangle f0 = (a, b, c) with h: a->b; triangle f1 = (b, a, d) with t: b->a.
  const Index a = m.Corners(f0, h % 3), c = m.Corners(f0, h2 % 3), b = m.Corners(f1, t % 3),
              d = m.Corners(f1, t2 % 3);
  const double lab = m.Length[h], lbc = m.Length[h1], lca = m.Length[h2], lad = m.Length[t1],
               ldb = m.Length[t2];

  // Unfold the quad into the plane with a at the origin and b on the positive x axis, c
  // above and d below; the new diagonal is the distance from c to d.
  const double xc = (lab * lab + lca * lca - lbc * lbc) / (2.0 * lab);
  const double yc = 2.0 * TriangleArea(lab, lbc, lca) / lab;
  const double xd = (lab * lab + lad * lad - ldb * ldb) / (2.0 * lab);
  const double yd = -2.0 * TriangleArea(lab, lad, ldb) / lab;
  const double lcd = std::hypot(xc - xd, yc - yd);
  // Both new triangles (c, a, d) and (d, b, c) must be proper: strict triangle inequality.
  auto proper = [](double x, double y, double z) {
    return x < y + z && y < z + x && z < x + y;
  };
  if (!std::isfinite(lcd) || !proper(lca, lad, lcd) || !proper(ldb, lbc, lcd))
  {
    return false;
  }

  // New f0 = (c, a, d): c->a (was h2), a->d (was t1), d->c (new).
  // New f1 = (d, b, c): d->b (was t2), b->c (was h1), c->d (new).
  const Index base0 = 3 * f0, base1 = 3 * f1;
  const Index oldIds[4] = { h2, t1, t2, h1 };
  const Index newIds[4] = { base0, base0 + 1, base1, base1 + 1 };
  const double lengths[4] = { lca, lad, ldb, lbc };
  Index outerTwins[4];
  for (int i = 0; i < 4; ++i)
  {
    outerTwins[i] = m.Twin[oldIds[i]];
    // A twin inside the quad itself moves too (possible in intrinsic triangulations).
    for (int j = 0; j < 4; ++j)
    {
      if (outerTwins[i] == oldIds[j])
      {
        outerTwins[i] = newIds[j];
      }
    }
  }
  m.Corners(f0, 0) = c;
  m.Corners(f0, 1) = a;
  m.Corners(f0, 2) = d;
  m.Corners(f1, 0) = d;
  m.Corners(f1, 1) = b;
  m.Corners(f1, 2) = c;
  for (int i = 0; i < 4; ++i)
  {
    m.Length[newIds[i]] = lengths[i];
    m.Twin[newIds[i]] = outerTwins[i];
    if (outerTwins[i] >= 0)
    {
      m.Twin[outerTwins[i]] = newIds[i];
    }
  }
  m.Length[base0 + 2] = m.Length[base1 + 2] = lcd;
  m.Twin[base0 + 2] = base1 + 2;
  m.Twin[base1 + 2] = base0 + 2;
  return true;
}
}

bool MakeIntrinsicTriangulation(
  const Points& points, const Triangles& triangles, IntrinsicTriangulation& intrinsic)
{
  const Index m = triangles.rows();
  intrinsic.Corners = triangles;
  intrinsic.Length.assign(static_cast<size_t>(3 * m), 0.0);
  intrinsic.Twin.assign(static_cast<size_t>(3 * m), -1);
  // Pair half-edges through each vertex's outgoing ones, sorted by where they go (a
  // counting sort by start vertex, then a sort of each vertex's few): the twin of a -> b is
  // the one b -> a. An edge must have at most two sides, in opposite directions.
  const Index numberOfPoints = points.rows();
  if (m > 0 && (triangles.minCoeff() < 0 || triangles.maxCoeff() >= numberOfPoints))
  {
    return false;
  }
  auto from = [&](Index h) { return triangles(h / 3, h % 3); };
  auto to = [&](Index h) { return triangles(h / 3, (h % 3 + 1) % 3); };
  std::vector<Index> start(static_cast<size_t>(numberOfPoints) + 1, 0);
  for (Index h = 0; h < 3 * m; ++h)
  {
    ++start[from(h) + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<Index> outgoing(static_cast<size_t>(3 * m));
  {
    std::vector<Index> fill(start.begin(), start.end() - 1);
    for (Index h = 0; h < 3 * m; ++h)
    {
      outgoing[fill[from(h)]++] = h;
    }
  }
  auto byEnd = [&](Index x, Index y) { return to(x) < to(y); };
  for (Index v = 0; v < numberOfPoints; ++v)
  {
    const auto begin = outgoing.begin() + start[v], end = outgoing.begin() + start[v + 1];
    StableSortRun(begin, end, byEnd);
    if (std::adjacent_find(begin, end, [&](Index x, Index y) { return to(x) == to(y); }) != end)
    {
      return false; // two sides in the same direction: inconsistent or non-manifold
    }
  }
  for (Index h = 0; h < 3 * m; ++h)
  {
    const Index a = from(h), b = to(h);
    intrinsic.Length[h] = (points.row(a) - points.row(b)).norm();
    // b's outgoing half-edges have distinct ends, so at most one goes back to a.
    const auto begin = outgoing.begin() + start[b], end = outgoing.begin() + start[b + 1];
    const auto twin = std::lower_bound(
      begin, end, a, [&](Index x, Index target) { return to(x) < target; });
    if (twin != end && to(*twin) == a && *twin != h)
    {
      intrinsic.Twin[h] = *twin;
    }
  }
  return true;
}

Index FlipToDelaunay(IntrinsicTriangulation& m, Index maximumFlips)
{
  const Index halfEdges = static_cast<Index>(m.Length.size());
  if (maximumFlips <= 0)
  {
    maximumFlips = 100 * halfEdges;
  }
  // Work stack of half-edges to check; stale entries are simply re-checked.
  std::vector<Index> stack;
  std::vector<char> queued(static_cast<size_t>(halfEdges), 0);
  for (Index h = 0; h < halfEdges; ++h)
  {
    if (m.Twin[h] > h)
    {
      stack.push_back(h);
      queued[h] = 1;
    }
  }
  Index flips = 0;
  while (!stack.empty() && flips < maximumFlips)
  {
    const Index h = stack.back();
    stack.pop_back();
    queued[h] = 0;
    if (m.Twin[h] < 0 || IsDelaunay(m, h))
    {
      continue;
    }
    const Index f0 = h / 3, f1 = m.Twin[h] / 3;
    if (!Flip(m, h))
    {
      continue;
    }
    ++flips;
    // The four outer edges of the quad may have stopped being Delaunay. After the flip
    // they are the first two half-edges of each of the two triangles.
    for (Index e : { 3 * f0, 3 * f0 + 1, 3 * f1, 3 * f1 + 1 })
    {
      if (!queued[e])
      {
        queued[e] = 1;
        stack.push_back(e);
      }
    }
  }
  return flips;
}

std::vector<double> OppositeCotangents(const IntrinsicTriangulation& m)
{
  std::vector<double> cotangents(m.Length.size());
  for (size_t t = 0; 3 * t < m.Length.size(); ++t)
  {
    const double l[3] = { m.Length[3 * t], m.Length[3 * t + 1], m.Length[3 * t + 2] };
    const double area = TriangleArea(l[0], l[1], l[2]);
    for (int k = 0; k < 3; ++k)
    {
      // Law of cosines over twice the area: cot = (b^2 + c^2 - a^2) / (4 area).
      const double a = l[k], b = l[(k + 1) % 3], c = l[(k + 2) % 3];
      cotangents[3 * t + k] = (b * b + c * c - a * a) / (4.0 * area);
    }
  }
  return cotangents;
}
}
