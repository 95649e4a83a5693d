#include "Icosphere.h"

#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace mobius
{
void MakeIcosphere(int levels, Points& points, Triangles& triangles)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> p = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 },
    { 0, -1, t }, { 0, 1, t }, { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 },
    { -t, 0, -1 }, { -t, 0, 1 } };
  for (auto& v : p)
  {
    v.normalize();
  }
  std::vector<std::array<Index, 3>> f = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 },
    { 0, 10, 11 }, { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 },
    { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 },
    { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };

  for (int level = 0; level < levels; ++level)
  {
    // Each edge gets one midpoint vertex, shared by the two triangles of the edge.
    std::map<std::pair<Index, Index>, Index> midpoint;
    auto middle = [&](Index a, Index b) {
      const auto key = std::minmax(a, b);
      auto it = midpoint.find(key);
      if (it != midpoint.end())
      {
        return it->second;
      }
      p.push_back((p[a] + p[b]).normalized());
      const Index id = static_cast<Index>(p.size()) - 1;
      midpoint.emplace(key, id);
      return id;
    };
    std::vector<std::array<Index, 3>> refined;
    refined.reserve(4 * f.size());
    for (const auto& tri : f)
    {
      const Index a = middle(tri[0], tri[1]);
      const Index b = middle(tri[1], tri[2]);
      const Index c = middle(tri[2], tri[0]);
      refined.push_back({ tri[0], a, c });
      refined.push_back({ tri[1], b, a });
      refined.push_back({ tri[2], c, b });
      refined.push_back({ a, b, c });
    }
    f.swap(refined);
  }

  points.resize(static_cast<Eigen::Index>(p.size()), 3);
  for (size_t i = 0; i < p.size(); ++i)
  {
    points.row(static_cast<Eigen::Index>(i)) = p[i].transpose();
  }
  triangles.resize(static_cast<Eigen::Index>(f.size()), 3);
  for (size_t i = 0; i < f.size(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      triangles(static_cast<Eigen::Index>(i), k) = f[i][k];
    }
  }
}

void InsertSliver(const Points& points, const Triangles& triangles, const Eigen::RowVector3d& where,
  Points& withSliver, Triangles& split)
{
  const Index a = triangles(0, 0), b = triangles(0, 1), c = triangles(0, 2), m = points.rows();
  withSliver.resize(m + 1, 3);
  withSliver << points, where;
  split.resize(triangles.rows() + 2, 3);
  split.topRows(triangles.rows() - 1) = triangles.bottomRows(triangles.rows() - 1);
  split.bottomRows(3) << a, m, c, m, b, c, a, b, m;
}
}
