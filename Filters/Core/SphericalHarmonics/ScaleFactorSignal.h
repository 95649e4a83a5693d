// The spherical signal that rotational alignment correlates: a centered map's conformal
// scale factors rasterized exactly onto the cell-centered N x N grid, expanded in spherical
// harmonics and low-passed with the heat kernel (paper Section 6.2, Figure 6).
//
// vtkSphericalScaleGrid shows it; vtkSO3Register correlates the coefficients of two of
// them. Both go through this one function, so what a user looks at is what is registered.
#ifndef mobius_ScaleFactorSignal_h
#define mobius_ScaleFactorSignal_h

#include "MeshTypes.h"
#include "SphericalAreaGrid.h"
#include "SphericalHarmonics.h"

#include <string>
#include <vector>

namespace mobius
{
struct ScaleFactorSignalParameters
{
  /// Grid size N (even, >= 4); the bandwidth is B = N / 2.
  int Resolution = 256;
  /// What a cell holds: the area ratio lambda, or its square root, for which the squared
  /// L2 norm of the signal is the surface area.
  ScaleFactorValue Value = ScaleFactorValue::SquareRootAreaRatio;
  /// Heat-kernel time t of the low pass exp(-t l(l+1)); 0 disables smoothing.
  double SmoothingTime = 5e-4;
  /// 0: automatic (ResolveThreadCount). The signal is the same bit for bit for any count.
  int NumberOfThreads = 0;
};

struct ScaleFactorSignal
{
  /// Cell values before smoothing, values[j*N + i] (see SphericalHarmonics.h).
  SphericalAreaGridResult Grid;
  /// Spherical-harmonic coefficients of the smoothed signal, bandwidth N / 2.
  SphericalHarmonicCoefficients Coefficients;
  /// The smoothed signal at the cell centers (empty unless asked for).
  std::vector<double> SmoothedValues;
};

/// Empty when the grid size `resolution` is even and at least `minimum` (a caller may need a
/// finer grid than MinimumGridResolution), else "Resolution must be even and at least
/// <minimum> (it is <resolution>)": the one wording of this rule for the filters' and
/// the alignment's Resolution.
std::string CheckGridResolution(int resolution, int minimum = MinimumGridResolution);

/// Rasterizes, transforms and smooths. Returns false with `error` naming the problem.
bool ComputeScaleFactorSignal(const Points& spherePoints, const Triangles& triangles,
  const Vector& triangleAreas, const ScaleFactorSignalParameters& parameters,
  bool computeSmoothedValues, ScaleFactorSignal& signal, std::string& error,
  const ProgressCallback& progress = {});
}

#endif
