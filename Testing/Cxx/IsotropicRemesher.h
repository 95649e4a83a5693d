// A simple isotropic remesher for the tests (Botsch & Kobbelt, "A Remeshing Approach to
// Multiresolution Modeling", SGP 2004): edges split above 4/3 of a target length, collapsed
// below 4/5 of it, flipped toward valence 6, vertices relaxed tangentially and projected back
// onto the input surface. It gives a closed genus-0 mesh another, well-shaped triangulation of
// about a given number of vertices, as remeshing tools give users (the triangulations that
// the conformal map meets in the wild), without a GPL dependency.
//
// Topology is kept: a collapse needs the link condition and leaves no vertex of valence
// below 3; collapses and flips that would turn a triangle's normal by more than 60 degrees
// are skipped.
#ifndef IsotropicRemesher_h
#define IsotropicRemesher_h

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace mobius_corpus
{
class IsotropicRemesher
{
public:
  using Vec = Eigen::Vector3d;
  using Tri = std::array<int, 3>;

  explicit IsotropicRemesher(vtkPolyData* surface)
  {
    for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
    {
      this->P.emplace_back(surface->GetPoint(i));
    }
    for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
    {
      vtkIdType npts;
      const vtkIdType* ids;
      surface->GetCellPoints(c, npts, ids);
      this->T.push_back({ static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) });
    }
    this->InputPoints = this->P;
    this->InputTriangles = this->T;
    this->InputAround = this->VertexTriangles();
    this->Home.resize(this->P.size(), 0);
    for (int t = 0; t < static_cast<int>(this->T.size()); ++t)
    {
      for (int v : this->T[t])
      {
        this->Home[v] = t;
      }
    }
  }

  /// Remeshes to about `vertices` vertices with `iterations` rounds.
  vtkSmartPointer<vtkPolyData> Remesh(int vertices, int iterations = 8)
  {
    double area = 0.0;
    for (const Tri& t : this->T)
    {
      area += 0.5 * (this->P[t[1]] - this->P[t[0]]).cross(this->P[t[2]] - this->P[t[0]]).norm();
    }
    // Equilateral triangles, two per vertex: area = 2 V (sqrt(3) / 4) L^2.
    const double length = std::sqrt(2.0 * area / (std::sqrt(3.0) * vertices));
    for (int i = 0; i < iterations || (i < 3 * iterations && this->P.size() > 1.1 * vertices); ++i)
    {
      this->SplitLongEdges(4.0 / 3.0 * length);
      this->CollapseShortEdges(4.0 / 5.0 * length, 4.0 / 3.0 * length);
      this->FlipTowardValenceSix();
      this->RelaxAndProject();
    }
    return this->Output();
  }

private:
  static std::uint64_t Key(int a, int b)
  {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
  }

  Vec Normal(const Tri& t) const
  {
    return (this->P[t[1]] - this->P[t[0]]).cross(this->P[t[2]] - this->P[t[0]]);
  }

  // Each edge once, with the triangles on its two sides: (triangle, corner) where the edge
  // runs from the corner to the next one. Sorted by key, for lookups.
  struct Edge
  {
    std::uint64_t Key;
    int Triangle[2];
    int Corner[2];
    bool operator<(const Edge& other) const { return this->Key < other.Key; }
  };
  std::vector<Edge> Edges() const
  {
    std::vector<std::pair<std::uint64_t, int>> halves; // key, 3 * triangle + corner
    halves.reserve(3 * this->T.size());
    for (int t = 0; t < static_cast<int>(this->T.size()); ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        halves.emplace_back(Key(this->T[t][k], this->T[t][(k + 1) % 3]), 3 * t + k);
      }
    }
    std::sort(halves.begin(), halves.end());
    std::vector<Edge> edges;
    for (size_t h = 0; h + 1 < halves.size(); ++h)
    {
      if (halves[h].first == halves[h + 1].first) // closed and manifold: exactly two halves
      {
        edges.push_back({ halves[h].first, { halves[h].second / 3, halves[h + 1].second / 3 },
          { halves[h].second % 3, halves[h + 1].second % 3 } });
        ++h;
      }
    }
    return edges;
  }
  static bool HasEdge(const std::vector<Edge>& edges, std::uint64_t key)
  {
    Edge probe{ key, { 0, 0 }, { 0, 0 } };
    return std::binary_search(edges.begin(), edges.end(), probe);
  }

  std::vector<std::vector<int>> VertexTriangles() const
  {
    std::vector<std::vector<int>> around(this->P.size());
    for (int t = 0; t < static_cast<int>(this->T.size()); ++t)
    {
      for (int v : this->T[t])
      {
        around[v].push_back(t);
      }
    }
    return around;
  }

  // Splits the longest edges first; an edge whose triangles another split changed waits for
  // the next round.
  void SplitLongEdges(double longest)
  {
    const std::vector<Edge> edges = this->Edges();
    std::vector<std::pair<double, size_t>> queue;
    for (size_t e = 0; e < edges.size(); ++e)
    {
      const int a = static_cast<int>(edges[e].Key >> 32), b = static_cast<int>(edges[e].Key & 0xffffffffu);
      const double length = (this->P[a] - this->P[b]).norm();
      if (length > longest)
      {
        queue.emplace_back(-length, e);
      }
    }
    std::sort(queue.begin(), queue.end());
    std::vector<char> touched(this->T.size(), 0);
    for (const auto& item : queue)
    {
      const Edge& edge = edges[item.second];
      const int t0 = edge.Triangle[0], k0 = edge.Corner[0], t1 = edge.Triangle[1], k1 = edge.Corner[1];
      if (touched[t0] || touched[t1])
      {
        continue;
      }
      const int a = this->T[t0][k0], b = this->T[t0][(k0 + 1) % 3], c = this->T[t0][(k0 + 2) % 3];
      const int d = this->T[t1][(k1 + 2) % 3]; // T[t1] runs b -> a -> d
      const int m = static_cast<int>(this->P.size());
      this->P.push_back(0.5 * (this->P[a] + this->P[b]));
      this->Home.push_back(this->Home[a]);
      this->T[t0] = { a, m, c };
      this->T[t1] = { b, m, d };
      this->T.push_back({ m, b, c });
      this->T.push_back({ m, a, d });
      touched[t0] = touched[t1] = 1;
      touched.push_back(1);
      touched.push_back(1);
    }
  }

  // Collapses the shortest edges first into their midpoints, where the link condition holds,
  // no edge gets longer than `longest`, no triangle turns over and no vertex drops below
  // valence 3. Vertices next to a collapse wait for the next round.
  void CollapseShortEdges(double shortest, double longest)
  {
    auto around = this->VertexTriangles();
    std::vector<std::pair<double, std::uint64_t>> queue;
    for (const Edge& edge : this->Edges())
    {
      const int a = static_cast<int>(edge.Key >> 32), b = static_cast<int>(edge.Key & 0xffffffffu);
      const double length = (this->P[a] - this->P[b]).norm();
      if (length < shortest)
      {
        queue.emplace_back(length, edge.Key);
      }
    }
    std::sort(queue.begin(), queue.end());
    std::vector<char> locked(this->P.size(), 0), dead(this->T.size(), 0), removed(this->P.size(), 0);
    size_t remaining = this->P.size();
    auto neighbours = [&](int v) {
      std::vector<int> list;
      for (int t : around[v])
      {
        for (int w : this->T[t])
        {
          if (w != v && std::find(list.begin(), list.end(), w) == list.end())
          {
            list.push_back(w);
          }
        }
      }
      return list;
    };
    for (const auto& item : queue)
    {
      const int a = static_cast<int>(item.second >> 32), b = static_cast<int>(item.second & 0xffffffffu);
      if (locked[a] || locked[b] || remaining <= 4)
      {
        continue;
      }
      const std::vector<int> na = neighbours(a), nb = neighbours(b);
      std::vector<int> common;
      for (int w : na)
      {
        if (std::find(nb.begin(), nb.end(), w) != nb.end())
        {
          common.push_back(w);
        }
      }
      if (common.size() != 2 || na.size() + nb.size() < 7)
      {
        continue; // link condition, or a collapse into a tetrahedron-like spot
      }
      bool ok = true;
      for (int c : common)
      {
        ok = ok && neighbours(c).size() > 3;
      }
      const Vec middle = 0.5 * (this->P[a] + this->P[b]);
      for (int w : nb)
      {
        ok = ok && (w == a || (this->P[w] - middle).norm() <= longest);
      }
      for (int w : na)
      {
        ok = ok && (w == b || (this->P[w] - middle).norm() <= longest);
      }
      // No triangle that stays may turn over.
      for (int v : { a, b })
      {
        for (int t : around[v])
        {
          Tri moved = this->T[t];
          if (std::count(moved.begin(), moved.end(), a) + std::count(moved.begin(), moved.end(), b) == 2)
          {
            continue; // one of the two triangles that go
          }
          const Vec before = this->Normal(moved);
          const Vec saved = this->P[v];
          this->P[v] = middle;
          const Vec after = this->Normal(moved);
          this->P[v] = saved;
          ok = ok && after.dot(before) > 0.5 * after.norm() * before.norm();
        }
      }
      if (!ok)
      {
        continue;
      }
      this->P[a] = middle;
      removed[b] = 1;
      --remaining;
      std::vector<int> kept;
      for (int t : around[a])
      {
        if (std::find(this->T[t].begin(), this->T[t].end(), b) != this->T[t].end())
        {
          dead[t] = 1;
        }
        else
        {
          kept.push_back(t);
        }
      }
      for (int t : around[b])
      {
        if (dead[t])
        {
          continue;
        }
        std::replace(this->T[t].begin(), this->T[t].end(), b, a);
        kept.push_back(t);
      }
      around[a] = kept;
      around[b].clear();
      for (int c : common)
      {
        around[c].erase(std::remove_if(around[c].begin(), around[c].end(), [&](int t) { return dead[t]; }),
          around[c].end());
      }
      for (int w : neighbours(a))
      {
        locked[w] = 1;
      }
      locked[a] = locked[b] = 1;
    }
    this->Compact(dead, removed);
  }

  // Drops dead triangles and removed vertices, renumbering the rest.
  void Compact(const std::vector<char>& dead, const std::vector<char>& removed)
  {
    std::vector<int> number(this->P.size(), -1);
    std::vector<Vec> points;
    std::vector<int> home;
    for (size_t v = 0; v < this->P.size(); ++v)
    {
      if (!removed[v])
      {
        number[v] = static_cast<int>(points.size());
        points.push_back(this->P[v]);
        home.push_back(this->Home[v]);
      }
    }
    this->Home.swap(home);
    std::vector<Tri> triangles;
    for (size_t t = 0; t < this->T.size(); ++t)
    {
      if (!dead[t])
      {
        triangles.push_back({ number[this->T[t][0]], number[this->T[t][1]], number[this->T[t][2]] });
      }
    }
    this->P.swap(points);
    this->T.swap(triangles);
  }

  // Flips an edge when that brings the four vertices' valences closer to 6 and neither new
  // triangle turns over.
  void FlipTowardValenceSix()
  {
    std::vector<int> valence(this->P.size(), 0);
    const std::vector<Edge> edges = this->Edges();
    for (const Edge& edge : edges)
    {
      ++valence[edge.Key >> 32];
      ++valence[edge.Key & 0xffffffffu];
    }
    std::vector<char> locked(this->P.size(), 0);
    for (const Edge& edge : edges)
    {
      const int t0 = edge.Triangle[0], k0 = edge.Corner[0], t1 = edge.Triangle[1], k1 = edge.Corner[1];
      const int a = this->T[t0][k0], b = this->T[t0][(k0 + 1) % 3], c = this->T[t0][(k0 + 2) % 3];
      const int d = this->T[t1][(k1 + 2) % 3];
      if (locked[a] || locked[b] || locked[c] || locked[d] || c == d || HasEdge(edges, Key(c, d)) ||
        valence[a] <= 3 || valence[b] <= 3)
      {
        continue;
      }
      auto deviation = [](int v) { return std::abs(v - 6); };
      const int before = deviation(valence[a]) + deviation(valence[b]) + deviation(valence[c]) + deviation(valence[d]);
      const int after = deviation(valence[a] - 1) + deviation(valence[b] - 1) + deviation(valence[c] + 1) +
        deviation(valence[d] + 1);
      const Tri first{ c, a, d }, second{ d, b, c };
      const Vec n0 = this->Normal(this->T[t0]) + this->Normal(this->T[t1]);
      const Vec n1 = this->Normal(first), n2 = this->Normal(second);
      if (after >= before || n1.dot(n0) <= 0.5 * n1.norm() * n0.norm() ||
        n2.dot(n0) <= 0.5 * n2.norm() * n0.norm())
      {
        continue;
      }
      this->T[t0] = first;
      this->T[t1] = second;
      --valence[a], --valence[b], ++valence[c], ++valence[d];
      locked[a] = locked[b] = locked[c] = locked[d] = 1;
    }
  }

  // Moves each vertex halfway to the area-weighted centroid of its neighbours' triangles, in
  // its tangent plane, then onto the nearest point of the input surface.
  void RelaxAndProject()
  {
    std::vector<Vec> centroid(this->P.size(), Vec::Zero()), normal(this->P.size(), Vec::Zero());
    std::vector<double> weight(this->P.size(), 0.0);
    for (const Tri& t : this->T)
    {
      const Vec n = this->Normal(t);
      const Vec center = (this->P[t[0]] + this->P[t[1]] + this->P[t[2]]) / 3.0;
      for (int v : t)
      {
        centroid[v] += n.norm() * center;
        weight[v] += n.norm();
        normal[v] += n;
      }
    }
    for (size_t v = 0; v < this->P.size(); ++v)
    {
      if (!(weight[v] > 0.0) || !(normal[v].norm() > 0.0))
      {
        continue;
      }
      const Vec n = normal[v].normalized();
      Vec move = centroid[v] / weight[v] - this->P[v];
      move -= n.dot(move) * n;
      this->P[v] = this->Project(this->P[v] + 0.5 * move, this->Home[v]);
    }
  }

  // The point of the input triangle nearest to p (Ericson, Real-Time Collision Detection,
  // 5.1.5: by the region of the triangle's plane p falls in).
  Vec NearestOnTriangle(const Vec& p, int t) const
  {
    const Vec& a = this->InputPoints[this->InputTriangles[t][0]];
    const Vec& b = this->InputPoints[this->InputTriangles[t][1]];
    const Vec& c = this->InputPoints[this->InputTriangles[t][2]];
    const Vec ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0)
      return a;
    const Vec bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3)
      return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
      return a + d1 / (d1 - d3) * ab;
    const Vec cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6)
      return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
      return a + d2 / (d2 - d6) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
      return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
    const double denominator = 1.0 / (va + vb + vc);
    return a + ab * (vb * denominator) + ac * (vc * denominator);
  }

  // The nearest point of the input surface to p, searched by walking from the triangle
  // `home` (where the vertex was last) over triangles sharing a corner: vertices move a
  // fraction of an edge per round, so the walk is short.
  Vec Project(const Vec& p, int& home) const
  {
    Vec best = this->NearestOnTriangle(p, home);
    for (int step = 0; step < 20; ++step)
    {
      int next = home;
      for (int corner : this->InputTriangles[home])
      {
        for (int t : this->InputAround[corner])
        {
          const Vec q = this->NearestOnTriangle(p, t);
          if ((q - p).squaredNorm() < (best - p).squaredNorm())
          {
            best = q;
            next = t;
          }
        }
      }
      if (next == home)
      {
        break;
      }
      home = next;
    }
    return best;
  }

  vtkSmartPointer<vtkPolyData> Output() const
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (const Vec& p : this->P)
    {
      points->InsertNextPoint(p.data());
    }
    vtkNew<vtkCellArray> triangles;
    for (const Tri& t : this->T)
    {
      const vtkIdType ids[3] = { t[0], t[1], t[2] };
      triangles->InsertNextCell(3, ids);
    }
    auto mesh = vtkSmartPointer<vtkPolyData>::New();
    mesh->SetPoints(points);
    mesh->SetPolys(triangles);
    return mesh;
  }

  std::vector<Vec> InputPoints;
  std::vector<Tri> InputTriangles;
  std::vector<std::vector<int>> InputAround;
  std::vector<Vec> P;
  std::vector<Tri> T;
  std::vector<int> Home; // per vertex: the input triangle it was last projected onto
};

/// `surface` isotropically remeshed to about `vertices` vertices.
inline vtkSmartPointer<vtkPolyData> IsotropicallyRemeshed(vtkPolyData* surface, int vertices)
{
  IsotropicRemesher remesher(surface);
  return remesher.Remesh(vertices);
}
}

#endif
