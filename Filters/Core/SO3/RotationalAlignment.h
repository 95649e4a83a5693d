// The rotational alignment of two centered spherical maps (vtkSO3Register's work, the
// paper's §6.2): the settings checked, each map's scale-factor signal, the correlation over
// SO(3), the landmarks' choice among its candidates (or their Möbius fit), the check for a
// mirrored pair, and the source's sphere points moved onto the target's. Every message of
// the alignment is made here (the filter adds only its own: an input port left empty).
#ifndef mobius_RotationalAlignment_h
#define mobius_RotationalAlignment_h

#include "MeshTypes.h"
#include "MirrorCheck.h"
#include "SO3Correlation.h"
#include "ScaleFactorSignal.h"

#include <string>
#include <utility>
#include <vector>

namespace mobius
{
/// One centered spherical map as its reader found it.
struct AlignmentMap
{
  Points Sphere;               ///< unit vectors
  mobius::Triangles Triangles;
  Vector Areas;                ///< per triangle, of the surface
  std::string Name;            ///< what messages call it, e.g. "Source (port 0)"
  std::string Problem;         ///< why it could not be read; empty if it was
};

struct RotationalAlignmentParameters
{
  /// Resolution, value, smoothing and threads of both signals.
  ScaleFactorSignalParameters Signal;
  /// Candidates, their separation, the kinds of transform and the threads (Progress is the
  /// alignment's own, below).
  SO3CorrelationOptions Correlation;
  /// Also find the best transform of the other kind, and warn when it fits far better.
  bool CheckMirroring = true;
  /// The landmarks fit a Möbius transformation (LandmarkMode 1) instead of choosing the
  /// rotation among the candidates (LandmarkMode 0).
  bool FitMobius = false;
  /// The fraction of the whole alignment done; returning false stops it.
  ProgressCallback Progress;
};

struct RotationalAlignment
{
  /// The message of the reason the maps cannot be aligned; empty on success.
  std::string Error;
  /// Warnings in the order they arose (before the error, if there is one).
  std::vector<std::string> Warnings;
  /// Progress asked to stop: no result and no error.
  bool Stopped = false;
  /// The kept transform and the candidates, the kept one first.
  SO3CorrelationResult Correlation;
  /// The other kind's coarse fit (-1 errors when not checked).
  MirrorCheck Mirroring;
  /// Per candidate, the root mean square angle (radians) between the landmarks it moves and
  /// their targets; empty without landmarks or with their Möbius fit.
  std::vector<double> LandmarkAngles;
  /// The source's sphere points moved by the kept transform (or the landmarks' Möbius
  /// transformation); empty unless the alignment succeeded.
  Points AlignedSource;
};

/// Estimated peak memory in bytes of an alignment at grid size `resolution`: 160 bytes per
/// grid cell and 50 MB, about twice what a registration was measured to use.
double AlignmentMemoryEstimate(int resolution);

/// The largest even grid size whose AlignmentMemoryEstimate fits in `bytes` (0 or less: the
/// machine's physical memory), at least 4.
int LargestAlignmentResolution(double bytes = 0);

/// The machine's physical memory in bytes, 0 if unknown.
double PhysicalMemoryBytes();

/// Aligns `source` with `target`; `landmarks` are point ids of the two maps.
RotationalAlignment AlignSphericalMaps(AlignmentMap source, const AlignmentMap& target,
  const std::vector<std::pair<Index, Index>>& landmarks,
  const RotationalAlignmentParameters& parameters);
}

#endif
