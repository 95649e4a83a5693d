// Whether the user's landmarks agree with the map the registration made: the check after
// the final map, and its warning. A contradiction among the landmarks (two swapped, a mirror
// image searched by rotations only, another vertex numbering, a Candidate against them)
// would otherwise go through silently: the map is bent to meet them.
#ifndef mobius_LandmarkDisagreement_h
#define mobius_LandmarkDisagreement_h

#include "LandmarkAlignment.h"
#include "RegistrationParameters.h"

#include <string>
#include <vector>

namespace mobius
{
/// The warning when the landmarks disagree with the map: the transform the map starts
/// from, candidate `kept` (of the correlation's `candidates`, best first; the aligned source
/// is candidate 0's, so candidate c is reached by T_c T_0^T), leaves landmarks more than
/// kLandmarkDisagreementAngle from their targets. `landmarks` are on the aligned source's
/// sphere and on the target's centered one. The warning names them and, when there is one,
/// the fix: another candidate, or the kind of transform not searched. Empty when they agree,
/// without landmarks, and with LandmarkMode 1 (whose Möbius fit meets the first 3 by
/// construction).
std::string LandmarkDisagreement(const std::vector<Eigen::Matrix3d>& candidates, int kept,
  const SphereLandmarks& landmarks, const RegistrationParameters& options);
}

#endif
