// Unit tests of Algorithm 1 (Möbius centering) on generated spherical maps.
#include "BumpySurface.h"
#include "CoreTest.h"
#include "Icosphere.h"
#include "MobiusCentering.h"

#include <Eigen/Dense>

#include <limits>
#include <random>
#include <string>

using namespace mobius;

namespace
{
// Largest distance between R*p and q over all points, for the best rotation R (Kabsch).
double DistanceUpToRotation(const Points& p, const Points& q)
{
  const Eigen::Matrix3d covariance = p.transpose() * q;
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1 : 1;
  const Eigen::Matrix3d rotation = svd.matrixV() * d * svd.matrixU().transpose();
  return ((p * rotation.transpose()) - q).rowwise().norm().maxCoeff();
}

Eigen::Vector3d MirrorSymmetricInX(const Eigen::Vector3d& x)
{
  // f(-x, y, z) = S f(x, y, z) with S the mirror x -> -x.
  return Eigen::Vector3d(x.x() * (1.0 + 0.3 * x.y()), x.y() + 0.5 * x.z() * x.z(), 2.0 * x.z());
}

void TestRecoversOriginalAfterRandomInversion()
{
  Points sphere;
  Triangles triangles;
  MakeIcosphere(4, sphere, triangles);
  // The icosphere's own areas: icosahedral symmetry makes mu exactly zero, so the
  // original map is already centered.
  const Vector areas = EmbeddedTriangleAreas(sphere, triangles, [](const Eigen::Vector3d& x) { return x; });
  MOBIUS_CHECK(SphericalCenterOfMass(sphere, triangles, areas).norm() < 1e-14);

  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 5; ++trial)
  {
    Eigen::Vector3d c(normal(random), normal(random), normal(random));
    c *= (0.3 + 0.15 * trial) / c.norm(); // |c| from 0.3 to 0.9
    Points moved = sphere;
    ApplyInversion(c, moved);
    MOBIUS_CHECK(SphericalCenterOfMass(moved, triangles, areas).norm() > 0.1);

    Points centered = moved;
    MobiusCenteringResult result;
    MOBIUS_CHECK(CenterSphericalMap(centered, triangles, areas, {}, result));
    MOBIUS_CHECK(result.Converged);
    MOBIUS_CHECK(result.CenterOfMassNorm <= 1e-10);
    MOBIUS_CHECK(result.NumberOfIterations <= 10);
    MOBIUS_CHECK(DistanceUpToRotation(centered, sphere) < 1e-7);

    // The returned Lorentz matrix reproduces the centered map from the input map.
    double lorentzError = 0;
    for (Eigen::Index i = 0; i < moved.rows(); ++i)
    {
      const Eigen::Vector3d image = ApplyLorentzTransform(result.LorentzTransform, moved.row(i));
      lorentzError = std::max(lorentzError, (image - centered.row(i).transpose()).norm());
    }
    MOBIUS_CHECK(lorentzError < 1e-9);
  }
}

void TestStartingInversionDoesNotMatter()
{
  Points sphere;
  Triangles triangles;
  MakeIcosphere(4, sphere, triangles);
  const Vector areas = BumpySurfaceAreas(sphere, triangles);

  Points first = sphere;
  ApplyInversion(Eigen::Vector3d(0.5, -0.2, 0.3), first);
  Points second = sphere;
  ApplyInversion(Eigen::Vector3d(-0.3, 0.6, -0.4), second);

  MobiusCenteringResult result;
  MOBIUS_CHECK(CenterSphericalMap(first, triangles, areas, {}, result));
  MOBIUS_CHECK(result.CenterOfMassNorm <= 1e-10);
  MOBIUS_CHECK(CenterSphericalMap(second, triangles, areas, {}, result));
  MOBIUS_CHECK(result.CenterOfMassNorm <= 1e-10);
  // The bumpy areas are far from centered on the sphere, so the centered map is a real
  // Möbius transformation away from the identity, yet both starts end at the same map.
  MOBIUS_CHECK(DistanceUpToRotation(first, sphere) > 0.05);
  MOBIUS_CHECK(DistanceUpToRotation(first, second) < 1e-7);
}

