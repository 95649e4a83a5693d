// Geometric polish of a dense surface map (source vertex -> point on the target), after the
// spectral refinement: non-rigid ICP with an as-rigid-as-possible regularizer.
//
// The spectral map is right to about an edge length but slides in thin parts, by an amount
// set by how well the coarse mesh's Laplacian is discretized, not by the search. Geometry can
// finish it: a near-isometric copy is locally rigid, so the source mesh, deformed as rigidly
// as it can be while its vertices lie on the target, lands on the true images. Unknowns are
// positions y_i (one per source vertex, starting at the mapped points z_i); each iteration
// fits a rotation R_i per vertex to its neighbourhood (the ARAP local step), finds the point
// c_i of the target closest to y_i, and solves
//
//   min  ARAP(y; x, R) + Fit sum_i d_i |y_i - c_i|^2 + Anchor sum_i d_i |y_i - z_i|^2
//
// (x: the source scaled to the target's area; ARAP on the intrinsic Delaunay cotangent
// weights; d_i: vertex area over mean vertex area). The system matrix L + (Fit + Anchor) D
// does not change, so it is factored once (the closest-point term is point-to-point, not
// point-to-plane, for that reason: along the surface it only holds y_i near its last
// position, which slows slides down but does not stop them; heavy-ball momentum makes up for
// most of it). A correspondence that looks wrong (c_i farther than RejectDistance mean
// target edges from y_i, or the target facing another way than the rotated source normal)
// pulls y_i towards where it already is instead, which keeps the matrix fixed while that
// vertex follows its neighbours. Finally each y_i is projected onto the target (closest
// points by walking over the target's triangles from the last one); a vertex that ends far
// from the target keeps its spectral point.
//
// Given the surfaces' smoothed curvatures h_k (mean and Gaussian), c_i is moved towards the
// closest point in the product of space and curvature: one Gauss-Newton step from c_i, in
// its triangle's plane, on |c - p|^2 + sum_k (CurvatureWeights[k] sqrt(target area))^2
// (h_k,i - h_k(p))^2. Position alone lets a map slide along a smooth part (a torso, a
// thigh) to wherever the rigid prior puts it, which is not where the truth is when a pose or
// a person stretches the skin unevenly: on 10 FAUST_r training pairs a map started at the
// ground truth (0.44) drifted to 1.44 without the pull to the spectral map. Curvature holds
// the slide where it varies; the two curvatures vary in different directions, so together
// they hold it in more places (docs/DEVELOPMENT.md, "Curvature in the polish").
//
// How far to trust the rigid prior is measured on the pair itself. ARAP is right for a
// near-isometric pair; between two poses (skin stretching at the joints) or two people it
// pulls a map off the truth: FAUST_r maps started at the ground truth drifted from 0.44 to
// 1.26 within 15 iterations, by slides that trade the true stretch for rigidity. Halfway
// through, the polish measures the mean ARAP residual of its map, sum_j w_ij |y_j - y_i -
// R_i (x_j - x_i)|^2 over sum_j w_ij |x_j - x_i|^2 (area-weighted). Measured: CGAL's cow
// and man onto bent copies 0.0015-0.0024, SMPL's man -> woman (one pose) 0.0027-0.0029, the
// hand onto a bent copy 0.005, generated pose pairs of CGAL's animals 0.002-0.009, FAUST_r
// pairs 0.008-0.025. Above RigidResidual the closest-point fit grows in proportion for the
// second half (at most MaximumFitGain times), so the target's shape and curvatures hold the
// map against the rigid prior's slides, and the curvatures' weights follow
// GainedCurvatureScales (docs/DEVELOPMENT.md, "Trusting the rigid prior less").
//
// Measured (README, Accuracy): on rotated re-triangulated copies the mean error falls from
// 4.9e-3..7.9e-3 to 0.6e-3..3.2e-3 of sqrt(area), on bent copies by a fifth to a half, on
// SMPL's man -> woman (not isometric: different bodies) by more than half.
#ifndef mobius_SurfacePolish_h
#define mobius_SurfacePolish_h

