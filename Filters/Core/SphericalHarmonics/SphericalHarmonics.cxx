// Spherical harmonic coefficient storage, heat-kernel smoothing and direct series evaluation.
// The fast transform lives in SphericalHarmonicTransform.cxx.
#include "SphericalHarmonics.h"

#include "NormalizedLegendre.h"

#include <cmath>

namespace mobius
{
void SphericalHarmonicCoefficients::Resize(int bandwidth)
{
  this->Bandwidth = bandwidth < 0 ? 0 : bandwidth;
  this->Values.assign(static_cast<size_t>(this->Bandwidth) * this->Bandwidth, { 0.0, 0.0 });
}

void SmoothWithHeatKernel(SphericalHarmonicCoefficients& coefficients, double time)
{
  // exp(-t l(l+1)) is the heat kernel's eigenvalue on band l (Laplacian eigenvalue -l(l+1)).
  for (int l = 0; l < coefficients.Bandwidth; ++l)
  {
    const double factor = std::exp(-time * l * (l + 1.0));
    for (int m = -l; m <= l; ++m)
    {
      coefficients(l, m) *= factor;
    }
  }
}

std::vector<double> DegreeEnergies(const SphericalHarmonicCoefficients& coefficients)
{
  std::vector<double> energies(static_cast<std::size_t>(coefficients.Bandwidth), 0.0);
  for (int l = 0; l < coefficients.Bandwidth; ++l)
  {
    for (int m = -l; m <= l; ++m)
    {
      energies[l] += std::norm(coefficients(l, m));
    }
  }
  return energies;
}

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
