// Whether a spherical conformal map can serve the registration: the one rule that refuses a
// map (vtkSphericalConformalMap's DegenerateMap; mobius-register stops on it unless
// --allow-poor-maps) or warns about it.
//
// Refused: a map whose flow did not converge, that has triangles flipped after the repair,
// whose triangles crowd into a spot, whose squeezed-region refinement failed, or that
// squashes more than MaximumSquashedAreaShare of the surface. Not refused for its mean
// distortion: a conformal map squeezes tails and fingers exponentially, and the few
// triangles there (QC in the millions) carry off the mean (a decimated cow: mean 24.6,
// median 1.09) while the rest of the map registers as well as any.
#ifndef mobius_MapVerdict_h
#define mobius_MapVerdict_h

#include "ConformalMap.h"

#include <string>
#include <vector>

namespace mobius
{
/// A map that squashes (quasi-conformal distortion above SquashedQuasiConformalDistortion)
/// more than this share of the surface is refused. See the README, "Degenerate maps", for
/// the measurements behind it.
constexpr double MaximumSquashedAreaShare = 0.5;
/// A map that squashes more than this share, but no more than the maximum, is used with a
/// warning naming the share. The development meshes stay below it (CGAL's bull: 0.6%).
constexpr double WarningSquashedAreaShare = 0.01;
/// A map whose triangles span less than this share of the sphere has collapsed (spread
/// over the sphere, even a tetrahedron's span 37%).
constexpr double MinimumMappedAreaShare = 0.1;

struct MapVerdict
{
  /// Why the map cannot serve the registration (empty: it can).
  std::vector<std::string> Problems;
  /// What the user should know about a usable map (empty: nothing).
  std::string Warning;

  bool Degenerate() const { return !this->Problems.empty(); }
  /// The problems joined by "; ".
  std::string Reason() const;
  /// The warning of a usable map; empty for a degenerate one, whose problems say enough.
  std::string UsableWarning() const { return this->Degenerate() ? std::string() : this->Warning; }
};

/// Judges `result` (a successful map); `convergenceTolerance` is the flow's, for the message.
MapVerdict JudgeConformalMap(const ConformalMapResult& result, double convergenceTolerance);
}

#endif
