#include "MirrorCheck.h"

namespace mobius
{
namespace
{
// The registration error of the best transform of one kind, from a coarse search alone: one
// candidate on a grid of bandwidth 16, polished by Newton's method on the same 16 bands. Coarse on
// both sides, the two kinds compare fairly, at a small share of the registration's cost.
double CoarseRegistrationError(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, const SO3CorrelationOptions& options,
  SO3ReflectionMode kind)
{
  SO3CorrelationOptions coarse = options;
  coarse.Reflections = kind;
  coarse.NumberOfCandidates = 1;
  coarse.MinimumCorrelationBandwidth = 16;
  coarse.MaximumCorrelationBandwidth = 16;
  coarse.RefinementTolerance = 1.0; // B'' = B': Newton on the same 16 bands
  coarse.Progress = nullptr;
  const SO3CorrelationResult result = CorrelateOverRotations(source, target, coarse);
  return result.Candidates.empty() ? -1.0 : result.RegistrationError;
}
}

MirrorCheck CheckMirroring(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, const SO3CorrelationOptions& options)
{
  MirrorCheck check;
  if (options.Reflections == SO3ReflectionMode::Both)
  {
    return check;
  }
  const SO3ReflectionMode other = options.Reflections == SO3ReflectionMode::RotationsOnly
    ? SO3ReflectionMode::ReflectionsOnly
    : SO3ReflectionMode::RotationsOnly;
  check.ChosenError = CoarseRegistrationError(source, target, options, options.Reflections);
  check.OtherError = CoarseRegistrationError(source, target, options, other);
  check.OtherFitsFarBetter = OtherKindFitsFarBetter(check.ChosenError, check.OtherError);
  return check;
}

bool OtherKindFitsFarBetter(double chosenError, double otherError)
{
  // Errors are at least 0 up to rounding (a perfect fit comes out near -1e-16); -1: not
  // checked.
  return chosenError > -0.5 && otherError > -0.5 && otherError < 0.5 * chosenError &&
    chosenError - otherError >= 0.01;
}
}
