// SO(3) correlation: Euler/matrix conventions on points, rotation of harmonic coefficients
// against pointwise evaluation of f(R⁻¹x), the fast grid and the Fourier-tensor evaluation
// (with derivatives) against the direct Wigner-D sum, and recovery of random rotations and
// reflections of a random smooth band-limited function to a small fraction of a degree.
#include "CoreTest.h"
#include "CorrelationChecks.h"
#include "Rotation.h"
#include "SO3Correlation.h"
#include "SO3CorrelationTensor.h"
#include "SphericalHarmonicSeries.h"
#include "SphericalHarmonics.h"

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <vector>

namespace
{
std::mt19937 Random(2018);

double Uniform(double low, double high)
{
  return std::uniform_real_distribution<double>(low, high)(Random);
}

// Uniformly distributed random rotation (normalized Gaussian quaternion).
Eigen::Matrix3d RandomRotation()
{
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(Random), normal(Random), normal(Random), normal(Random));
  return q.normalized().toRotationMatrix();
}

// Coefficients of a real function: random Gaussian bands with amplitude decay `decay(l)`.
template <typename Decay>
mobius::SphericalHarmonicCoefficients RandomRealFunction(int bandwidth, Decay decay)
{
  std::normal_distribution<double> normal;
  mobius::SphericalHarmonicCoefficients c;
  c.Resize(bandwidth);
  for (int l = 0; l < bandwidth; ++l)
  {
    const double a = decay(l);
    c(l, 0) = a * normal(Random);
    for (int m = 1; m <= l; ++m)
    {
      c(l, m) = a * std::complex<double>(normal(Random), normal(Random)) / std::sqrt(2.0);
      c(l, -m) = ((m & 1) ? -1.0 : 1.0) * std::conj(c(l, m));
    }
  }
  return c;
}

Eigen::Vector3d Direction(double theta, double phi)
{
  return { std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta) };
}

double Evaluate(const mobius::SphericalHarmonicCoefficients& c, const Eigen::Vector3d& x)
{
  return mobius::EvaluateSphericalHarmonicSeries(c, std::acos(std::clamp(x.z(), -1.0, 1.0)),
    std::atan2(x.y(), x.x()))
    .real();
}

void TestEulerConventions()
{
  // Rz, Ry are right-handed; R = Rz(α) Ry(β) Rz(γ) applies Rz(γ) first.
  const double a = 0.3, b = 1.1, g = -2.0;
  MOBIUS_CHECK(
    (mobius::RotationAboutZ(a) * Eigen::Vector3d::UnitX() - Eigen::Vector3d(std::cos(a), std::sin(a), 0))
      .norm() < 1e-15);
  MOBIUS_CHECK(
    (mobius::RotationAboutY(b) * Eigen::Vector3d::UnitZ() - Eigen::Vector3d(std::sin(b), 0, std::cos(b)))
      .norm() < 1e-15);
  const Eigen::Vector3d p(0.2, -0.7, 0.4);
  const Eigen::Vector3d sequential =
    mobius::RotationAboutZ(a) * (mobius::RotationAboutY(b) * (mobius::RotationAboutZ(g) * p));
  MOBIUS_CHECK((mobius::EulerZYZToMatrix(a, b, g) * p - sequential).norm() < 1e-15);
  // Round trips, including the degenerate β = 0 and β = π.
  double worst = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    Eigen::Matrix3d r = RandomRotation();
    if (trial == 0)
    {
      r = mobius::EulerZYZToMatrix(0.4, 0.0, 0.9);
    }
    if (trial == 1)
    {
      r = mobius::EulerZYZToMatrix(0.4, M_PI, 0.9);
    }
    const Eigen::Vector3d e = mobius::MatrixToEulerZYZ(r);
    MOBIUS_CHECK(e[1] >= 0 && e[1] <= M_PI && e[0] >= 0 && e[0] < 2 * M_PI && e[2] >= 0 &&
      e[2] < 2 * M_PI);
    worst = std::max(worst, (mobius::EulerZYZToMatrix(e[0], e[1], e[2]) - r).norm());
  }
  std::cout << "Euler round trip: " << worst << std::endl;
  MOBIUS_CHECK(worst < 1e-12);
  const Eigen::Matrix3d r = RandomRotation();
  MOBIUS_CHECK_NEAR(
    mobius::RotationAngleBetween(r * mobius::RotationAboutZ(0.25), r), 0.25, 1e-14);
}

