#include "ScaleFactorSignal.h"

#include <sstream>
#include <stdexcept>

namespace mobius
{
std::string CheckGridResolution(int resolution, int minimum)
{
  if (resolution >= minimum && resolution % 2 == 0)
  {
    return std::string();
  }
  std::ostringstream message;
  message << "Resolution must be even and at least " << minimum << " (it is " << resolution
          << ")";
  return message.str();
}

bool ComputeScaleFactorSignal(const Points& spherePoints, const Triangles& triangles,
  const Vector& triangleAreas, const ScaleFactorSignalParameters& parameters,
  bool computeSmoothedValues, ScaleFactorSignal& signal, std::string& error,
  const ProgressCallback& progress)
{
  if (!(parameters.SmoothingTime >= 0))
  {
    error = "the smoothing time must be non-negative";
    return false;
  }
  // Rasterization is most of the work: give it the first 80% of the progress range.
  ProgressCallback rasterProgress;
  if (progress)
  {
    rasterProgress = [&progress](double fraction) { return progress(0.8 * fraction); };
  }
  if (!RasterizeSphericalAreas(spherePoints, triangles, triangleAreas, parameters.Resolution,
        parameters.Value, signal.Grid, error, rasterProgress, parameters.NumberOfThreads))
  {
    return false;
  }
  if (progress && !progress(0.8))
  {
    error = "aborted";
    return false;
  }
  try
  {
    const SphericalHarmonicTransform transform(parameters.Resolution / 2, parameters.NumberOfThreads);
    transform.Forward(signal.Grid.Values.data(), signal.Coefficients);
    SmoothWithHeatKernel(signal.Coefficients, parameters.SmoothingTime);
    if (computeSmoothedValues)
    {
      signal.SmoothedValues.resize(signal.Grid.Values.size());
      transform.Inverse(signal.Coefficients, signal.SmoothedValues.data());
    }
  }
  catch (const std::exception& exception)
  {
    error = std::string("spherical harmonic transform failed: ") + exception.what();
    return false;
  }
  if (progress)
  {
    progress(1.0);
  }
  return true;
}
}
