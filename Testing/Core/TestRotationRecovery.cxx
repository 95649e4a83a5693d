// Rotational alignment through the real pipeline: a centered spherical map of an asymmetric
// surface, and copies of it whose points are rotated (or mirrored and rotated) by known
// transforms, each rasterized on its own by ComputeScaleFactorSignal (exact area rasterization,
// forward SHT, heat smoothing at the defaults, N = 256). The grid is not rotation invariant, so
// the copies' signals differ from the rotated source signal by rasterization error; the
// correlation must still return the transform to a small fraction of a degree:
// median <= 0.05 deg and max <= 0.2 deg for 20 random rotations (RotationsOnly) and for 20
// mirrored copies (ReflectionsOnly), each plus rotations with degenerate Euler angles, and mode
// Both must pick the right determinant.
#include "BumpySurface.h"
#include "CoreTest.h"
#include "Icosphere.h"
#include "MobiusCentering.h"
#include "Rotation.h"
#include "SO3Correlation.h"
#include "ScaleFactorSignal.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace mobius;

namespace
{
const int Resolution = 256;

std::mt19937 Random(20180704);

Eigen::Matrix3d RandomRotation()
{
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(Random), normal(Random), normal(Random), normal(Random));
  return q.normalized().toRotationMatrix();
}

struct SphericalMap
{
  Points Sphere;
  Triangles Faces;
  Vector Areas;
};

// The icosphere as the conformal map of the bumpy surface (BumpySurface.h),
// centered by Algorithm 1.
SphericalMap MakeCenteredMap()
{
  SphericalMap map;
  MakeIcosphere(5, map.Sphere, map.Faces);
  map.Areas = BumpySurfaceAreas(map.Sphere, map.Faces);
  MobiusCenteringResult centering;
  MOBIUS_CHECK(CenterSphericalMap(map.Sphere, map.Faces, map.Areas, {}, centering));
  MOBIUS_CHECK(centering.Converged);
  return map;
}

// The map with every point moved by `transform` (orthogonal). A reflection reverses the
// triangles' orientation, so their vertex order is flipped to keep them facing outward.
SphericalMap TransformMap(const SphericalMap& map, const Eigen::Matrix3d& transform)
{
  SphericalMap moved = map;
  moved.Sphere = map.Sphere * transform.transpose();
  if (transform.determinant() < 0)
  {
    moved.Faces.col(1) = map.Faces.col(2);
    moved.Faces.col(2) = map.Faces.col(1);
  }
  return moved;
}

SphericalHarmonicCoefficients Signal(const SphericalMap& map)
{
  ScaleFactorSignalParameters parameters; // defaults: sqrt area ratio, t = 5e-4
  parameters.Resolution = Resolution;
  ScaleFactorSignal signal;
  std::string error;
  const bool ok =
    ComputeScaleFactorSignal(map.Sphere, map.Faces, map.Areas, parameters, false, signal, error);
  if (!ok)
  {
    std::cerr << "ComputeScaleFactorSignal: " << error << std::endl;
  }
  MOBIUS_CHECK(ok);
  return signal.Coefficients;
}

const char* ModeName(SO3ReflectionMode mode)
{
  switch (mode)
  {
    case SO3ReflectionMode::RotationsOnly:
      return "RotationsOnly";
    case SO3ReflectionMode::ReflectionsOnly:
      return "ReflectionsOnly";
    default:
      return "Both";
  }
}

