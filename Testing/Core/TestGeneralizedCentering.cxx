// Generalized centering: the real harmonics are orthonormal; degree-2 centering zeroes the
// moments of degree 1 and 2 without flipping triangles and spreads area more evenly than
// Möbius centering does (the paper's Figure 5).
#include "BumpySurface.h"
#include "CoreTest.h"
#include "GeneralizedCentering.h"
#include "Icosphere.h"
#include "MobiusCentering.h"

#include <Eigen/Geometry>

#include <cmath>
#include <vector>

using namespace mobius;

namespace
{
// Spread of log(area share on the surface / area share on the sphere) over the triangles.
double LogAreaDistortionDeviation(const Points& sphere, const Triangles& triangles, const Vector& areas)
{
  std::vector<double> logs;
  double sphereTotal = 0;
  Vector sphereAreas(triangles.rows());
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    const Eigen::Vector3d a = sphere.row(triangles(t, 0)), b = sphere.row(triangles(t, 1)),
                          c = sphere.row(triangles(t, 2));
    sphereAreas[t] = 0.5 * (b - a).cross(c - a).norm();
    sphereTotal += sphereAreas[t];
  }
  double mean = 0, squares = 0;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    const double value = std::log((areas[t] / areas.sum()) / (sphereAreas[t] / sphereTotal));
    mean += value / triangles.rows();
    squares += value * value / triangles.rows();
  }
  return std::sqrt(squares - mean * mean);
}

void TestOrthonormality()
{
  // Quadrature on a fine icosphere: the Gram matrix of the 15 harmonics of degree 1..3.
  Points sphere;
  Triangles triangles;
  MakeIcosphere(5, sphere, triangles);
  const int k = 15;
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(k, k);
  std::vector<double> values(k);
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    const Eigen::Vector3d a = sphere.row(triangles(t, 0)), b = sphere.row(triangles(t, 1)),
                          c = sphere.row(triangles(t, 2));
    const double area = 0.5 * (b - a).cross(c - a).norm() * 4 * M_PI / 4.0 / M_PI;
    EvaluateRealSphericalHarmonics(3, (a + b + c).normalized(), values.data());
    const Eigen::Map<const Eigen::VectorXd> v(values.data(), k);
    gram += area * v * v.transpose();
  }
  // The flat icosphere's area is slightly below 4 pi; normalize by it.
  gram /= gram.trace() / k;
  MOBIUS_CHECK((gram - Eigen::MatrixXd::Identity(k, k)).cwiseAbs().maxCoeff() < 2e-3);
  // Degree 1 in this basis is proportional to (y, z, x).
  EvaluateRealSphericalHarmonics(1, Eigen::Vector3d(0, 0, 1), values.data());
  MOBIUS_CHECK_NEAR(values[1], std::sqrt(3 / (4 * M_PI)), 1e-14);
}

void TestDegreeTwoCentering()
{
  Points sphere;
  Triangles triangles;
  MakeIcosphere(4, sphere, triangles);
  const Vector areas = BumpySurfaceAreas(sphere, triangles);
  Points mobius = sphere;
  MobiusCenteringResult mobiusResult;
  MOBIUS_CHECK(CenterSphericalMap(mobius, triangles, areas, {}, mobiusResult));

  Points general = mobius;
  GeneralizedCenteringResult result;
  GeneralizedCenteringParameters parameters;
  parameters.Degree = 2;
  MOBIUS_CHECK(CenterWithSphericalHarmonics(general, triangles, areas, parameters, result));
  std::cout << "degree 2: |mu| " << result.InitialCenterOfMassNorm << " -> " << result.CenterOfMassNorm
            << " in " << result.NumberOfIterations << " steps\n";
  MOBIUS_CHECK(result.Converged);
  MOBIUS_CHECK(result.InitialCenterOfMassNorm > 0.01);
  MOBIUS_CHECK(SphericalHarmonicMoments(general, triangles, areas, 2).norm() <= 1e-8);
  // No triangle flipped, every point on the sphere.
  Index flipped = 0;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    const Eigen::Vector3d a = general.row(triangles(t, 0)), b = general.row(triangles(t, 1)),
                          c = general.row(triangles(t, 2));
    flipped += a.dot((b - a).cross(c - a)) <= 0;
  }
  MOBIUS_CHECK(flipped == 0);
  MOBIUS_CHECK((general.rowwise().norm().array() - 1).abs().maxCoeff() < 1e-12);
  // More even area than the Möbius-centered map.
  const double before = LogAreaDistortionDeviation(mobius, triangles, areas);
  const double after = LogAreaDistortionDeviation(general, triangles, areas);
  std::cout << "log area distortion spread: Moebius " << before << ", degree 2 " << after << "\n";
  MOBIUS_CHECK(after < 0.8 * before);
}
}

int main()
{
  TestOrthonormality();
  TestDegreeTwoCentering();
  return MOBIUS_TEST_RESULT();
}
