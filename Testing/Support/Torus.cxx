#include "Torus.h"

#include <cmath>

namespace mobius
{
void MakeTorus(int n, int m, double major, double minor, Points& points, Triangles& triangles)
{
  const double pi = std::acos(-1.0);
  points.resize(static_cast<Eigen::Index>(n) * m, 3);
  triangles.resize(2 * static_cast<Eigen::Index>(n) * m, 3);
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < m; ++j)
    {
      const double u = 2 * pi * i / n, v = 2 * pi * j / m;
      const Index a = i * m + j, b = ((i + 1) % n) * m + j, c = ((i + 1) % n) * m + (j + 1) % m,
                  d = i * m + (j + 1) % m;
      points.row(a) << (major + minor * std::cos(v)) * std::cos(u),
        (major + minor * std::cos(v)) * std::sin(u), minor * std::sin(v);
      triangles.row(2 * a) << a, b, c;
      triangles.row(2 * a + 1) << a, c, d;
    }
  }
}
}
