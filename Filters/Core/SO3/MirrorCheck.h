// Whether the pair looks mirrored. The registration searches rotations (or reflections) only,
// as asked: a target that is the source's mirror image then gets the best rotation, which is
// wrong, and nothing says so. A second, cheap correlation finds the best transform of the
// other determinant; when it fits far better, the interfaces say "the shapes look mirrored".
//
// Measured with the coarse search (registration errors, chosen kind / other kind, CGAL meshes
// at resolution 64): the hand, bunny and armadillo onto their mirror images by rotations
// 0.020 / 0.001, 0.020 / 0.0009, 0.041 / 0 (warned); the cow, nearly symmetric, not warned.
// Full-resolution errors of real pairs, where a body's mirror image is nearly itself, differ
// by a few percent (SMPL man -> woman 0.0895 / 0.0857, FAUST_r training pairs 0.168 / 0.167,
// 0.160 / 0.163); 5 FAUST_r training pairs, SMPL and 33 generated pose pairs: no warning.
#ifndef mobius_MirrorCheck_h
#define mobius_MirrorCheck_h

#include "SO3Correlation.h"

namespace mobius
{
struct MirrorCheck
{
  /// Registration errors of the best transform of the kind searched and of the other kind,
  /// both from the same coarse search; -1 when not checked (mode Both).
  double ChosenError = -1.0;
  double OtherError = -1.0;
  /// The other kind's error is below half the chosen kind's and at least 0.01 lower (a nearly
  /// symmetric shape, such as the cow, fits both ways almost equally well, and either map is
  /// right up to its symmetry).
  bool OtherFitsFarBetter = false;
};

/// The rule of MirrorCheck::OtherFitsFarBetter, for errors measured before (field data
/// MirrorCheckErrors: the refinement reads it to know that no candidate of the kind searched
/// can be right, and says so instead of suggesting another one).
bool OtherKindFitsFarBetter(double chosenError, double otherError);

/// Both kinds' best fits by a coarse search (one candidate each, a grid of bandwidth 16,
/// polished on that band-limited correlation), for the options' mode; nothing for mode Both.
MirrorCheck CheckMirroring(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, const SO3CorrelationOptions& options);
}

#endif
