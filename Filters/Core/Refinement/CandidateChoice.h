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
//
// Between two bodies of different proportions (an ape's arms and legs, thick or thin
// limbs) the curvatures differ for real, and the screened map of the right candidate and
// that of the half-turned body can keep them about equally well. When the runner-up comes
// within kFinishRunnerUpMargin, both maps are finished (extended to every vertex and
// polished) and their stretch is weighed too: the polish makes the right map nearly as rigid
// as the two bodies allow, while a turned map must twist where the front and the back differ
// (the feet, the face) and stays stretched there. The map with the lower product of its
// curvature difference and its finished map's mean edge stretch is kept, so that whichever
// of the two tells the maps apart more clearly decides: on generated non-isometric human
// pairs where the two finalists differ by at most 1% in one, the other told them apart
// (docs/accuracy.md, "Non-isometric pairs").
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

/// Below this relative margin of the screened maps' score (with the geometric polish on),
/// the runner-up's map is finished too and the two are compared by score times stretch
/// (ChooseByFinishedMaps): the curvature chose the wrong one of two finalists at margins of
/// 0.3-5.3% on generated non-isometric pairs, and twice that leaves room.
constexpr double kFinishRunnerUpMargin = 0.1;

struct CandidateChoice
{
  int Kept = 0;
  /// The best candidate of the expected orientation whose map differs from the kept one;
  /// -1 when there is none.
  int RunnerUp = -1;
  /// (runner-up's score - kept's) / kept's score, the score being what decided (the
  /// criterion's, or with ByFinishedMaps the criterion's times the finished map's stretch);
  /// infinite without a runner-up.
  double Margin = std::numeric_limits<double>::infinity();
  /// Per candidate, what the criterion compared (the screened map's curvature difference,
  /// or its orthogonality residual).
  std::vector<double> Score;
  /// Both maps were finished and compared by score times stretch (ChooseByFinishedMaps),
  /// which decided.
  bool ByFinishedMaps = false;
  /// Per candidate, the mean edge stretch of its finished map (MeanEdgeStretch); NaN for a
  /// candidate whose map was not finished.
  std::vector<double> Stretch;
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

/// Decides between the kept candidate and its runner-up, both maps finished, by the product
/// of each one's Score and its finished map's mean edge stretch (the lower is kept): records
/// both stretches, swaps Kept and RunnerUp if the runner-up's product is lower, and measures
/// the margin on the product. `candidates` is the number of candidates (the size of
/// Stretch).
void ChooseByFinishedMaps(
  CandidateChoice& choice, size_t candidates, double keptStretch, double runnerUpStretch);

/// Mean distance between the images of the same source samples under two sample maps, in
/// units of sqrt(target area).
double SampleMapDistance(
  const SampleMap& a, const SampleMap& b, const SpectralSurface& target);
}

#endif