void TestMirrorSymmetryIsKept()
{
  Points sphere;
  Triangles triangles;
  MakeIcosphere(4, sphere, triangles);
  const Vector areas = EmbeddedTriangleAreas(sphere, triangles, MirrorSymmetricInX);

  // Pair every vertex with its mirror image under x -> -x.
  std::vector<Eigen::Index> mirror(sphere.rows(), -1);
  for (Eigen::Index i = 0; i < sphere.rows(); ++i)
  {
    const Eigen::Vector3d reflected(-sphere(i, 0), sphere(i, 1), sphere(i, 2));
    for (Eigen::Index j = 0; j < sphere.rows(); ++j)
    {
      if ((sphere.row(j).transpose() - reflected).norm() < 1e-12)
      {
        mirror[i] = j;
      }
    }
    MOBIUS_CHECK(mirror[i] >= 0);
  }

  // An inversion whose center lies in the mirror plane keeps the map symmetric while
  // moving it far from centered.
  Points centered = sphere;
  ApplyInversion(Eigen::Vector3d(0.0, 0.4, -0.3), centered);
  MobiusCenteringResult result;
  MOBIUS_CHECK(CenterSphericalMap(centered, triangles, areas, {}, result));
  MOBIUS_CHECK(result.CenterOfMassNorm <= 1e-10);
  MOBIUS_CHECK(result.InitialCenterOfMassNorm > 0.2);
  double asymmetry = 0;
  for (Eigen::Index i = 0; i < sphere.rows(); ++i)
  {
    const Eigen::Vector3d reflected(-centered(i, 0), centered(i, 1), centered(i, 2));
    asymmetry = std::max(asymmetry, (centered.row(mirror[i]).transpose() - reflected).norm());
  }
  MOBIUS_CHECK(asymmetry < 1e-9);
}

void TestPointSet()
{
  // Points crowded around +z: a point set is centered with unit weights.
  std::mt19937 random(3);
  std::normal_distribution<double> normal;
  Points points(500, 3);
  for (Eigen::Index i = 0; i < points.rows(); ++i)
  {
    Eigen::Vector3d p(normal(random), normal(random), normal(random));
    p.normalize();
    p.z() = std::abs(p.z()) + 0.5;
    points.row(i) = p.normalized();
  }
  MobiusCenteringResult result;
  MOBIUS_CHECK(CenterSphericalMap(points, Triangles(), Vector(), {}, result));
  MOBIUS_CHECK(result.InitialCenterOfMassNorm > 0.5);
  MOBIUS_CHECK(result.CenterOfMassNorm <= 1e-10);
  MOBIUS_CHECK(points.colwise().mean().norm() <= 1e-10);
}

void ExpectFailure(Points points, const Triangles& triangles, const Vector& areas,
  const std::string& expectedWords)
{
  const Points before = points;
  MobiusCenteringResult result;
  MOBIUS_CHECK(!CenterSphericalMap(points, triangles, areas, {}, result));
  if (result.Error.find(expectedWords) == std::string::npos)
  {
    std::cerr << "error message '" << result.Error << "' lacks '" << expectedWords << "'\n";
    ++mobius_test::Failures();
  }
  // Nothing is modified on failure (NaN compares unequal to itself, hence the second test).
  MOBIUS_CHECK((points.array() == before.array() || (points.array().isNaN() && before.array().isNaN())).all());
}

void TestBadInput()
{
  Points sphere;
  Triangles triangles;
  MakeIcosphere(1, sphere, triangles);
  const Vector areas = Vector::Ones(triangles.rows());

  ExpectFailure(Points(), Triangles(), Vector(), "no points");
  Points offSphere = sphere;
  offSphere.row(3) *= 1.01;
  ExpectFailure(offSphere, triangles, areas, "not on the unit sphere");
  Points withNaN = sphere;
  withNaN(5, 1) = std::nan("");
  ExpectFailure(withNaN, triangles, areas, "NaN");
  Vector negative = areas;
  negative[2] = -1;
  ExpectFailure(sphere, triangles, negative, "invalid area");
  ExpectFailure(sphere, triangles, Vector::Ones(3), "one area per triangle");
  ExpectFailure(sphere, triangles, Vector::Zero(triangles.rows()), "no area");
  Vector infinite = areas;
  infinite[0] = std::numeric_limits<double>::infinity();
  ExpectFailure(sphere, triangles, infinite, "invalid area");
}
}

int main()
{
  TestRecoversOriginalAfterRandomInversion();
  TestStartingInversionDoesNotMatter();
  TestMirrorSymmetryIsKept();
  TestPointSet();
  TestBadInput();
  return MOBIUS_TEST_RESULT();
}
