// Whether a candidate's map keeps the landmarks between them, not only at them.
//
// Each landmark's source sample is pinned to its target vertex in every ZoomOut iteration,
// but the other samples follow the candidate's start. A start that brings the landmarks'
// sphere points near their targets can still have the body between them turned: on a
// generated pair of a human onto an ape-like copy of it, with the head, the hands and the
// feet as landmarks, the candidate kept mapped every landmark exactly while the torso, the
// arms and the legs went half a turn round (each hand's neighbours on the other hand), and
// it kept the curvature better than the right map did. Such a map does not keep the
// distances to the landmarks: a point beside the left hand lands far from it. So every
// screened map is measured by how well each sample's edge-path distances to the landmarks
// are kept, and a candidate far worse than the best is not kept.
#ifndef mobius_LandmarkConsistency_h
#define mobius_LandmarkConsistency_h

#include "ZoomOut.h"

#include <utility>
#include <vector>

namespace mobius
{
/// A candidate whose LandmarkDistanceDifference exceeds the lowest one by more than this
/// share of it is not kept. The right maps of one pair differ by a few percent, a map turned
/// between its landmarks by 40-50% or more (docs/landmarks.md, "Between the landmarks").
constexpr double kLandmarkDistanceMargin = 0.2;

/// Per vertex of `surface`, the edge-path distance to each of `landmarks` (one vector per
/// landmark), over the square root of the surface's area.
std::vector<Vector> LandmarkDistances(
  const SpectralSurface& surface, const std::vector<Index>& landmarks);

/// The mean, over the source's samples and the landmarks, of |d_S(s, l) - d_T(T(s), l')|:
/// how far the sample map moves each sample's distances to the landmarks (from
/// LandmarkDistances of the source with the source landmarks and of the target with their
/// targets, in the same order). 0 for a map that keeps them all.
double LandmarkDistanceDifference(const SpectralSurface& source, const SampleMap& map,
  const std::vector<Vector>& sourceDistances, const std::vector<Vector>& targetDistances);

/// Per screened map, its LandmarkDistanceDifference (all 0 without landmarks).
std::vector<double> LandmarkDistanceDifferences(const SpectralSurface& source,
  const SpectralSurface& target, const std::vector<SampleMap>& screened,
  const std::vector<std::pair<Index, Index>>& landmarks);

/// Per screened map, whether its difference is within kLandmarkDistanceMargin of the lowest
/// among the `eligible` ones (all true when none is eligible).
std::vector<bool> KeepsLandmarkDistances(
  const std::vector<double>& differences, const std::vector<bool>& eligible);
}

#endif
