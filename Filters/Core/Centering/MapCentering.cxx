#include "MapCentering.h"

#include "StopWatchingProgress.h"

#include <sstream>

namespace mobius
{
namespace
{
// The generalized centering after the Möbius one; false with the error, or stopped, if it
// cannot be done.
bool CenterToDegree(Points& points, const Triangles& triangles, const Vector& areas,
  const MapCenteringParameters& mapParameters, StopWatchingProgress& report,
  MapCentering& centering)
{
  GeneralizedCenteringParameters parameters = mapParameters.Generalized;
  parameters.Degree = mapParameters.Degree;
  if (triangles.rows() == 0)
  {
    std::ostringstream message;
    message << "Cannot center: Degree " << parameters.Degree
            << " needs triangles; a point set can only be centered with Degree 1.";
    centering.Error = message.str();
    return false;
  }
  auto progress = [&report](double fraction) { return report(fraction); };
  if (!CenterWithSphericalHarmonics(
        points, triangles, areas, parameters, centering.Generalized, progress))
  {
    centering.Stopped = report.StopAsked;
    if (!report.StopAsked)
    {
      centering.Error = "Generalized centering failed: " + centering.Generalized.Error + ".";
    }
    return false;
  }
  centering.Mobius.CenterOfMassNorm = centering.Generalized.CenterOfMassNorm;
  centering.Mobius.Converged = centering.Generalized.Converged;
  return true;
}

// "Centering stopped after 100 iterations with |mu| = 0.001 above the tolerance 1e-10."
std::string NotConvergedWarning(
  const MapCenteringParameters& parameters, const MapCentering& centering)
{
  const bool generalized = parameters.Degree > 1;
  std::ostringstream warning;
  warning << (generalized ? "Generalized centering" : "Centering") << " stopped after "
          << (generalized ? centering.Generalized.NumberOfIterations
                          : centering.Mobius.NumberOfIterations)
          << " iterations with |mu| = " << centering.Mobius.CenterOfMassNorm
          << " above the tolerance "
          << (generalized ? parameters.Generalized.Tolerance : parameters.Mobius.Tolerance)
          << ".";
  return warning.str();
}
}

MapCentering CenterMap(Points& points, const Triangles& triangles, const Vector& areas,
  const MapCenteringParameters& parameters)
{
  MapCentering centering;
  StopWatchingProgress report{ parameters.Progress };
  auto progress = [&report](double fraction) { return report(fraction); };
  if (!CenterSphericalMap(
        points, triangles, areas, parameters.Mobius, centering.Mobius, progress))
  {
    centering.Stopped = report.StopAsked;
    if (!report.StopAsked)
    {
      centering.Error = "Centering failed: " + centering.Mobius.Error + ".";
    }
    return centering;
  }
  if (parameters.Degree > 1 &&
    !CenterToDegree(points, triangles, areas, parameters, report, centering))
  {
    return centering;
  }
  if (!centering.Mobius.Converged)
  {
    centering.Warnings.push_back(NotConvergedWarning(parameters, centering));
  }
  return centering;
}
}