void TestCoefficientRotation()
{
  const int B = 14;
  const auto f = RandomRealFunction(B, [](int) { return 1.0; });
  double worst = 0;
  double scale = 0;
  for (int trial = 0; trial < 6; ++trial)
  {
    Eigen::Matrix3d t = RandomRotation();
    if (trial % 2 == 1)
    {
      t = -t; // det -1: antipodal map, then rotation
    }
    mobius::SphericalHarmonicCoefficients rotated;
    mobius::RotateCoefficients(f, t, rotated);
    for (int point = 0; point < 40; ++point)
    {
      const Eigen::Vector3d x = Direction(std::acos(Uniform(-1, 1)), Uniform(-M_PI, M_PI));
      const double expected = Evaluate(f, t.transpose() * x); // T⁻¹ = Tᵀ
      worst = std::max(worst, std::abs(Evaluate(rotated, x) - expected));
      scale = std::max(scale, std::abs(expected));
      // Real functions stay real.
      const std::complex<double> value = mobius::EvaluateSphericalHarmonicSeries(rotated,
        std::acos(x.z()), std::atan2(x.y(), x.x()));
      MOBIUS_CHECK(std::abs(value.imag()) < 1e-10 * scale + 1e-12);
    }
  }
  std::cout << "rotated coefficients vs f(T^-1 x): " << worst << " (max |f| " << scale << ")"
            << std::endl;
  MOBIUS_CHECK(worst < 1e-11 * scale);
}

void TestGridAgainstDirectSum()
{
  const int B = 12;
  const auto f = RandomRealFunction(B, [](int l) { return 1.0 / (1 + l); });
  const auto g = RandomRealFunction(B, [](int l) { return 1.0 / (1 + l); });
  double norms = 0;
  for (int l = 0; l < B; ++l)
  {
    for (int m = -l; m <= l; ++m)
    {
      norms += std::norm(f(l, m)) + std::norm(g(l, m));
    }
  }
  for (bool reflect : { false, true })
  {
    const double sign = reflect ? -1.0 : 1.0;
    const std::vector<double> grid = mobius::ComputeCorrelationGrid(f, g, B, reflect, 2);
    const int M = 2 * B;
    double worstGrid = 0;
    for (int sample = 0; sample < 300; ++sample)
    {
      const int a = Random() % M, c = Random() % M, j = Random() % (B + 1);
      const double direct = mobius::EvaluateCorrelationDirectly(
        f, g, sign * mobius::EulerZYZToMatrix(2 * M_PI * a / M, M_PI * j / B, 2 * M_PI * c / M));
      worstGrid = std::max(worstGrid,
        std::abs(grid[(static_cast<std::size_t>(j) * M + c) * M + a] - direct));
    }
    // Off-grid: the tensor's series and its derivatives.
    mobius::SO3CorrelationTensor tensor(f, g, B, reflect, 2);
    tensor.TransformToBetaSamples();
    tensor.TransformToFourier(); // round trip must be exact too
    double worstSeries = 0;
    double worstDerivative = 0;
    for (int sample = 0; sample < 30; ++sample)
    {
      const Eigen::Vector3d e(Uniform(0, 2 * M_PI), Uniform(0, M_PI), Uniform(0, 2 * M_PI));
      Eigen::Vector3d gradient;
      Eigen::Matrix3d hessian;
      const double value = tensor.Evaluate(e, &gradient, &hessian);
      const double direct = mobius::EvaluateCorrelationDirectly(
        f, g, sign * mobius::EulerZYZToMatrix(e[0], e[1], e[2]));
      worstSeries = std::max(worstSeries, std::abs(value - direct));
      const double h = 1e-5;
      for (int i = 0; i < 3; ++i)
      {
        Eigen::Vector3d gp, gm;
        const double vp = tensor.Evaluate(e + h * Eigen::Vector3d::Unit(i), &gp, nullptr);
        const double vm = tensor.Evaluate(e - h * Eigen::Vector3d::Unit(i), &gm, nullptr);
        worstDerivative = std::max(worstDerivative, std::abs((vp - vm) / (2 * h) - gradient[i]));
        worstDerivative =
          std::max(worstDerivative, ((gp - gm) / (2 * h) - hessian.col(i)).cwiseAbs().maxCoeff());
      }
    }
    // The full-band sample evaluation (refinement) against the tensor, several points at once.
    std::vector<mobius::SO3CorrelationSample> samples(7);
    for (mobius::SO3CorrelationSample& sample : samples)
    {
      sample.EulerAngles = Eigen::Vector3d(Uniform(-1, 7), Uniform(-0.5, 3.6), Uniform(-1, 7));
      sample.ReflectSource = reflect;
    }
    samples[0].EulerAngles[1] = 0.0; // degenerate Euler angles are fine too
    samples[1].EulerAngles[1] = M_PI;
    mobius::EvaluateCorrelationSamples(f, g, samples, 0, 2);
    double worstSamples = 0;
    for (const mobius::SO3CorrelationSample& sample : samples)
    {
      Eigen::Vector3d gradient;
      Eigen::Matrix3d hessian;
      const double value = tensor.Evaluate(sample.EulerAngles, &gradient, &hessian);
      worstSamples = std::max({ worstSamples, std::abs(sample.Value - value),
        (sample.Gradient - gradient).cwiseAbs().maxCoeff(),
        (sample.Hessian - hessian).cwiseAbs().maxCoeff() });
    }
    // Thread count must not change the result.
    std::vector<mobius::SO3CorrelationSample> single = samples;
    mobius::EvaluateCorrelationSamples(f, g, single, 0, 1);
    bool identical = true;
    for (std::size_t i = 0; i < samples.size(); ++i)
    {
      identical = identical && single[i].Value == samples[i].Value &&
        single[i].Gradient == samples[i].Gradient && single[i].Hessian == samples[i].Hessian;
    }
    MOBIUS_CHECK(identical);
    MOBIUS_CHECK(worstSamples < 1e-11 * norms);
    std::cout << (reflect ? "reflected" : "rotations") << ": samples (value, gradient, Hessian) vs tensor "
              << worstSamples / norms << std::endl;
    std::cout << (reflect ? "reflected" : "rotations") << ": grid vs direct " << worstGrid / norms
              << ", series vs direct " << worstSeries / norms << ", derivatives vs differences "
              << worstDerivative / norms << " (relative to |f|^2+|g|^2)" << std::endl;
    MOBIUS_CHECK(worstGrid < 1e-9 * norms);
    MOBIUS_CHECK(worstSeries < 1e-9 * norms);
    MOBIUS_CHECK(worstDerivative < 1e-6 * norms);
  }
}

