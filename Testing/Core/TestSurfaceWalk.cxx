// Closest points on triangles and walks on a mesh: against a brute-force search over
// barycentric coordinates, on regular triangles and on degenerate ones (two corners at one
// position, three, three on a line), which must give finite weights on the segment or point
// the triangle is; a walk over an icosphere ends at the closest triangle of the whole mesh.
#include "CoreTest.h"
#include "Icosphere.h"
#include "MeshAdjacency.h"
#include "SurfaceWalk.h"

#include <iostream>
#include <random>

using namespace mobius;

namespace
{
// The least squared distance from q to a point of triangle abc on a fine barycentric grid.
double GridDistance(const Eigen::Vector3d& q, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
  const Eigen::Vector3d& c)
{
  constexpr int steps = 400;
  double best = 1e300;
  for (int i = 0; i <= steps; ++i)
  {
    for (int j = 0; i + j <= steps; ++j)
    {
      const double u = double(i) / steps, v = double(j) / steps;
      best = std::min(best, ((1 - u - v) * a + u * b + v * c - q).squaredNorm());
    }
  }
  return best;
}

void CheckTriangle(const char* what, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
  const Eigen::Vector3d& c, std::mt19937& random)
{
  std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
  int wrong = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    const Eigen::Vector3d q(coordinate(random), coordinate(random), coordinate(random));
    Eigen::Vector3d weights;
    const double d2 = ClosestOnTriangle(q, a, b, c, weights);
    const Eigen::Vector3d point = weights[0] * a + weights[1] * b + weights[2] * c;
    const bool valid = weights.allFinite() && weights.minCoeff() >= -1e-12 &&
      std::abs(weights.sum() - 1) < 1e-12 && std::abs((point - q).squaredNorm() - d2) < 1e-9;
    // The grid's best is at most a grid step off the true closest point.
    const bool closest = d2 <= GridDistance(q, a, b, c) + 1e-9;
    wrong += !(valid && closest);
  }
  std::cout << what << ": " << wrong << " of 200 queries wrong\n";
  MOBIUS_CHECK(wrong == 0);
}

void TestClosestOnTriangle()
{
  std::mt19937 random(20181);
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0.3, 0.8, 0.1), d(2, 0, 0);
  CheckTriangle("regular", a, b, c, random);
  CheckTriangle("obtuse", a, d, c, random);
  CheckTriangle("corners 0 and 1 at one position", a, a, c, random);
  CheckTriangle("corners 1 and 2 at one position", a, c, c, random);
  CheckTriangle("corners 0 and 2 at one position", c, a, c, random);
  CheckTriangle("all corners at one position", c, c, c, random);
  CheckTriangle("corners on a line", a, b, d, random);
}

void TestWalk()
{
  Points points;
  Triangles triangles;
  MakeIcosphere(3, points, triangles);
  const VertexLists corners = VertexTriangles(points.rows(), triangles);
  const SurfaceWalker walker{ points, triangles, corners };
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  int wrong = 0, quickWrong = 0;
  double quickWorst = 0;
  for (int trial = 0; trial < 100; ++trial)
  {
    const Eigen::Vector3d q =
      1.05 * Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized();
    double best = 1e300;
    for (Index t = 0; t < triangles.rows(); ++t)
    {
      Eigen::Vector3d weights;
      best = std::min(best, walker.Closest(q, t, weights));
    }
    // From a triangle of some unrelated vertex (the distance has one minimum on a sphere).
    Index t = corners.Items[corners.Begin(trial % points.rows())];
    Eigen::Vector3d weights;
    const double walked = walker.Walk(q, t, weights);
    wrong += std::abs(walked - best) > 1e-12 ||
      std::abs((walker.Point(t, weights) - q).squaredNorm() - walked) > 1e-12;
    // The local walk from the same far triangle: over corners and across edges to a
    // triangle q projects inside, which on this convex mesh is the closest one or next to
    // it (a second-order difference).
    Index quick = corners.Items[corners.Begin(trial % points.rows())];
    const double quickWalked = walker.Walk(q, quick, weights, true);
    quickWrong += std::abs((walker.Point(quick, weights) - q).squaredNorm() - quickWalked) > 1e-12;
    quickWorst = std::max(quickWorst, std::sqrt(quickWalked) - std::sqrt(best));
  }
  std::cout << "walks: " << wrong << " of 100 did not end at the closest point\n";
  MOBIUS_CHECK(wrong == 0);
  // Edges of the level-3 icosphere are about 0.15 long.
  std::cout << "local walks: " << quickWrong << " of 100 inconsistent, farthest "
            << quickWorst << " beyond the closest distance\n";
  MOBIUS_CHECK(quickWrong == 0 && quickWorst < 1e-3);
}
}

int main()
{
  TestClosestOnTriangle();
  TestWalk();
  return MOBIUS_TEST_RESULT();
}
