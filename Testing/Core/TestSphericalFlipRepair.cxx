// Repair of folded triangles in a spherical map: a fold made by hand in a map of ordinary
// scale and in a region squeezed to 1e-10 (as conformal maps squeeze limbs) is removed with
// only nearby vertices moved; random folds are never made worse; 0 passes changes nothing.
#include "CoreTest.h"
#include "Icosphere.h"
#include "SphericalFlipRepair.h"

#include <Eigen/Geometry>

#include <random>

using namespace mobius;

namespace
{
// A conformal map of the sphere onto itself that shrinks the neighbourhood of `pole` by
// `scale` (stereographic projection from the antipode, scaled, projected back): no folds, but
// the triangles near the pole become `scale` times smaller.
Points SqueezeToward(const Points& x, const Eigen::Vector3d& pole, double scale)
{
  const Eigen::Vector3d e1 = pole.unitOrthogonal(), e2 = pole.cross(e1);
  Points squeezed(x.rows(), 3);
  for (Index i = 0; i < x.rows(); ++i)
  {
    const Eigen::Vector3d p = x.row(i).transpose();
    const double denominator = 1.0 + p.dot(pole);
    if (denominator < 1e-12)
    {
      squeezed.row(i) = -pole.transpose(); // the antipode stays
      continue;
    }
    const Eigen::Vector2d z = scale * Eigen::Vector2d(p.dot(e1), p.dot(e2)) / denominator;
    const double z2 = z.squaredNorm();
    const Eigen::Vector3d q = (2 * z.x() * e1 + 2 * z.y() * e2 + (1 - z2) * pole) / (1 + z2);
    squeezed.row(i) = q.normalized().transpose();
  }
  return squeezed;
}

Index FirstNeighbour(const Triangles& triangles, Index v)
{
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (triangles(t, k) == v)
      {
        return triangles(t, (k + 1) % 3);
      }
    }
  }
  return -1;
}

bool OnUnitSphere(const Points& x)
{
  return x.allFinite() && ((x.rowwise().norm().array() - 1.0).abs() < 1e-14).all();
}

void TestHandMadeFold(double scale)
{
  Points sphere;
  Triangles triangles;
  MakeIcosphere(3, sphere, triangles);
  const Index v = 100;
  Points x = SqueezeToward(sphere, sphere.row(v).transpose(), scale);
  MOBIUS_CHECK(CountFlippedTriangles(x, triangles) == 0);
  // Push v past its neighbour a: the triangles around v fold over.
  const Index a = FirstNeighbour(triangles, v);
  const Eigen::RowVector3d pushed = x.row(v) + 2.5 * (x.row(a) - x.row(v));
  x.row(v) = pushed.normalized();
  const Points folded = x;
  const FlipRepairResult result = RepairFlippedTriangles(x, triangles);
  std::cout << "scale " << scale << ": " << result.InitialFlips << " folds -> "
            << result.RemainingFlips << ", " << result.MovedVertices << " vertices moved, "
            << result.Passes << " sweeps\n";
  MOBIUS_CHECK(result.InitialFlips >= 2);
  MOBIUS_CHECK(result.RemainingFlips == 0);
  MOBIUS_CHECK(CountFlippedTriangles(x, triangles) == 0);
  MOBIUS_CHECK(OnUnitSphere(x));
  // Local: a few rings around v move (642 vertices in all), and v lands back among its
  // neighbours, at the squeezed region's scale.
  MOBIUS_CHECK(result.MovedVertices >= 1 && result.MovedVertices <= 60);
  MOBIUS_CHECK((x.row(v) - x.row(a)).norm() < 2 * (folded.row(v) - x.row(a)).norm());
  Index moved = 0;
  for (Index i = 0; i < x.rows(); ++i)
  {
    moved += (x.row(i) != folded.row(i)) ? 1 : 0;
  }
  MOBIUS_CHECK(moved == result.MovedVertices);
}

// Random displacements at the size of the squeezed triangles fold about 540 of them. Three
// smoothing sweeps leave 0-2 folds in each trial; kernel placement removes those. Whatever the
// sweeps do, the repair never returns more folds than it was given.
void TestNeverWorse()
{
  Points sphere;
  Triangles triangles;
  MakeIcosphere(3, sphere, triangles);
  std::mt19937 random(7);
  std::normal_distribution<double> gaussian;
  for (int trial = 0; trial < 5; ++trial)
  {
    const Eigen::Vector3d pole = sphere.row(10 * trial).transpose();
    Points x = SqueezeToward(sphere, pole, 1e-9);
    for (Index i = 0; i < x.rows(); ++i)
    {
      const double distance = (x.row(i).transpose() - pole).norm();
      if (distance < 1e-8)
      {
        const Eigen::RowVector3d noise(gaussian(random), gaussian(random), gaussian(random));
        x.row(i) = (x.row(i) + 0.3 * distance * noise).normalized();
      }
    }
    const Index before = CountFlippedTriangles(x, triangles);
    const FlipRepairResult result = RepairFlippedTriangles(x, triangles, 3);
    std::cout << "random folds: " << before << " -> " << result.RemainingFlips << "\n";
    MOBIUS_CHECK(result.InitialFlips == before);
    MOBIUS_CHECK(result.RemainingFlips <= before);
    MOBIUS_CHECK(result.RemainingFlips == 0);
    MOBIUS_CHECK(result.RemainingFlips == CountFlippedTriangles(x, triangles));
    MOBIUS_CHECK(OnUnitSphere(x));
  }
}

void TestNoPassesChangesNothing()
{
  Points x;
  Triangles triangles;
  MakeIcosphere(2, x, triangles);
  x.row(5) = (x.row(5) + 2.0 * (x.row(FirstNeighbour(triangles, 5)) - x.row(5))).normalized();
  const Points folded = x;
  const FlipRepairResult result = RepairFlippedTriangles(x, triangles, 0);
  MOBIUS_CHECK(result.InitialFlips > 0 && result.RemainingFlips == result.InitialFlips);
  MOBIUS_CHECK(x == folded && result.MovedVertices == 0);
}
}

int main()
{
  TestHandMadeFold(1.0);
  TestHandMadeFold(1e-10);
  TestNeverWorse();
  TestNoPassesChangesNothing();
  return mobius_test::Failures() == 0 ? 0 : 1;
}
