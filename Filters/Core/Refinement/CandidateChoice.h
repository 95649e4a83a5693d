// Which of the refinement's candidate maps to keep (one per candidate rotation of the Möbius
// registration, each refined by ZoomOut on the samples), and how sure that choice is.
//
// A map of the orientation its rotation asks for (a rotation preserves orientation, a
// reflection reverses it) beats one of the other. Among those, the functional map's
// orthogonality cannot tell a human body from the same body turned half a turn about its
// vertical axis (left on right and front on back: orientation-preserving, and nearly an
// isometry, since a body's front and back are nearly mirror images of each other), and
// neither can any intrinsic measure of the first eigenfunctions. The surfaces' mean
// curvature can: faces, toes, kneecaps, breasts are features of the front. So the kept map
// is the one whose images keep the source's smoothed mean curvature best (measured on 100
// FAUST_r training pairs: the half-turned map is chosen in none of them, against 39 with
// the orthogonality residual).
#ifndef mobius_CandidateChoice_h
#define mobius_CandidateChoice_h

#include "ZoomOut.h"

#include <limits>
#include <vector>

namespace mobius
{
/// Two candidate maps whose images of the same source samples lie closer than this on
/// average (in units of sqrt(target area)) are one map reached twice (two rotations of the
/// registration often converge to the same map): the margin is measured to a different one.
constexpr double kSameMapDistance = 0.05;

/// Below this relative margin the runner-up is called near-equal (the CLI warns).
constexpr double kNearEqualMargin = 0.05;

struct CandidateChoice
{
  int Kept = 0;
  /// The best candidate of the expected orientation whose map differs from the kept one;
  /// -1 when there is none.
  int RunnerUp = -1;
  /// (runner-up's score - kept's) / kept's score, the score being what the criterion
  /// compares; infinite without a runner-up.
  double Margin = std::numeric_limits<double>::infinity();
};

/// What tells candidates of the expected orientation apart.
enum class CandidateCriterion
{
  /// The curvature difference (the orthogonality residual where a surface has none): for
  /// registration, where the half-turned body must lose.
  Curvature,
  /// The orthogonality residual alone, intrinsic: for a mesh's own mirror symmetry, where a
  /// pose can make another reflection an exact extrinsic symmetry (a body bent sideways
  /// stays its own front-back mirror image, with every curvature kept) while the intrinsic
  /// left-right symmetry is what is asked for.
  Orthogonality
};

/// Chooses among screened candidates: `rightSide[c]` says whether candidate c's map has the
/// orientation its rotation asks for.
CandidateChoice ChooseCandidate(const std::vector<SampleMap>& screened,
  const std::vector<bool>& rightSide, const SpectralSurface& target,
  CandidateCriterion criterion = CandidateCriterion::Curvature);

/// Mean distance between the images of the same source samples under two sample maps, in
/// units of sqrt(target area).
double SampleMapDistance(
  const SampleMap& a, const SampleMap& b, const SpectralSurface& target);
}

#endif
