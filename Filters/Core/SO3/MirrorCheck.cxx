#include "MirrorCheck.h"

namespace mobius
{
double OtherDeterminantRegistrationError(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, const SO3CorrelationOptions& options)
{
  if (options.Reflections == SO3ReflectionMode::Both)
  {
    return -1.0;
  }
  SO3CorrelationOptions other = options;
  other.Reflections = options.Reflections == SO3ReflectionMode::RotationsOnly
    ? SO3ReflectionMode::ReflectionsOnly
    : SO3ReflectionMode::RotationsOnly;
  other.NumberOfCandidates = 1;
  other.MinimumCorrelationBandwidth = 16;
  other.MaximumCorrelationBandwidth = 16;
  other.Progress = nullptr;
  const SO3CorrelationResult result = CorrelateOverRotations(source, target, other);
  return result.Candidates.empty() ? -1.0 : result.RegistrationError;
}

bool OtherDeterminantFitsFarBetter(double chosenError, double otherError)
{
  return otherError >= 0 && otherError < 0.5 * chosenError && chosenError - otherError >= 0.01;
}
}
