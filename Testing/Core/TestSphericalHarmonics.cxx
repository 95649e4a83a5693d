// Spherical harmonic transform on the cell-centered N = 2B grid: quadrature exactness,
// closed forms and conventions (Condon-Shortley phase, half-cell azimuth), round trips up to
// B = 512, agreement with direct evaluation, heat smoothing.
#include "CoreTest.h"
#include "SphericalHarmonicSeries.h"
#include "SphericalHarmonics.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <vector>

namespace
{
using Complex = std::complex<double>;

double CellTheta(int j, int n) { return M_PI * (j + 0.5) / n; }
double CellPhi(int i, int n) { return 2.0 * M_PI * (i + 0.5) / n; }

// Random coefficients of a real function: f_{l,-m} = (-1)^m conj(f_lm), f_l0 real.
mobius::SphericalHarmonicCoefficients RandomRealCoefficients(int bandwidth, unsigned seed)
{
  std::mt19937 generator(seed);
  std::normal_distribution<double> normal;
  mobius::SphericalHarmonicCoefficients c;
  c.Resize(bandwidth);
  for (int l = 0; l < bandwidth; ++l)
  {
    c(l, 0) = normal(generator);
    for (int m = 1; m <= l; ++m)
    {
      c(l, m) = Complex(normal(generator), normal(generator));
      c(l, -m) = ((m % 2 == 0) ? 1.0 : -1.0) * std::conj(c(l, m));
    }
  }
  return c;
}

double MaxAbs(const std::vector<Complex>& values)
{
  double result = 0.0;
  for (const auto& v : values)
  {
    result = std::max(result, std::abs(v));
  }
  return result;
}

double MaxDifference(
  const mobius::SphericalHarmonicCoefficients& a, const mobius::SphericalHarmonicCoefficients& b)
{
  double result = 0.0;
  for (size_t k = 0; k < a.Values.size(); ++k)
  {
    result = std::max(result, std::abs(a.Values[k] - b.Values[k]));
  }
  return result;
}

void TestQuadratureIsExact()
{
  // sum_j w_j x_j^k = int_{-1}^{1} x^k dx for every degree k < N.
  const int b = 16, n = 2 * b;
  mobius::SphericalHarmonicTransform transform(b, 1);
  for (int k = 0; k < n; ++k)
  {
    double sum = 0.0;
    for (int j = 0; j < n; ++j)
    {
      sum += transform.GetQuadratureWeight(j) * std::pow(std::cos(CellTheta(j, n)), k);
    }
    const double exact = (k % 2 == 0) ? 2.0 / (k + 1.0) : 0.0;
    MOBIUS_CHECK_NEAR(sum, exact, 1e-14);
  }
}

void TestClosedForms()
{
  mobius::SphericalHarmonicCoefficients c;
  c.Resize(3);
  const double theta = 0.7, phi = 2.1;
  c(1, 0) = 1.0;
  Complex y = mobius::EvaluateSphericalHarmonicSeries(c, theta, phi);
  MOBIUS_CHECK_NEAR(y.real(), std::sqrt(3.0 / (4.0 * M_PI)) * std::cos(theta), 1e-15);
  MOBIUS_CHECK_NEAR(y.imag(), 0.0, 1e-15);

  c.Resize(3);
  c(1, 1) = 1.0; // Y_1^1 = -sqrt(3/(8 pi)) sin(theta) e^{i phi}
  y = mobius::EvaluateSphericalHarmonicSeries(c, theta, phi);
  const Complex y11 = -std::sqrt(3.0 / (8.0 * M_PI)) * std::sin(theta) * std::polar(1.0, phi);
  MOBIUS_CHECK_NEAR(std::abs(y - y11), 0.0, 1e-15);

  c.Resize(3);
  c(1, -1) = 1.0; // Y_1^{-1} = -conj(Y_1^1)
  y = mobius::EvaluateSphericalHarmonicSeries(c, theta, phi);
  MOBIUS_CHECK_NEAR(std::abs(y + std::conj(y11)), 0.0, 1e-15);

  c.Resize(3);
  c(2, 2) = 1.0; // Y_2^2 = sqrt(15/(32 pi)) sin^2(theta) e^{2 i phi}
  y = mobius::EvaluateSphericalHarmonicSeries(c, theta, phi);
  const Complex y22 =
    std::sqrt(15.0 / (32.0 * M_PI)) * std::pow(std::sin(theta), 2) * std::polar(1.0, 2.0 * phi);
  MOBIUS_CHECK_NEAR(std::abs(y - y22), 0.0, 1e-15);

  c.Resize(3);
  c(2, 1) = 1.0; // Y_2^1 = -sqrt(15/(8 pi)) sin(theta) cos(theta) e^{i phi}
  y = mobius::EvaluateSphericalHarmonicSeries(c, theta, phi);
  const Complex y21 =
    -std::sqrt(15.0 / (8.0 * M_PI)) * std::sin(theta) * std::cos(theta) * std::polar(1.0, phi);
  MOBIUS_CHECK_NEAR(std::abs(y - y21), 0.0, 1e-15);
}

// Addition theorem sum_m |Y_l^m|^2 = (2l+1)/(4 pi) near the pole, where sin^m(theta) underflows
// for the high orders (exercises the extended-exponent Legendre seeds), and Y_l^l in closed form
// (computed in logarithms).
void TestHighDegreeNearPole()
{
  const int l = 400;
  mobius::SphericalHarmonicCoefficients c;
  for (double theta : { 0.01, 0.3, M_PI - 0.002 })
  {
    double sum = 0.0;
    for (int m = -l; m <= l; ++m)
    {
      c.Resize(l + 1);
      c(l, m) = 1.0;
      sum += std::norm(mobius::EvaluateSphericalHarmonicSeries(c, theta, 0.4));
    }
    std::cout << "addition theorem, l = " << l << ", theta = " << theta << ": relative error "
              << sum / ((2.0 * l + 1.0) / (4.0 * M_PI)) - 1.0 << std::endl;
    MOBIUS_CHECK_NEAR(sum / ((2.0 * l + 1.0) / (4.0 * M_PI)), 1.0, 1e-11);
  }
  const int degree = 150;
  const double theta = 0.3;
  c.Resize(degree + 1);
  c(degree, degree) = 1.0;
  const Complex y = mobius::EvaluateSphericalHarmonicSeries(c, theta, 0.0);
  // |Y_l^l| = sqrt((2l+1)!/(4 pi)) / (2^l l!) sin^l(theta), sign (-1)^l.
  const double logMagnitude = 0.5 * (std::lgamma(2.0 * degree + 2.0) - std::log(4.0 * M_PI)) -
    degree * std::log(2.0) - std::lgamma(degree + 1.0) + degree * std::log(std::sin(theta));
  MOBIUS_CHECK_NEAR(y.real() / std::exp(logMagnitude), 1.0, 1e-11);
}

void TestForwardOfSampledFunctions()
{
  // x = sin(theta) cos(phi) = sqrt(2 pi/3) (Y_1^{-1} - Y_1^1), sampled at the cell centers:
  // a half-cell azimuth error would rotate these coefficients by e^{i pi/N}.
  const int b = 8, n = 2 * b;
  mobius::SphericalHarmonicTransform transform(b, 2);
  std::vector<double> grid(n * n);
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      grid[j * n + i] = std::sin(CellTheta(j, n)) * std::cos(CellPhi(i, n));
    }
  }
  mobius::SphericalHarmonicCoefficients c;
  transform.Forward(grid.data(), c);
  const double a = std::sqrt(2.0 * M_PI / 3.0);
  MOBIUS_CHECK_NEAR(std::abs(c(1, 1) - Complex(-a, 0.0)), 0.0, 1e-14);
  MOBIUS_CHECK_NEAR(std::abs(c(1, -1) - Complex(a, 0.0)), 0.0, 1e-14);
  double others = 0.0;
  for (int l = 0; l < b; ++l)
  {
    for (int m = -l; m <= l; ++m)
    {
      if (!(l == 1 && std::abs(m) == 1))
      {
        others = std::max(others, std::abs(c(l, m)));
      }
    }
  }
  MOBIUS_CHECK_NEAR(others, 0.0, 1e-14);

  // Orthonormality spot check: Re Y_5^3 sampled by direct evaluation has exactly the
  // coefficients f_{5,3} = 1/2 and f_{5,-3} = (-1)^3 / 2.
  mobius::SphericalHarmonicCoefficients single;
  single.Resize(b);
  single(5, 3) = 1.0;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      grid[j * n + i] =
        mobius::EvaluateSphericalHarmonicSeries(single, CellTheta(j, n), CellPhi(i, n)).real();
    }
  }
  transform.Forward(grid.data(), c);
  MOBIUS_CHECK_NEAR(std::abs(c(5, 3) - 0.5), 0.0, 1e-14);
  MOBIUS_CHECK_NEAR(std::abs(c(5, -3) + 0.5), 0.0, 1e-14);
  MOBIUS_CHECK_NEAR(std::abs(c(5, 3)) * std::abs(c(5, 3)) * 2.0, 0.5, 1e-14);
}

