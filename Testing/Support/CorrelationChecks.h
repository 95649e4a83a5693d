// Slow, direct evaluations of the SO(3) correlation of SO3Correlation.h, against which the
// tests check the fast ones.
#ifndef mobius_CorrelationChecks_h
#define mobius_CorrelationChecks_h

#include "SphericalHarmonics.h"

#include <Eigen/Core>

#include <vector>

namespace mobius
{
/// C(T) summed directly from Wigner D matrices (O(B^3), long-double recursion).
double EvaluateCorrelationDirectly(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, const Eigen::Matrix3d& transform);

/// The whole Euler grid at correlation bandwidth B' (memory (B'+1)(2B')^2 doubles): value
/// C(α_a, β_j, γ_c) at index (j * M + c) * M + a, M = 2B', α_a = 2πa/M, β_j = πj/B'
/// (0 <= j <= B'), γ_c = 2πc/M.
std::vector<double> ComputeCorrelationGrid(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, int correlationBandwidth, bool reflectSource,
  int numberOfThreads = 0);
}

#endif
