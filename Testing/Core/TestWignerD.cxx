// Wigner small-d matrices: the Δ = d(π/2) recursion and the Δ factorization of d(β), and the
// three-term recursion in l, against Wigner's explicit sum formula (long double) and against
// each other; orthogonality and the group property d(a) d(b) = d(a + b) at high degree.
#include "CoreTest.h"
#include "WignerD.h"
#include "WignerSmallDMatrix.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace
{
long double Factorial(int n)
{
  long double result = 1;
  for (int i = 2; i <= n; ++i)
  {
    result *= i;
  }
  return result;
}

// Wigner's formula, independent of the code under test.
double WignerFormula(int l, int m, int n, double beta)
{
  const long double c = std::cos(static_cast<long double>(beta) / 2);
  const long double s = std::sin(static_cast<long double>(beta) / 2);
  long double sum = 0;
  for (int k = 0; k <= 2 * l; ++k)
  {
    if (l + n - k < 0 || m - n + k < 0 || l - m - k < 0)
    {
      continue;
    }
    const long double term =
      std::sqrt(Factorial(l + m) * Factorial(l - m) * Factorial(l + n) * Factorial(l - n)) /
      (Factorial(l + n - k) * Factorial(k) * Factorial(m - n + k) * Factorial(l - m - k)) *
      std::pow(c, 2 * l + n - m - 2 * k) * std::pow(s, m - n + 2 * k);
    sum += ((m - n + k) % 2 != 0) ? -term : term;
  }
  return static_cast<double>(sum);
}
}

int main()
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(0.0, M_PI);

  // Δ quadrant and symmetries against the explicit formula.
  double worstDelta = 0;
  for (int l = 0; l <= 14; ++l)
  {
    std::vector<double> quadrant((l + 1) * (l + 1));
    mobius::ComputeWignerDeltaQuadrant(l, quadrant.data());
    for (int k = -l; k <= l; ++k)
    {
      for (int m = -l; m <= l; ++m)
      {
        worstDelta = std::max(worstDelta,
          std::abs(mobius::WignerDeltaFromQuadrant(quadrant.data(), l, k, m) -
            WignerFormula(l, k, m, M_PI / 2)));
      }
    }
  }
  std::cout << "Delta vs formula (l <= 14): " << worstDelta << std::endl;
  MOBIUS_CHECK(worstDelta < 1e-13);

  // d(β) from the Δ factorization and from the recursion in l, against the formula.
  double worstFactorized = 0;
  double worstSequence = 0;
  const int smallMax = 14;
  for (int trial = 0; trial < 4; ++trial)
  {
    const double beta = trial == 0 ? 0.0 : (trial == 1 ? M_PI : angle(random));
    std::vector<Eigen::MatrixXd> d;
    for (int l = 0; l <= smallMax; ++l)
    {
      d.push_back(mobius::WignerSmallDMatrix(l, beta));
    }
    std::vector<double> sequence(smallMax + 1);
    for (int m = -smallMax; m <= smallMax; ++m)
    {
      for (int n = -smallMax; n <= smallMax; ++n)
      {
        mobius::WignerSmallDSequence(m, n, smallMax, beta, sequence.data());
        for (int l = std::max(std::abs(m), std::abs(n)); l <= smallMax; ++l)
        {
          const double exact = WignerFormula(l, m, n, beta);
          worstFactorized = std::max(worstFactorized, std::abs(d[l](m + l, n + l) - exact));
          worstSequence = std::max(worstSequence, std::abs(sequence[l] - exact));
        }
      }
    }
  }
  std::cout << "d(beta) factorized vs formula: " << worstFactorized
            << ", l-recursion vs formula: " << worstSequence << std::endl;
  MOBIUS_CHECK(worstFactorized < 1e-12);
  MOBIUS_CHECK(worstSequence < 1e-12);

  // High degree: the two independent routes agree, d is orthogonal, d(a)d(b) = d(a+b).
  const int lHigh = 160;
  const double a = angle(random);
  const double b = angle(random) / 2;
  const Eigen::MatrixXd da = mobius::WignerSmallDMatrix(lHigh, a);
  const Eigen::MatrixXd db = mobius::WignerSmallDMatrix(lHigh, b);
  const Eigen::MatrixXd dab = mobius::WignerSmallDMatrix(lHigh, a + b);
  const int size = 2 * lHigh + 1;
  const double orthogonality =
    (da * da.transpose() - Eigen::MatrixXd::Identity(size, size)).cwiseAbs().maxCoeff();
  const double group = (da * db - dab).cwiseAbs().maxCoeff();
  double recursionVsFactorized = 0;
  std::vector<double> sequence(lHigh + 1);
  for (int m = -lHigh; m <= lHigh; m += 7)
  {
    for (int n = -lHigh; n <= lHigh; n += 5)
    {
      mobius::WignerSmallDSequence(m, n, lHigh, a, sequence.data());
      recursionVsFactorized =
        std::max(recursionVsFactorized, std::abs(sequence[lHigh] - da(m + lHigh, n + lHigh)));
    }
  }
  std::cout << "l = " << lHigh << ": |d d^T - I| = " << orthogonality
            << ", |d(a)d(b) - d(a+b)| = " << group
            << ", recursion vs factorized = " << recursionVsFactorized << std::endl;
  MOBIUS_CHECK(orthogonality < 1e-12);
  MOBIUS_CHECK(group < 1e-12);
  MOBIUS_CHECK(recursionVsFactorized < 1e-12);

  // Δ stays orthogonal at the largest degree we use (B = 512).
  const int lMax = 511;
  std::vector<double> quadrant((lMax + 1) * (lMax + 1));
  mobius::ComputeWignerDeltaQuadrant(lMax, quadrant.data());
  Eigen::MatrixXd delta(2 * lMax + 1, 2 * lMax + 1);
  for (int k = -lMax; k <= lMax; ++k)
  {
    for (int m = -lMax; m <= lMax; ++m)
    {
      delta(k + lMax, m + lMax) = mobius::WignerDeltaFromQuadrant(quadrant.data(), lMax, k, m);
    }
  }
  const double deltaOrthogonality =
    (delta * delta.transpose() - Eigen::MatrixXd::Identity(2 * lMax + 1, 2 * lMax + 1))
      .cwiseAbs()
      .maxCoeff();
  std::cout << "l = " << lMax << ": |Delta Delta^T - I| = " << deltaOrthogonality << std::endl;
  MOBIUS_CHECK(deltaOrthogonality < 1e-12);

  return MOBIUS_TEST_RESULT();
}