// trials random copies: rotated (mirrored = false) or mirrored and rotated (mirrored = true).
void TestRecovery(bool mirrored, mobius::SO3ReflectionMode mode, int trials)
{
  const bool reflections = mirrored;
  const int B = 128;
  const auto f = RandomRealFunction(B, [](int l) { return std::exp(-2e-4 * l * (l + 1)) / (1 + l); });
  mobius::SO3CorrelationOptions options;
  options.Reflections = mode;
  options.NumberOfCandidates = 1; // the best peak is what is tested; keeps the test fast
  std::vector<double> errors;
  double seconds = 0;
  int wrongDeterminant = 0;
  int bandwidth = 0;
  double worstRegistrationError = 0;
  for (int trial = 0; trial < trials; ++trial)
  {
    Eigen::Matrix3d truth = RandomRotation();
    if (reflections)
    {
      truth = truth * Eigen::Vector3d(-1, 1, 1).asDiagonal(); // a mirrored copy
    }
    mobius::SphericalHarmonicCoefficients g;
    mobius::RotateCoefficients(f, truth, g);
    const auto start = std::chrono::steady_clock::now();
    const mobius::SO3CorrelationResult result = mobius::CorrelateOverRotations(f, g, options);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    bandwidth = result.CorrelationBandwidth;
    wrongDeterminant += (result.Determinant * truth.determinant() < 0);
    worstRegistrationError = std::max(worstRegistrationError, result.RegistrationError);
    errors.push_back(mobius::RotationAngleBetween(result.Transform, truth) * 180 / M_PI);
    MOBIUS_CHECK(!result.Candidates.empty());
    MOBIUS_CHECK(std::abs(result.Transform.determinant() - result.Determinant) < 1e-12);
    const Eigen::Vector3d e = result.EulerAngles;
    MOBIUS_CHECK((result.Determinant * mobius::EulerZYZToMatrix(e[0], e[1], e[2]) -
                   result.Transform)
                   .norm() < 1e-12);
  }
  std::sort(errors.begin(), errors.end());
  const double median = 0.5 * (errors[(trials - 1) / 2] + errors[trials / 2]);
  const char* modeName = mode == mobius::SO3ReflectionMode::Both
    ? "Both"
    : (mode == mobius::SO3ReflectionMode::RotationsOnly ? "RotationsOnly" : "ReflectionsOnly");
  std::cout << trials << (reflections ? " mirrored copies" : " rotated copies") << " (mode "
            << modeName << ")"
            << ": B = " << B << ", B' = " << bandwidth << ", angular error median " << median
            << " deg, max " << errors.back() << " deg, worst registration error "
            << worstRegistrationError << ", wrong determinant " << wrongDeterminant
            << ", mean time " << seconds / trials << " s" << std::endl;
  MOBIUS_CHECK(median <= 0.05);
  MOBIUS_CHECK(errors.back() <= 0.2);
  MOBIUS_CHECK(wrongDeterminant == 0);
  MOBIUS_CHECK(worstRegistrationError < 1e-8);
}
}

int main()
{
  TestEulerConventions();
  TestCoefficientRotation();
  TestGridAgainstDirectSum();
  TestRecovery(false, mobius::SO3ReflectionMode::RotationsOnly, 20);
  TestRecovery(true, mobius::SO3ReflectionMode::ReflectionsOnly, 20);
  // Mode Both must pick the right determinant on its own.
  TestRecovery(false, mobius::SO3ReflectionMode::Both, 3);
  TestRecovery(true, mobius::SO3ReflectionMode::Both, 3);
  return MOBIUS_TEST_RESULT();
}
