// The canonical centering of a spherical map (vtkMobiusCenter's work, the paper's §4 and
// Algorithm 1, and with a degree above 1 its generalized centering, §5 and §6.1): the Möbius
// centering, then the advection along spherical harmonics of degree 2 and up, and a warning
// when the tolerance was not reached. Every message of the centering is made here (the filter
// adds only its own: an input it cannot read).
#ifndef mobius_MapCentering_h
#define mobius_MapCentering_h

#include "GeneralizedCentering.h"
#include "MobiusCentering.h"

#include <string>
#include <vector>

namespace mobius
{
struct MapCenteringParameters
{
  /// The Möbius centering's tolerance and steps.
  MobiusCenteringParameters Mobius;
  /// 1: the Möbius centering alone; 2 to 8 go on to the generalized centering of this
  /// degree.
  int Degree = 1;
  /// The generalized centering's tolerance and steps (its Degree is the one above).
  GeneralizedCenteringParameters Generalized;
  /// The fraction done of each of the two centerings (each runs from 0 to 1); returning
  /// false stops the centering.
  ProgressCallback Progress;
};

struct MapCentering
{
  /// The message of the reason the map cannot be centered; empty on success.
  std::string Error;
  /// Warnings in the order they arose.
  std::vector<std::string> Warnings;
  /// Progress asked to stop: no result and no error.
  bool Stopped = false;
  /// The Möbius centering: its inversions and their Lorentz matrix. With a degree above 1,
  /// CenterOfMassNorm and Converged are the generalized centering's.
  MobiusCenteringResult Mobius;
  /// The generalized centering's steps (none with degree 1).
  GeneralizedCenteringResult Generalized;
};

/// Centers the spherical map in place (`areas`: the surface area of each triangle; without
/// triangles the points are centered as a point set, which only degree 1 can do). After an error
/// or a stop the points are not a result.
MapCentering CenterMap(Points& points, const Triangles& triangles, const Vector& areas,
  const MapCenteringParameters& parameters);
}

#endif
