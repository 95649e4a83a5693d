#include "SphericalHarmonicSeries.h"

#include "NormalizedLegendre.h"

#include <cmath>

namespace mobius
{
std::complex<double> EvaluateSphericalHarmonicSeries(
  const SphericalHarmonicCoefficients& coefficients, double theta, double phi)
{
  const int bandwidth = coefficients.Bandwidth;
  const double cosTheta = std::cos(theta);
  const double sinTheta = std::abs(std::sin(theta));
  detail::NormalizedLegendreRecursion legendre;
  std::complex<double> sum = 0.0;
  for (int m = 0; m < bandwidth; ++m)
  {
    const std::complex<double> positive = std::polar(1.0, m * phi);
    // Y_l^{-m} = (-1)^m conj(Y_l^m), and Pbar_l^m is real.
    const std::complex<double> negative = ((m % 2 == 0) ? 1.0 : -1.0) * std::conj(positive);
    legendre.Run(m, bandwidth, &cosTheta, &sinTheta, 1, [&](int l, const double* value) {
      std::complex<double> term = coefficients(l, m) * positive;
      if (m > 0)
      {
        term += coefficients(l, -m) * negative;
      }
      sum += value[0] * term;
    });
  }
  return sum;
}
}
