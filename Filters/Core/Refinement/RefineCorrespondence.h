// The refinement of the Möbius registration's correspondence, from the two surfaces'
// spectral data to a point on the target for every source vertex: every candidate rotation
// of the registration screened by ZoomOut on the samples, each held on its side of the
// sphere; the one to keep chosen (CandidateChoice; with landmarks among the maps that keep
// the distances to them, LandmarkConsistency); its orientation repaired when no candidate
// reached the expected one; its basis grown to the full size; the map extended to every
// vertex and, on request, polished on the surfaces (SurfacePolish), on further request in
// both directions, each point then averaged with the inverse of the other direction's map
// (InverseAveraging). When the runner-up came close, its map is finished too and the two
// finished maps are compared by their score times their stretch (ChooseByFinishedMaps).
#ifndef mobius_RefineCorrespondence_h
#define mobius_RefineCorrespondence_h

#include "CandidateChoice.h"
#include "SphericalPointLocator.h"
#include "ZoomOut.h"

#include <functional>
#include <string>
#include <vector>

namespace mobius
{
using RotationMatrix = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

/// The registered spherical maps the candidates start from.
struct RegisteredSpheres
{
  const Points& Source; ///< the source's sphere points, turned by the registration's best transform
  const Points& Target; ///< the target's sphere points
  const Triangles& TargetTriangles;
  const SphericalPointLocator& TargetLocator; ///< built on Target and TargetTriangles
  /// The rotations of the aligned source that reach each candidate, the best one (identity)
  /// first.
  const std::vector<RotationMatrix>& Starts;
  /// The best transform reverses orientation (a reflection): its candidates' maps should too.
  bool BestReflects;
  /// Landmarks: (source vertex, target vertex), each source vertex one of the source's
  /// samples (AddPinnedSamples). Every candidate maps them onto their target vertices, the
  /// candidates whose starts bring them much farther apart on the sphere than the best one
  /// (kLandmarkAngleMargin) or whose maps keep the distances to them much worse than the
  /// best one (kLandmarkDistanceMargin) are not kept, and the polish holds them.
  std::vector<std::pair<Index, Index>> Landmarks = {};
};

/// A candidate whose start leaves the landmarks this much farther apart on the sphere (root
/// mean square angle, radians) than the closest start is not kept: about 20 degrees, far
/// less than a mirror image or a half turn moves them, more than the correlation's
/// candidates near one another differ.
constexpr double kLandmarkAngleMargin = 0.35;

/// No defaults here: RegistrationParameters holds them.
struct CorrespondenceRefinementOptions
{
  /// StartSize, Growth, FullResolutionIterations, NumberOfThreads; FinalSize is the
  /// screening size, at most BasisSize.
  ZoomOutParameters ZoomOut;
  int BasisSize;
  bool RepairOrientation;
  double SphereAnchorWeight;
  CandidateCriterion Criterion;
  /// The candidate to keep; -1: chosen by Criterion.
  int Candidate;
  bool GeometricPolish;
  /// With GeometricPolish: the map the other way polished too, on a second thread, and
  /// each point averaged with its inverse (InverseAveraging).
  bool BothDirections;
  /// Called with the share of the refinement done (0.7 after the screening, 0.85 before the
  /// kept map is finished); false after the screening stops the refinement.
  std::function<bool(double)> Progress;
};

struct RefinedCorrespondence
{
  /// Per candidate, its map after the screening.
  std::vector<SampleMap> Screened;
  /// Per candidate, how far its screened map moves the samples' distances to the landmarks
  /// (LandmarkDistanceDifference; all 0 without landmarks).
  std::vector<double> LandmarkDistanceDifferences;
  /// The candidate kept (the requested one, if any), its runner-up and margin, and the
  /// finished maps' stretch.
  CandidateChoice Choice;
  /// The kept candidate's map after the orientation repair and the basis growth.
  SampleMap Kept;
  /// The kept candidate's screened map had the wrong orientation (repaired with
  /// RepairOrientation).
  bool WrongOrientation = false;
  /// Per source vertex, its point on the target (polished with GeometricPolish, averaged
  /// with the inverse of the other direction's map with BothDirections).
  DenseMap Dense;
  /// Why the polish failed (the spectral map is kept); empty if it did not.
  std::string PolishError;
  /// Wall time of the stages; with BothDirections the polish's includes the other
  /// direction's extension and polish beyond the forward extension's (they run at the same
  /// time) and the averaging. The candidates' includes the runner-up's map when it was
  /// finished too and not kept (or the first kept's, when the runner-up won).
  double CandidateSeconds = 0, ExtensionSeconds = 0, PolishSeconds = 0;
  /// Progress asked to stop: nothing after the screening is filled.
  bool Stopped = false;
};

/// Empty when the basis sizes fit together (the ZoomOut starts at most at the full size),
/// else the error, a sentence naming the filter's settings StartBasisSize and BasisSize.
std::string CheckBasisSizes(int startBasisSize, int basisSize);

/// The rotations of the aligned source (its points turned by `best`) that reach each
/// candidate transform T: T best^-1 = T best^T (transforms are orthogonal), the identity (the
/// best one) first. A non-finite candidate, and the best one repeated, are left out.
std::vector<RotationMatrix> CandidateStarts(
  const RotationMatrix& best, const std::vector<RotationMatrix>& candidates);

/// Empty when `candidate` (-1: none given) is one of the registration's `count` candidates,
/// else the error, a sentence.
std::string CheckCandidate(int candidate, size_t count);

/// Refines the correspondence between `source` and `target` (prepared with
/// PrepareSpectralSurface on the surfaces of the registered spheres).
RefinedCorrespondence RefineCorrespondence(const SpectralSurface& source,
  const SpectralSurface& target, const RegisteredSpheres& spheres,
  const CorrespondenceRefinementOptions& options);
}

#endif
