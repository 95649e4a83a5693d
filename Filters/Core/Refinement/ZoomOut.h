// Spectral refinement of a pointwise map between two surfaces: ZoomOut (Melzi, Ren, Rodolà,
// Sharma, Wonka & Ovsjanikov, "ZoomOut: Spectral Upsampling for Efficient Shape
// Correspondence", SIGGRAPH Asia 2019), run on evenly spread vertex samples and extended to
// every vertex at the end, with the mapped points placed inside target triangles.
//
// Conventions: Phi_S (n_S x k) and Phi_T (n_T x k) are the surfaces' Laplace-Beltrami
// eigenfunctions, mass-orthonormal on the unit-area surfaces. A pointwise map T (source
// vertex i -> target vertex T(i)) and the functional map C (k x k) are related by
// Phi_S C ~ Pi Phi_T, i.e. row T(i) of Phi_T ~ row i of Phi_S times C; C pulls target
// functions back to the source. An area-preserving map has an orthogonal C.
#ifndef mobius_ZoomOut_h
#define mobius_ZoomOut_h

#include "Curvature.h"
#include "LaplaceBeltramiBasis.h"
#include "MeshAdjacency.h"
#include "MeshTypes.h"
#include "SpectralSearch.h"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace mobius
{
/// What the refinement needs of one surface, computed once and reused for every candidate
/// start.
struct SpectralSurface
{
  Points Positions;     ///< the surface's vertices
  Points Normals;       ///< area-weighted unit vertex normals
  Triangles Faces;
  RowMatrix Embedding;  ///< n x k eigenfunction values, one row per vertex
  Vector Eigenvalues;   ///< k, ascending, of the unit-area surface
  SparseMatrix Mass;    ///< mass matrix of the unit-area surface (Embedding is orthonormal in it)
  VertexLists Neighbors;
  VertexLists Corners;  ///< triangles around each vertex
  std::vector<Index> Samples;      ///< vertex indices, farthest-point order
  std::vector<Index> SampleLabels; ///< per vertex: position in Samples of its nearest sample
  /// Smoothed mean curvature per vertex (kCandidateCurvature):
  /// compared between the surfaces to choose among candidate maps.
  Vector Curvature;
  /// The curvatures the geometric polish matches, one vector per entry of kPolishCurvatures.
  std::vector<Vector> PolishCurvatures;
  /// Triangles of samples (positions in Samples), one per mesh triangle whose corners have
  /// three different nearest samples: a coarse triangulation to check orientation on.
  std::vector<std::array<Index, 3>> SampleTriangles;
};

/// Eigenbasis of `basisSize` functions, adjacency and `sampleCount` samples of a closed
/// manifold triangle mesh; `consistentMassShare` is the eigenproblem's mass option
/// (ComputeLaplaceBeltramiBasis). False with `error` set if the eigenbasis cannot be computed.
bool PrepareSpectralSurface(const Points& points, const Triangles& triangles, int basisSize,
  Index sampleCount, SpectralSurface& surface, std::string& error,
  double consistentMassShare = 0.0);

/// The same from an eigenbasis computed earlier (ComputeLaplaceBeltramiBasis on these points
/// and triangles): the surface is then identical, bit for bit, to PrepareSpectralSurface's.
void PrepareSpectralSurface(const Points& points, const Triangles& triangles,
  LaplaceBeltramiBasis basis, Index sampleCount, SpectralSurface& surface);

struct ZoomOutParameters
{
  /// Basis size of the first iteration. Small: a few smooth functions are all a start with
  /// whole limbs misplaced can pin down, and growing from there keeps the limbs from locking
  /// onto their mirror counterparts (measured: starting at 4 rather than 12-20 turns maps
  /// with 10-15% of the vertices on the wrong limb into maps with none).
  int StartSize = 4;
  int FinalSize = 80;  ///< basis size of the last (at most the surfaces' basis size)
  double Growth = 0.15; ///< the basis grows by this fraction per iteration (at least by 1)
  /// Iterations on all vertices after the extension, each with the exact nearest rows: one
  /// scores as two (FAUST_r training pairs) at less than half the cost.
  int FullResolutionIterations = 1;
  /// Weights of the smoothed mean and Gaussian curvatures (kPolishCurvatures, both
  /// surfaces' in the target's root mean square) as extra coordinates of the nearest-row
  /// searches on all vertices, each relative to one eigenfunction. Curvature does not change
  /// with the pose where the skin does not stretch: it holds the spectral map's slides on
  /// smooth parts (FAUST_r training pairs: 1.344 -> 1.319 at 3, alike at 2-6, worse at 10;
  /// docs/DEVELOPMENT.md, "Curvature in the spectral map"). 0: the eigenfunctions alone.
  std::array<double, kPolishCurvatures.size()> FullResolutionCurvatureWeights{ 3.0, 3.0 };
  /// The same in the iterations on the samples, from basis size SampleCurvatureFromSize on:
  /// after the candidates are screened (RegistrationParameters::ScreeningBasisSize, 30),
  /// once the eigenfunctions place the limbs. Lower than on all vertices: 1,000 samples are
  /// far apart beside the curvatures' features, and at 2-3 a sample can jump to a far one of
  /// like curvature (a bent copy of CGAL's man came out with 0.6% of its vertices wrong).
  /// FAUST_r training pairs: 1.321 -> 1.305 and 1.357 -> 1.339 (docs/DEVELOPMENT.md, "On the
  /// samples too").
  std::array<double, kPolishCurvatures.size()> SampleCurvatureWeights{ 1.0, 1.0 };
  int SampleCurvatureFromSize = 40;
  /// The orientation the sample map should have: +1 preserved (the registration is a
  /// rotation), -1 reversed (a reflection), 0 either. When not 0, an iteration whose map
  /// comes out decisively of the other orientation is retried with the sign of one
  /// eigenfunction negated (see ZoomOutOnSamples).
  int Orientation = 0;
  int NumberOfThreads = 0;          ///< 0: one per core
};

/// The map between the samples after ZoomOut, and how good it looks without ground truth.
struct SampleMap
{
  std::vector<Index> TargetVertex;  ///< per source sample, a target vertex (a target sample)
  Eigen::MatrixXd FunctionalMap;    ///< FinalSize x FinalSize
  /// |C^T C - I|_F / sqrt(k): 0 for an area-preserving (e.g. isometric) map. Candidate
  /// starts that put parts on the wrong side converge to maps far from orthogonal.
  double OrthogonalityResidual = 0;
  /// Share of target samples that are the image of some source sample: low when the map
  /// folds several parts of the source onto one part of the target.
  double TargetCoverage = 0;
  /// Share of sample triangles whose image keeps their orientation (facing the same side of
  /// the surface): near 1 for an orientation-preserving map, near 0 for a mirror image.
  double OrientationAgreement = 0;
  /// Mean over the source samples of |H_source - H_target at the image| (the surfaces'
  /// smoothed mean curvatures): low when the map keeps the shape's features on their
  /// counterparts, higher for a near-isometry that puts the front on the back. NaN when a
  /// surface has no curvature.
  double CurvatureDifference = 0;
};

/// Coordinates that hold a sample map near where its start put it: per source sample and per
/// target sample a point in a space the two share (the unit spheres after the Möbius
/// registration, the source's turned by the candidate's rotation), appended with `Weight` to
/// the eigenfunction values in every nearest-row search. The spectral search alone cannot
/// tell a body's front from its back: the first eigenfunctions of a human are nearly
/// symmetric under both the left-right and the front-back reflection, and ZoomOut slides a
/// right start into one of them. The rotation on the sphere cannot reflect, so the sphere
/// keeps each side on its side, while it allows the large moves along limbs that the
/// refinement must make (a conformal map squeezes a limb into a small patch of the sphere).
struct SampleAnchor
{
  RowMatrix Source; ///< row s: source sample s
  RowMatrix Target; ///< row t: target sample t
  double Weight = 0; ///< 0: no anchor
  /// Landmarks: (position in the source's Samples, target vertex). Each pinned sample maps
  /// to its target vertex in every iteration (a hard constraint of the pointwise step), and
  /// counts kPinnedSampleWeight times in the fit of the functional map.
  std::vector<std::pair<Index, Index>> Pins;
};

/// How many ordinary samples a landmark weighs in the functional map's fit: enough for a few
/// landmarks to steer the low frequencies against a thousand samples that follow a wrong
/// start (at 1, CGAL's man onto a stretched copy stays wrong), not so much that the fit bends
/// the rest of a non-isometric map towards them (from 8 on, some generated pairs come out
/// worse with 5 exact landmarks than without; docs/landmarks.md, "Measured").
constexpr double kPinnedSampleWeight = 5.0;

/// Adds `vertices` (landmarks) to the surface's samples where they are not samples yet, and
/// makes each the nearest sample of its own vertex.
void AddPinnedSamples(SpectralSurface& surface, const std::vector<Index>& vertices);

/// ZoomOut from `initialTargetVertex` (one target vertex per source sample, e.g. read off
/// the Möbius map) on the samples of both surfaces.
///
/// Orientation: the first few eigenfunctions of a bilaterally symmetric shape are all
/// symmetric, so the first iterations cannot tell a point from its mirror counterpart and
/// scramble the start's left and right; the first antisymmetric eigenfunction then enters
/// with a sign fitted to that scrambled map, and which of the two near-isometries (the map
/// or its mirror image) ZoomOut converges to is decided by noise. With
/// `parameters.Orientation` set, an iteration whose map has at most
/// `kOrientationDecided` of its sample triangles on the expected side is redone with each
/// of the first kOrientationRows non-constant rows of its functional map negated in turn,
/// and the best-oriented result is kept if at least 1 - kOrientationDecided of its
/// triangles are on the expected side (at most kOrientationTries iterations per run).
SampleMap ZoomOutOnSamples(const SpectralSurface& source, const SpectralSurface& target,
  const std::vector<Index>& initialTargetVertex, const ZoomOutParameters& parameters,
  const SampleAnchor& anchor = SampleAnchor());

/// The sample map read off a functional map C (k x k, any k up to the basis size): each
/// source sample goes to the target sample whose row of Phi_T C^T is nearest to its row of
/// Phi_S.
std::vector<Index> SampleMapFromFunctionalMap(const SpectralSurface& source,
  const SpectralSurface& target, const Eigen::MatrixXd& functionalMap, int numberOfThreads);

/// Tries to turn a map that reverses orientation where it should not (a bilaterally
/// symmetric shape mapped onto the mirror image of the target: C = D C_true, with D = -1 on
/// the source's antisymmetric eigenfunctions) into one that preserves it: negates, in turn,
/// each of the first `flips` non-constant rows of the map's functional map (refitted on
/// flips + 1 functions), runs ZoomOut from each on to `parameters.FinalSize`, and returns the most orthogonal result that agrees with the expected orientation,
/// or `reversed` itself if none does.
SampleMap RepairOrientation(const SpectralSurface& source, const SpectralSurface& target,
  const SampleMap& reversed, bool preserveOrientation, int flips,
  const ZoomOutParameters& parameters, const SampleAnchor& anchor = SampleAnchor());

/// Share of sample triangles on the expected side at or below which ZoomOutOnSamples
/// calls an iteration's map decisively of the wrong orientation (a scrambled map, before
/// any antisymmetric eigenfunction is in the basis, has about one half).
constexpr double kOrientationDecided = 0.25;
/// How many iterations of one ZoomOutOnSamples run may retry with a sign flipped, and
/// among how many of the first non-constant eigenfunctions (each try costs one
/// nearest-row search per function).
constexpr int kOrientationTries = 3;
constexpr int kOrientationRows = 10;

/// True when a sample map has the orientation it should have: agreement above one half for
/// an orientation-preserving map, below for an orientation-reversing one.
inline bool HasOrientation(const SampleMap& map, bool preserveOrientation)
{
  return preserveOrientation ? map.OrientationAgreement > 0.5 : map.OrientationAgreement < 0.5;
}

/// A point on the target surface for every source vertex.
struct DenseMap
{
  std::vector<Index> Triangle;                ///< target triangle
  std::vector<Eigen::Vector3d> Barycentric;   ///< in that triangle
  std::vector<Index> NearestVertex;           ///< target vertex nearest in the embedding
  Eigen::MatrixXd FunctionalMap;              ///< of the final vertex map
  double OrthogonalityResidual = 0;
};

/// Extends a sample map to every source vertex: each vertex starts from the image of its
/// nearest sample and descends on the target mesh towards the vertex nearest in the
/// embedding; `FullResolutionIterations` ZoomOut steps at full size follow, each with the
/// exact nearest rows (NearestRowsByClusters); each point is finally projected onto the
/// target triangles around its vertex.
/// `pinned` (source vertex, target vertex): landmarks, mapped onto their target vertices.
DenseMap ExtendToAllVertices(const SpectralSurface& source, const SpectralSurface& target,
  const SampleMap& samples, const ZoomOutParameters& parameters,
  const std::vector<std::pair<Index, Index>>& pinned = {});

/// The basis size after `size` in the schedule: size + max(1, floor(size x growth)).
int NextBasisSize(int size, double growth);

/// |C^T C - I|_F / sqrt(k).
double OrthogonalityResidual(const Eigen::MatrixXd& functionalMap);
}

#endif
