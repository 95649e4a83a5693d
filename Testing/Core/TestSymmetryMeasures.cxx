// Symmetry measures: the correlation coefficient of the SO(3) correlation ignores the
// signals' means and sizes, the symmetry distance of a mirror-symmetric function under its
// best reflection is 0 and the reflection's plane is the mirror plane, a function without
// the symmetry is farther; the mirror plane and twist of composed reflections; the
// asymmetry of an exact involution is 0 and of a perturbed one is not.
#include "CoreTest.h"
#include "CotangentLaplacian.h"
#include "Icosphere.h"
#include "SO3Correlation.h"
#include "SphericalHarmonics.h"
#include "SymmetryMeasures.h"

#include <Eigen/Geometry>

#include <cmath>
#include <random>

namespace
{
std::mt19937 Random(73);

// A real band-limited function; with `mirrorZ`, even under z -> -z (Y_lm(pi - theta, phi)
// = (-1)^(l+m) Y_lm(theta, phi), so only l + m even remain).
mobius::SphericalHarmonicCoefficients RandomFunction(int bandwidth, bool mirrorZ)
{
  std::normal_distribution<double> normal;
  mobius::SphericalHarmonicCoefficients c;
  c.Resize(bandwidth);
  for (int l = 0; l < bandwidth; ++l)
  {
    const double a = 1.0 / (1.0 + l * l);
    for (int m = 0; m <= l; ++m)
    {
      if (mirrorZ && (l + m) % 2 != 0)
      {
        continue;
      }
      if (m == 0)
      {
        c(l, 0) = a * normal(Random);
        continue;
      }
      c(l, m) = a * std::complex<double>(normal(Random), normal(Random)) / std::sqrt(2.0);
      c(l, -m) = ((m & 1) ? -1.0 : 1.0) * std::conj(c(l, m));
    }
  }
  return c;
}

void TestCorrelationCoefficient()
{
  // g = 3 + 2 f correlates perfectly with f; the score and registration error do not say so.
  const auto f = RandomFunction(16, false);
  auto g = f;
  for (auto& value : g.Values)
  {
    value *= 2.0;
  }
  g(0, 0) += 3.0 * std::sqrt(4.0 * M_PI);
  mobius::SO3CorrelationOptions options;
  options.NumberOfCandidates = 1;
  const auto result = mobius::CorrelateOverRotations(f, g, options);
  MOBIUS_CHECK_NEAR(result.CorrelationCoefficient, 1.0, 1e-9);
  MOBIUS_CHECK((result.Transform - Eigen::Matrix3d::Identity()).norm() < 1e-6);
  MOBIUS_CHECK(result.RegistrationError > 0.1);
}

void TestSymmetryDistance()
{
  MOBIUS_CHECK_NEAR(mobius::SymmetryDistance(1.0), 0.0, 1e-15);
  MOBIUS_CHECK_NEAR(mobius::SymmetryDistance(0.0), std::sqrt(0.5), 1e-15);
  MOBIUS_CHECK_NEAR(mobius::SymmetryDistance(-1.0), 1.0, 1e-15);
  MOBIUS_CHECK_NEAR(mobius::SymmetryDistance(1.5), 0.0, 1e-15); // clamped

  mobius::SO3CorrelationOptions options;
  options.Reflections = mobius::SO3ReflectionMode::ReflectionsOnly;
  const auto symmetric = RandomFunction(16, true);
  const auto best = mobius::CorrelateOverRotations(symmetric, symmetric, options);
  const double distance = mobius::SymmetryDistance(best.CorrelationCoefficient);
  MOBIUS_CHECK(best.Determinant < 0);
  MOBIUS_CHECK_NEAR(distance, 0.0, 1e-5);
  const mobius::MirrorPlane plane = mobius::MirrorPlaneOf(best.Transform);
  MOBIUS_CHECK_NEAR(plane.Normal.z(), 1.0, 1e-6);
  MOBIUS_CHECK_NEAR(plane.Twist, 0.0, 1e-3);

  const auto generic = RandomFunction(16, false);
  const auto other = mobius::CorrelateOverRotations(generic, generic, options);
  MOBIUS_CHECK(mobius::SymmetryDistance(other.CorrelationCoefficient) > 0.05);
}

void TestMirrorPlane()
{
  const Eigen::Vector3d n = Eigen::Vector3d(1, -2, 0.5).normalized();
  const Eigen::Matrix3d pure = Eigen::Matrix3d::Identity() - 2 * n * n.transpose();
  const Eigen::Matrix3d twisted = Eigen::AngleAxisd(0.4, n).toRotationMatrix() * pure;
  for (const Eigen::Matrix3d& t : { pure, twisted })
  {
    const mobius::MirrorPlane plane = mobius::MirrorPlaneOf(t);
    MOBIUS_CHECK_NEAR(std::abs(plane.Normal.dot(n)), 1.0, 1e-12);
    MOBIUS_CHECK(plane.Normal(1) > 0); // sign: the largest component (-2) made positive
  }
  MOBIUS_CHECK_NEAR(mobius::MirrorPlaneOf(pure).Twist, 0.0, 1e-7);
  MOBIUS_CHECK_NEAR(mobius::MirrorPlaneOf(twisted).Twist, 0.4, 1e-9);
}

void TestAsymmetry()
{
  // An icosphere is symmetric under z -> -z: send each vertex to its partner (a corner of
  // one of its triangles, barycentric (1, 0, 0)).
  mobius::Points points;
  mobius::Triangles triangles;
  mobius::MakeIcosphere(2, points, triangles);
  const mobius::Index n = points.rows();
  std::vector<mobius::Index> triangle(n);
  std::vector<Eigen::Vector3d> barycentric(n);
  mobius::Points mirror(n, 3);
  for (mobius::Index v = 0; v < n; ++v)
  {
    Eigen::Vector3d target = points.row(v).transpose();
    target.z() = -target.z();
    mobius::Index partner = 0;
    (points.rowwise() - target.transpose()).rowwise().squaredNorm().minCoeff(&partner);
    for (mobius::Index t = 0; t < triangles.rows(); ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        if (triangles(t, k) == partner)
        {
          triangle[v] = t;
          barycentric[v] = Eigen::Vector3d::Unit(k);
        }
      }
    }
    mirror.row(v) = points.row(partner);
  }
  const mobius::Vector exact =
    mobius::MirrorAsymmetry(points, triangles, triangle, barycentric, mirror);
  MOBIUS_CHECK(exact.maxCoeff() < 1e-9);
  // Every image moved a little towards +x along its triangle: no longer an involution.
  for (mobius::Index v = 0; v < n; ++v)
  {
    barycentric[v] = 0.8 * barycentric[v] + Eigen::Vector3d::Constant(0.2 / 3);
    mirror.row(v).setZero();
    for (int k = 0; k < 3; ++k)
    {
      mirror.row(v) += barycentric[v][k] * points.row(triangles(triangle[v], k));
    }
  }
  const mobius::Vector perturbed =
    mobius::MirrorAsymmetry(points, triangles, triangle, barycentric, mirror);
  MOBIUS_CHECK(perturbed.mean() > 1e-3);
  // Over sqrt(area): a copy scaled by 3 has the same relative asymmetry.
  const mobius::Points scaled = 3.0 * points;
  const mobius::Vector relative = mobius::RelativeMirrorAsymmetry(scaled, triangles,
    mobius::TriangleAreas(scaled, triangles), triangle, barycentric, 3.0 * mirror);
  const double area = mobius::TriangleAreas(points, triangles).sum();
  MOBIUS_CHECK_NEAR(relative.mean(), perturbed.mean() / std::sqrt(area), 1e-12);
}