void TestInverseMatchesDirectEvaluation()
{
  const int b = 12, n = 2 * b;
  mobius::SphericalHarmonicTransform transform(b, 2);
  const auto c = RandomRealCoefficients(b, 7);
  std::vector<double> grid(n * n);
  transform.Inverse(c, grid.data());
  double error = 0.0;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const Complex direct =
        mobius::EvaluateSphericalHarmonicSeries(c, CellTheta(j, n), CellPhi(i, n));
      error = std::max(error, std::abs(direct.real() - grid[j * n + i]));
      error = std::max(error, std::abs(direct.imag()));
    }
  }
  MOBIUS_CHECK_NEAR(error, 0.0, 1e-12);

  // Inverse returns the real part also for coefficients of a complex function.
  mobius::SphericalHarmonicCoefficients complexCoefficients = c;
  complexCoefficients(3, 2) += Complex(0.3, -0.8);
  complexCoefficients(4, 0) += Complex(0.0, 0.5);
  transform.Inverse(complexCoefficients, grid.data());
  error = 0.0;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const Complex direct = mobius::EvaluateSphericalHarmonicSeries(
        complexCoefficients, CellTheta(j, n), CellPhi(i, n));
      error = std::max(error, std::abs(direct.real() - grid[j * n + i]));
    }
  }
  MOBIUS_CHECK_NEAR(error, 0.0, 1e-12);
}