#include "Curvature.h"
#include "MeshAdjacency.h"
#include "MeshTypes.h"

#include <Eigen/Core>

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace mobius
{
struct SurfacePolishParameters
{
  /// Slides of whole parts along the target converge slowly (see above): more iterations
  /// keep lowering the error of real pose pairs up to about this many, at a cost small
  /// beside the refinement's (docs/DEVELOPMENT.md, "Where the remaining FAUST_r error is").
  int Iterations = 60;
  /// Weight of the closest-point term per vertex, against the ARAP energy (whose weights
  /// per vertex sum to about 2-4 on a regular mesh): of order 1 balances the two at the
  /// scale of an edge. Below 1 since the closest points match curvatures, whose steps the
  /// rigid prior then smooths more (FAUST_r training pairs: 0.6 scored 1% better than 1,
  /// 2 4% worse; docs/DEVELOPMENT.md, "Curvature in the polish").
  double Fit = 0.6;
  /// Weight of the pull back to the spectral map: small, it only keeps directions the
  /// geometry does not fix (sliding along a featureless cylinder) where they were. Any more
  /// holds back the slides the polish is for (docs/DEVELOPMENT.md, "The polish's anchor":
  /// 0.005 and 0.02 score worse on FAUST_r, bent and re-triangulated copies; 0 and 0.001
  /// no better than this).
  double Anchor = 0.002;
  /// Smoothed curvatures of each surface per vertex, one vector per entry of
  /// kPolishCurvatures (SmoothedCurvatures); empty: positions alone.
  std::vector<Vector> SourceCurvatures;
  std::vector<Vector> TargetCurvatures;
  /// Weight of a unit of each curvature (of the unit-area surface) against distance, in
  /// units of sqrt(target area): a mean curvature mismatch of 1 counts like a distance of
  /// 0.0008 sqrt(area). In area units, not edge lengths, so that it means the same at every
  /// resolution (bodies of 20,000 vertices gained 1.6 times as much so). More helps FAUST_r's
  /// pairs of different people, less SMPL's man -> woman, whose curvatures differ for real:
  /// both gain at these weights. The Gaussian curvature's at twice the weight scored FAUST_r
  /// 4% better but SMPL 24% worse (docs/DEVELOPMENT.md, "Curvature in the polish").
  std::array<double, kPolishCurvatures.size()> CurvatureWeights{ 0.0008, 0.0004 };
  /// Mean relative ARAP residual (see above) up to which a pair counts as near-isometric:
  /// its map keeps Fit throughout. Above SMPL's man -> woman and CGAL's bent copies but the
  /// hand's, below FAUST_r's pairs.
  double RigidResidual = 0.004;
  /// A pair's Fit for the second half of the iterations is Fit times its mean ARAP residual
  /// over RigidResidual, at most this: FAUST_r training pairs (residuals 0.008-0.025) scored
  /// 3% better with the gain (2.5 for most), no better at 4. One gain for every pair scored
  /// FAUST_r alike but SMPL's man -> woman 14% worse (docs/DEVELOPMENT.md, "Trusting the rigid
  /// prior less").
  double MaximumFitGain = 2.5;
  /// Where the fit gained, each curvature's weight over the second half goes linearly from
  /// the first of these times its CurvatureWeights to the second times it: the mean
  /// curvature's stays, the Gaussian curvature's goes from 0.0012 down to 0.0002. It first
  /// holds the map harder against the slides the larger fit lets through, then lets go, as
  /// two bodies' Gaussian curvatures differ for real: FAUST_r training pairs scored 2.2%
  /// better than at a constant 0.0004 (from 0.0008: 1.3%; from 0.0016: the same mean, a
  /// worse median pair; down to 0.0004: 1.6%). Near-isometric pairs keep CurvatureWeights.
  std::array<std::array<double, 2>, kPolishCurvatures.size()> GainedCurvatureScales{ {
    { 1.0, 1.0 }, { 3.0, 0.5 } } };
  /// Closest points farther than this many mean target edge lengths are not trusted.
  double RejectDistance = 3.0;
  /// Closest points whose target normal makes a larger angle than this cosine allows with
  /// the rotated source normal are not trusted (the other side of a thin part).
  double MinimumNormalCosine = 0.3;
  /// Each iteration's solution is pushed on by this share of its step from the last one
  /// (heavy-ball momentum): slides of whole parts, which the closest-point term (anchored at
  /// the last iterate along the surface) lets through only slowly, converge several times
  /// faster (0.9 scored FAUST_r training pairs 1.3% better than 0.8, and with Fit 0.6 CGAL's
  /// cow onto its bent and subdivided copies too).
  double Momentum = 0.9;
  /// The map reverses orientation (a mirror image, e.g. a bilateral self-map): the source
  /// is mirrored first, so that rotations can follow it.
  bool ReverseOrientation = false;
  /// Landmarks (source vertex, target vertex): each source vertex is pulled onto its target
  /// vertex PinWeight times as hard as onto a closest point, and ends there exactly.
  std::vector<std::pair<Index, Index>> Pinned;
  double PinWeight = 100.0;
  int NumberOfThreads = 0; ///< 0: one per core
};

struct SurfacePolishInfo
{
  Index Rejected = 0;  ///< correspondences not trusted in the last iteration
  Index KeptSpectral = 0; ///< vertices that kept their spectral point
  double RigidResidual = 0; ///< the mean relative ARAP residual measured halfway
  double FitGain = 1;       ///< the Fit gain it gave the second half
  std::string Error;
};

/// The polish a few iterations at a time, so that two polishes (a map and the map the other
/// way) can meet between iterations and move towards each other (InverseAveraging). The
/// surfaces and parameters given to Start are referenced, not copied: they must outlive it.
class SurfacePolisher
{
public:
  SurfacePolisher();
  ~SurfacePolisher();
  SurfacePolisher(const SurfacePolisher&) = delete;
  SurfacePolisher& operator=(const SurfacePolisher&) = delete;

  /// Sets up the polish of the map given as a target triangle and barycentric coordinates
  /// per source vertex (as PolishSurfaceMap takes it). False with Info().Error set if the
  /// source's Laplacian cannot be built or factored.
  bool Start(const Points& sourcePoints, const Triangles& sourceTriangles,
    const Points& targetPoints, const Triangles& targetTriangles,
    const VertexLists& targetVertexTriangles, const std::vector<Index>& triangle,
    const std::vector<Eigen::Vector3d>& barycentric, const SurfacePolishParameters& parameters);
  /// Runs up to `count` more of the parameters' Iterations. False with Info().Error set if
  /// the system could not be factored again (the map is then unusable).
  bool Iterate(int count);
  /// The iterations run so far.
  int Iterations() const;
  /// The current solution on the target (closest points, found by walking from the last
  /// triangles); a vertex far from the target keeps its spectral point, a landmark sits on
  /// its target vertex.
  void CurrentMap(std::vector<Index>& triangle, std::vector<Eigen::Vector3d>& barycentric);
  /// Moves the current solution to the points of the map given, keeping each vertex's
  /// momentum (its last step).
  void MoveTo(const std::vector<Index>& triangle, const std::vector<Eigen::Vector3d>& barycentric);
  /// Rejected and kept-spectral counts (as of the last iteration and CurrentMap), the
  /// rigidity measured halfway, or the error.
  const SurfacePolishInfo& Info() const;

private:
  struct State;
  std::unique_ptr<State> Polish;
};

/// Polishes the map given as a target triangle and barycentric coordinates per source
/// vertex, in place. `targetTriangles` is the list of triangles around each target vertex
/// (VertexTriangles). False with info.Error set (and the map unchanged) if the source's
/// Laplacian cannot be built or factored.
bool PolishSurfaceMap(const Points& sourcePoints, const Triangles& sourceTriangles,
  const Points& targetPoints, const Triangles& targetTriangles,
  const VertexLists& targetVertexTriangles, std::vector<Index>& triangle,
  std::vector<Eigen::Vector3d>& barycentric, const SurfacePolishParameters& parameters,
  SurfacePolishInfo& info);
}

#endif
