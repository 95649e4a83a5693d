// The parameters of the whole registration job and their defaults: the one place every
// interface takes them from. The stage filters (their constructors), the command line
// (PipelineOptions, its --help), the Python module (through the filters' getters) and the
// ParaView plugin's XML (checked by TestParameterDefaults) all read these.
//
// Where a stage's own parameter struct holds a value, it is read from there, so that the
// stage's default and the registration's cannot drift apart.
#ifndef mobius_RegistrationParameters_h
#define mobius_RegistrationParameters_h

#include "ConformalMap.h"
#include "GeneralizedCentering.h"
#include "MeshTypes.h"
#include "MobiusCentering.h"
#include "SO3Correlation.h"
#include "ScaleFactorSignal.h"
#include "ZoomOut.h"

#include <string>
#include <vector>

namespace mobius
{
/// Allowed values of an integer parameter, both ends included.
struct IntegerRange
{
  int Minimum;
  int Maximum;
  bool Contains(long long value) const { return value >= Minimum && value <= Maximum; }
};

/// Allowed values of a real parameter, both ends included (NaN is in none).
struct NumberRange
{
  double Minimum;
  double Maximum;
  bool Contains(double value) const { return value >= Minimum && value <= Maximum; }
};

/// The allowed values, checked for every interface by CheckRegistrationParameters
/// (ParameterRules.h); the stage filters' setters clamp to them.
inline constexpr IntegerRange CenteringDegreeRange{ 1, 8 };
inline constexpr IntegerRange BasisSizeRange{ 2, 500 };
/// Correlation peaks refined: each costs a refinement, and 64 is far beyond a useful count.
inline constexpr IntegerRange CandidateCountRange{ 1, 64 };
inline constexpr IntegerRange CandidateRange{ -1, CandidateCountRange.Maximum - 1 }; ///< -1: the refinement chooses
/// Degrees between two candidates: two rotations are never more than 180 degrees apart.
inline constexpr NumberRange CandidateSeparationRange{ 0.0, 180.0 };
inline constexpr IntegerRange ThreadCountRange{ 0, 1024 };
/// An infinite or huge smoothing time wipes out the signals (exp(-l(l+1) t) leaves nothing
/// of degree 1 and up well before t = 1).
inline constexpr NumberRange SmoothingTimeRange{ 0.0, 1.0 };
/// The scale-factor grid of the registration is even and at least this; its upper end is
/// the machine's memory. Measured on CGAL's cow, hand, bull, man, camel and bear, each
/// registered with a rotated copy of itself: a grid of 4 (bandwidth 2) maps all six wrongly
/// (0.05-0.66 of sqrt(area)); from 6 on they come out right, but the man came out turned at 8.
inline constexpr int MinimumResolution = 8;
/// Below this grid size the registration warns that the rotation is coarse.
inline constexpr int ReliableResolution = 32;
/// The conformal flow stops when its relative change falls below the tolerance; in double
/// precision that change levels off near 1e-9 (CGAL meshes, measured), so a smaller tolerance
/// is never reached and the flow would run every one of its iterations.
inline constexpr double MinimumFlowTolerance = 1e-8;
/// A relative change above 1 is no tolerance.
inline constexpr NumberRange FlowToleranceRange{ MinimumFlowTolerance, 1.0 };

/// A point whose image the user knows: a source vertex and the target vertex it goes to,
/// as the meshes' 0-based vertex numbers (the files' numbers, `InputPointId`).
struct Landmark
{
  Index Source = 0;
  Index Target = 0;
  /// Where the user gave it, for messages: a file's line number (0: not from a file).
  int Line = 0;
};

/// How the landmarks steer the registration (RegistrationParameters::LandmarkMode).
enum class LandmarkMode
{
  /// The rotation search chooses among the correlation's transforms (and, with 3 or more,
  /// the landmarks' best-fit rotation) the one that brings the landmarks' sphere points
  /// closest together.
  ChooseRotation = 0,
  /// A Möbius transform of the source's sphere makes 3 landmarks meet their targets exactly
  /// on the sphere, and takes the place of the rotation.
  FitMobius = 1
};
inline constexpr IntegerRange LandmarkModeRange{ 0, 1 };
/// A Möbius transform of the sphere is fixed by 3 points and their images.
inline constexpr int FittedLandmarkCount = 3;

struct RegistrationParameters
{
  /// The inputs are centered spherical maps already (vtkMobiusCenter outputs, e.g. a
  /// collection's maps computed once per shape): the job starts at the rotational alignment.
  bool InputsAreCenteredMaps = false;
  // Conformal map (vtkSphericalConformalMap)
  int FlowIterations = ConformalMapParameters().MaximumNumberOfIterations;
  double FlowTolerance = ConformalMapParameters().ConvergenceTolerance;
  bool CenterBetweenSteps = ConformalMapParameters().MobiusCentering;
  /// Repair a mesh that is no closed, connected, manifold, oriented genus-0 surface into a
  /// genus-0 proxy (RepairMesh.h); false: strict, refuse it (FillHoles and
  /// KeepLargestComponent still repair on request).
  bool Repair = true;
  bool FillHoles = false;
  bool KeepLargestComponent = false;
  /// false: a degenerate conformal map (DegenerateMap in its field data) is an error
  bool AllowPoorMaps = false;
  // Centering (vtkMobiusCenter)
  double CenteringTolerance = MobiusCenteringParameters().Tolerance;
  double GeneralizedCenteringTolerance = GeneralizedCenteringParameters().Tolerance;
  /// Highest spherical-harmonic degree centered against, for both meshes of a registration:
  /// 1 the paper's Möbius centering; 2..8 its generalized centering (§5, Figure 5).
  int CenteringDegree = 1;
  bool Centering = true; ///< symmetry detection only: false for the uncentered comparison
  // Rotational alignment (vtkSO3Register)
  int Resolution = ScaleFactorSignalParameters().Resolution;
  double SmoothingTime = ScaleFactorSignalParameters().SmoothingTime;
  int TransformMode = static_cast<int>(SO3CorrelationOptions().Reflections); ///< 0 rotations, 1 reflections, 2 both
  int NumberOfCandidates = SO3CorrelationOptions().NumberOfCandidates;
  /// Correlation peaks closer than this (degrees) are not both kept as candidates. A body's
  /// ambiguities (the half turns that put the front on the back or the arms on the legs) are
  /// far apart, while a correlation peak has neighbours 10-45 degrees away that refine to the
  /// same map: at the search's own 10 degrees, two peaks of each of the two best ambiguities
  /// filled the four candidates, and on 7 of 26 non-isometric human pairs the right one was
  /// not among them (docs/accuracy.md, "Non-isometric pairs").
  double CandidateSeparation = 60.0;
  // Correspondence (vtkDenseCorrespondence, vtkCorrespondenceRefinement)
  int OutputGeometry = 0; ///< 0 target surface, 1 source surface
  bool Refine = true;     ///< spectral refinement of the Möbius map (false: the paper's map)
  int BasisSize = ZoomOutParameters().FinalSize;
  int StartBasisSize = ZoomOutParameters().StartSize;
  /// Every candidate is refined up to this many functions; the best goes on to BasisSize.
  int ScreeningBasisSize = 30;
  bool GeometricPolish = true; ///< the refinement's geometric polish
  /// The polish in both directions, each point averaged with the inverse of the other
  /// direction's map (InverseAveraging): FAUST_r errors about 3% lower for a second
  /// extension and polish, beside the first on a second core (docs/accuracy.md).
  bool BothDirections = true;
  int Candidate = -1;          ///< the refinement's candidate to keep (-1: it chooses)
  /// Points whose images the user knows: every stage keeps them (none by default).
  std::vector<Landmark> Landmarks;
  /// The file the landmarks were read from (Landmark::Line's), for messages; empty if none.
  std::string LandmarksFile;
  int LandmarkMode = static_cast<int>(mobius::LandmarkMode::ChooseRotation);
  /// Threads of every threaded stage (0: automatic, one per core of the CPU affinity mask,
  /// at most VTK_SMP_MAX_THREADS); the results do not depend on it.
  int NumberOfThreads = 0;
};

/// The spectral refinement compares BasisSize eigenfunctions and needs about twice as many
/// vertices to sample them: on a smaller surface (the smaller of the two maps) the Möbius
/// map is the answer.
bool RefinementApplies(Index vertexCount, int basisSize);

/// The basis sizes the refinement runs with: none above BasisSize.
int ClampToBasisSize(int size, int basisSize);
}

#endif