void TestRoundTrip(int bandwidth)
{
  const int n = 2 * bandwidth;
  mobius::SphericalHarmonicTransform transform(bandwidth);
  const auto c = RandomRealCoefficients(bandwidth, 1234u + bandwidth);
  std::vector<double> grid(static_cast<size_t>(n) * n);
  mobius::SphericalHarmonicCoefficients back;
  const auto start = std::chrono::steady_clock::now();
  transform.Inverse(c, grid.data());
  const auto middle = std::chrono::steady_clock::now();
  transform.Forward(grid.data(), back);
  const auto end = std::chrono::steady_clock::now();
  const double relative = MaxDifference(c, back) / MaxAbs(c.Values);
  std::cout << "B = " << bandwidth << ": round-trip relative max error " << relative
            << ", inverse " << std::chrono::duration<double>(middle - start).count()
            << " s, forward " << std::chrono::duration<double>(end - middle).count() << " s"
            << std::endl;
  MOBIUS_CHECK(back.Bandwidth == bandwidth);
  MOBIUS_CHECK_NEAR(relative, 0.0, 1e-10);
}

void TestHeatSmoothing()
{
  auto c = RandomRealCoefficients(10, 3);
  const auto original = c;
  const double t = 5e-4;
  mobius::SmoothWithHeatKernel(c, t);
  for (int l = 0; l < 10; ++l)
  {
    for (int m = -l; m <= l; ++m)
    {
      const Complex expected = original(l, m) * std::exp(-t * l * (l + 1));
      MOBIUS_CHECK_NEAR(std::abs(c(l, m) - expected), 0.0, 1e-15);
    }
  }
  MOBIUS_CHECK_NEAR(std::abs(c(0, 0) - original(0, 0)), 0.0, 0.0);
}
}

int main()
{
  TestQuadratureIsExact();
  TestClosedForms();
  TestHighDegreeNearPole();
  TestForwardOfSampledFunctions();
  TestInverseMatchesDirectEvaluation();
  TestHeatSmoothing();
  for (int bandwidth : { 16, 128, 512 })
  {
    TestRoundTrip(bandwidth);
  }
  return MOBIUS_TEST_RESULT();
}