// Registers the source signal with copies of the map moved by `truths`; checks the error bounds.
void TestRecovery(const SphericalMap& map, const SphericalHarmonicCoefficients& source,
  const std::vector<Eigen::Matrix3d>& truths, SO3ReflectionMode mode, double medianBound,
  double maximumBound)
{
  SO3CorrelationOptions options; // defaults otherwise
  options.Reflections = mode;
  std::vector<double> errors;
  int wrongDeterminant = 0;
  double correlationSeconds = 0;
  double worstRegistrationError = 0;
  int bandwidth = 0;
  int refinementBandwidth = 0;
  for (const Eigen::Matrix3d& truth : truths)
  {
    const SphericalHarmonicCoefficients target = Signal(TransformMap(map, truth));
    const auto start = std::chrono::steady_clock::now();
    const SO3CorrelationResult result = CorrelateOverRotations(source, target, options);
    correlationSeconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    MOBIUS_CHECK(!result.Candidates.empty());
    if (result.Candidates.empty())
    {
      continue;
    }
    bandwidth = result.CorrelationBandwidth;
    refinementBandwidth = result.RefinementBandwidth;
    MOBIUS_CHECK(std::abs(result.Transform.determinant() - result.Determinant) < 1e-12);
    const Eigen::Vector3d e = result.EulerAngles;
    MOBIUS_CHECK(
      (result.Determinant * EulerZYZToMatrix(e[0], e[1], e[2]) - result.Transform).norm() < 1e-12);
    if (result.Determinant * truth.determinant() < 0)
    {
      ++wrongDeterminant;
      errors.push_back(180.0);
      continue;
    }
    worstRegistrationError = std::max(worstRegistrationError, result.RegistrationError);
    errors.push_back(RotationAngleBetween(result.Transform, truth) * 180.0 / M_PI);
  }
  std::vector<double> sorted = errors;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  const double median = n ? 0.5 * (sorted[(n - 1) / 2] + sorted[n / 2]) : 180.0;
  const double maximum = n ? sorted.back() : 180.0;
  const bool mirrored = truths.front().determinant() < 0;
  std::cout << truths.size() << (mirrored ? " mirrored" : " rotated") << " copies, mode "
            << ModeName(mode) << ", N = " << Resolution << ", B' = " << bandwidth
            << ", B'' = " << refinementBandwidth << ": angular error median " << median
            << " deg, max " << maximum << " deg, wrong determinant " << wrongDeterminant
            << ", worst registration error " << worstRegistrationError
            << ", mean correlation time " << correlationSeconds / truths.size() << " s"
            << std::endl;
  std::cout << "  errors (deg):";
  for (double error : errors)
  {
    std::cout << " " << error;
  }
  std::cout << std::endl;
  MOBIUS_CHECK(median <= medianBound);
  MOBIUS_CHECK(maximum <= maximumBound);
  MOBIUS_CHECK(wrongDeterminant == 0);
  // Rasterization differences leave a small residual; a wrong peak would leave a large one.
  MOBIUS_CHECK(worstRegistrationError < 1e-3);
}
}

int main()
{
  const auto start = std::chrono::steady_clock::now();
  const SphericalMap map = MakeCenteredMap();
  const SphericalHarmonicCoefficients source = Signal(map);
  const Eigen::Matrix3d mirror = Eigen::Vector3d(-1, 1, 1).asDiagonal();

  // 20 random rotations, plus two whose Euler angles are (nearly) degenerate (β near 0 and π),
  // where the refinement's Euler chart is singular.
  std::vector<Eigen::Matrix3d> rotations;
  for (int i = 0; i < 20; ++i)
  {
    rotations.push_back(RandomRotation());
  }
  rotations.push_back(EulerZYZToMatrix(0.7, 2e-3, 2.1));
  rotations.push_back(EulerZYZToMatrix(4.0, M_PI - 1e-3, 1.3));
  TestRecovery(map, source, rotations, SO3ReflectionMode::RotationsOnly, 0.05, 0.2);

  // Mirrored copies: x -> -x, then a random rotation; the truth R·diag(-1, 1, 1) has det -1.
  std::vector<Eigen::Matrix3d> reflections;
  for (int i = 0; i < 20; ++i)
  {
    reflections.push_back(RandomRotation() * mirror);
  }
  reflections.push_back(EulerZYZToMatrix(2.5, 1e-3, 0.4) * mirror);
  TestRecovery(map, source, reflections, SO3ReflectionMode::ReflectionsOnly, 0.05, 0.2);

  // Mode Both must choose the determinant by itself.
  std::vector<Eigen::Matrix3d> rotatedBoth, mirroredBoth;
  for (int i = 0; i < 3; ++i)
  {
    rotatedBoth.push_back(RandomRotation());
    mirroredBoth.push_back(RandomRotation() * mirror);
  }
  TestRecovery(map, source, rotatedBoth, SO3ReflectionMode::Both, 0.05, 0.2);
  TestRecovery(map, source, mirroredBoth, SO3ReflectionMode::Both, 0.05, 0.2);

  std::cout << "total " << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
            << " s" << std::endl;
  return MOBIUS_TEST_RESULT();
}
