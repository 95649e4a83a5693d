// Direct evaluation of a spherical harmonic series (conventions in SphericalHarmonics.h),
// against which the tests check the fast transform and sub-grid interpolation.
#ifndef mobius_SphericalHarmonicSeries_h
#define mobius_SphericalHarmonicSeries_h

#include "SphericalHarmonics.h"

#include <complex>

namespace mobius
{
/// Direct evaluation of sum f_lm Y_lm at one point (all m, negative ones included), O(B^2).
std::complex<double> EvaluateSphericalHarmonicSeries(
  const SphericalHarmonicCoefficients& coefficients, double theta, double phi);
}

#endif
