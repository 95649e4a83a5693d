// Spherical harmonic coefficient storage and heat-kernel smoothing.
// The fast transform lives in SphericalHarmonicTransform.cxx.
#include "SphericalHarmonics.h"

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
}