void TestMirrorCandidates()
{
  // Two reflections, best first: the distances from the coefficients, the planes and the
  // best one's reflection.
  const Eigen::Vector3d n = Eigen::Vector3d(0, 0, 1), m = Eigen::Vector3d(0, 1, 0);
  const Eigen::Matrix3d first = Eigen::Matrix3d::Identity() - 2 * n * n.transpose();
  const Eigen::Matrix3d second = Eigen::Matrix3d::Identity() - 2 * m * m.transpose();
  mobius::MirrorCandidates candidates;
  MOBIUS_CHECK(mobius::DescribeMirrorCandidates({ first, second }, { 1.0, 0.0 }, candidates).empty());
  MOBIUS_CHECK(candidates.Distances.size() == 2 && candidates.Normals.size() == 6);
  MOBIUS_CHECK_NEAR(candidates.Distances[0], 0.0, 1e-15);
  MOBIUS_CHECK_NEAR(candidates.Distances[1], std::sqrt(0.5), 1e-15);
  MOBIUS_CHECK_NEAR(candidates.Normals[2], 1.0, 1e-12);
  MOBIUS_CHECK_NEAR(candidates.Normals[4], 1.0, 1e-12);
  MOBIUS_CHECK(candidates.Best == first);
  MOBIUS_CHECK_NEAR(candidates.BestPlane.Normal.z(), 1.0, 1e-12);
  // None, or a coefficient missing: the problem named.
  MOBIUS_CHECK(mobius::DescribeMirrorCandidates({}, {}, candidates).find("no candidates") !=
    std::string::npos);
  MOBIUS_CHECK(!mobius::DescribeMirrorCandidates({ first, second }, { 1.0 }, candidates).empty());
}
}

int main()
{
  TestCorrelationCoefficient();
  TestSymmetryDistance();
  TestMirrorPlane();
  TestAsymmetry();
  TestMirrorCandidates();
  return MOBIUS_TEST_RESULT();
}
