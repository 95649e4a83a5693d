// Spherical conformal map of a closed genus-0 surface by conformalized mean curvature flow
// (Kazhdan, Solomon & Ben-Chen, "Can Mean-Curvature Flow be Modified to be Non-singular?",
// SGP 2012).
//
// The flow: with the stiffness L built once from the input (cot/2 weights, optionally on the
// intrinsic Delaunay triangulation) and the lumped mass M_t of the current shape x_t, one
// backward-Euler step solves (M_t + delta L) x_{t+1} = M_t x_t, then recenters x_{t+1} at
// its area-weighted centroid and rescales it to unit area. Because L stays that of the input,
// the flow does not pinch off like mean curvature flow; it converges to a round sphere, and
// the vertices' positions on it are a conformal map.
//
// What we add to the published flow, each for a measured reason:
// - the flow starts from a linear conformal map (one sparse solve, LinearSphericalMap.h),
//   a near-fixed point that it only polishes: 3-7 steps instead of 8-9 on the development
//   meshes (3 instead of 9 at 200K vertices), to the same map;
// - Möbius centering after every step (paper §7.1): stops the drift toward a point, so the
//   flow converges (8-13 steps instead of 100 unconverged ones);
// - the stiffness on the intrinsic Delaunay triangulation: needle triangles (0.01 degrees)
//   give no extreme or negative weights;
// - a convergence test, one symbolic factorization, a 3-column solve for the displacement;
//   after the first step, preconditioned conjugate gradients with that step's factorization
//   instead of a new one (ReuseFactorization);
// - at the end: projection onto the unit sphere, mirroring if the triangles face inward,
//   re-solving regions squeezed below 1e-7 in local coordinates, and local sweeps that
//   unfold the few triangles still flipped (needles whose apex crosses the long edge).
#ifndef mobius_ConformalMap_h
#define mobius_ConformalMap_h

#include "MapDistortion.h"
#include "MeshTypes.h"
#include "SqueezedRegionRefinement.h"
#include "SphericalFlipRepair.h"

#include <functional>
#include <string>

namespace mobius
{
/// Optional step between flow iterations, given the current shape (centered, unit area; on
/// the sphere if MobiusCentering is on) and the number of iterations done. It may replace the
/// positions (the flow re-normalizes them afterwards). Return false to fail the map (keep
/// the reason in the hook's own state).
using FlowStepHook = std::function<bool(Points& positions, int iteration)>;

struct ConformalMapParameters
{
  /// delta of the backward-Euler step, for a surface scaled to unit area and the standard
  /// cot/2 stiffness. (The authors' program uses 0.1 with 4x that stiffness: 0.4 here.)
  double TimeStep = 0.4;
  /// Upper bound on flow steps.
  int MaximumNumberOfIterations = 100;
  /// Stop when the area-weighted RMS displacement of a step, relative to the RMS distance
  /// of the shape from its centroid, falls below this.
  double ConvergenceTolerance = 1e-4;
  /// Build the stiffness on the intrinsic Delaunay triangulation (robust to needle
  /// triangles; identical on meshes that are already Delaunay).
  bool IntrinsicDelaunay = true;
  /// With IntrinsicDelaunay off: if triangles are still flipped after the repair, map again
  /// on the intrinsic Delaunay triangulation and keep that map unless it has more of them.
  /// The input's own cotangent weights are negative across non-Delaunay edges (15% of the
  /// edges of a decimated mesh) and can fold the squeezed limbs of a mesh with no needles: a
  /// camel decimated to 3,000 vertices (smallest angle 1.25 degrees) had 524 folds, 188 of
  /// them left after the repair; on the intrinsic Delaunay triangulation 36, all repaired.
  /// Meshes whose folds the repair undoes are mapped once and keep their own weights, which
  /// give a slightly lower distortion measured on their triangles (CGAL's man remeshed to 5K,
  /// a few triangles folded and repaired: mean distortion 1.24 with its own weights, 1.53 on the
  /// intrinsic Delaunay triangulation).
  bool IntrinsicDelaunayWhenFolded = true;
  /// Re-solve the regions whose edges the map squeezes below this length on the unit sphere
  /// (long limbs) in local coordinates with positive weights (see
  /// SqueezedRegionRefinement.h); 0: off. 1e-7 leaves every well-resolved map alone
  /// (hand_smpl, armadillo, bunny: untouched) and takes the camel's mean quasi-conformal
  /// distortion from 1551 to 1.39, the man's from 48 to 1.30.
  double SqueezedRegionThreshold = 1e-7;
  /// Sweeps of local flip repair after the flow (see SphericalFlipRepair.h); 0: none.
  int FlipRepairPasses = 100;
  /// After each step, project onto the sphere and apply the canonical Möbius centering of
  /// the map (CenterSphericalMap, original areas as weights; paper §7.1). Stops the drift
  /// toward a point that otherwise collapses limbs and keeps the flow from converging; with
  /// it the flow converges in 8-13 steps on every development mesh.
  bool MobiusCentering = true;
  /// Start the flow from the linear conformal map of LinearSphericalMap.h (one solve with
  /// the flow's factorization pattern) instead of from the surface, so that the flow only
  /// polishes: 3-7 steps instead of 8-9 on the development meshes, to the same map (mean
  /// distance 1e-5 to 7e-5 after the best rotation, mean quasi-conformal distortion equal to
  /// 3-5 digits). False: the published flow from the surface. Only with MobiusCentering
  /// (the start is a centered map; without centering the flow is plain CMCF from the
  /// surface). The linear map is turned to the surface's orientation, so the map turns
  /// with the input. The flow from the surface keeps a mirror symmetry of the surface
  /// exactly, the linear start's map only to the tolerance (vtkSymmetryDetection turns it
  /// off).
  bool LinearStart = true;
  /// Solve each step's system (M_t + delta L) by conjugate gradients preconditioned with
  /// the factorization of an earlier step's, to a relative residual of 1e-10, and factorize
  /// only when that takes more than 10 iterations. Near convergence M_t changes little
  /// from step to step: measured 3-4 iterations (triangular solves) instead of a
  /// factorization for every step after the first, with the same steps and map.
  bool ReuseFactorization = true;
  /// ... for meshes of at least this many vertices: the supernodal factorization of large
  /// meshes (SparseCholesky.h) costs many times a three-column solve, so the conjugate
  /// gradients save time, while the simplicial one of smaller meshes costs only a few solves,
  /// about what the conjugate gradients take (README, Performance).
  Index ReuseFactorizationMinimumSize = 50000;
  /// Optional extra step between iterations (see FlowStepHook), after the centering.
  FlowStepHook BetweenSteps;
  /// Progress in [0, 1]; returning false aborts.
  ProgressCallback Progress;
};

struct ConformalMapResult
{
  /// False on invalid input, solver failure, non-finite values or abort; Message says why.
  bool Success = false;
  std::string Message;
  /// The map: one point on the unit sphere per input point.
  Points SpherePoints;
  /// Flow steps taken and the relative change of the last one.
  int Iterations = 0;
  double RelativeChange = 0.0;
  /// The relative change fell below the tolerance (otherwise the iteration limit ended it).
  bool Converged = false;
  /// The flow started from the linear conformal map (LinearStart on and the map computed);
  /// if it could not be computed, the flow started from the surface and LinearStartError
  /// says why.
  bool LinearStart = false;
  std::string LinearStartError;
  /// The triangle the linear map put at the north pole (-1 without it).
  Index PoleTriangle = -1;
  /// Numeric Cholesky factorizations (the linear start's and the flow's) and conjugate
  /// gradient iterations of the steps that reused one (see ReuseFactorization).
  int Factorizations = 0;
  int ConjugateGradientIterations = 0;
  /// The stiffness was built on the intrinsic Delaunay triangulation (asked for, or because
  /// the map with the input's weights folded: IntrinsicDelaunayWhenFolded).
  bool IntrinsicDelaunayUsed = false;
  /// Edge flips made for the intrinsic Delaunay stiffness.
  Index IntrinsicFlips = 0;
  /// The input's triangles faced inward (negative enclosed volume), so the map, whose
  /// triangles face outward on the sphere, is a mirror image of the surface.
  bool Reflected = false;
  /// What the squeezed-region refinement did.
  SqueezedRegionRefinementResult Refinement;
  /// What the flip repair did (flips before it, flips left, vertices moved).
  FlipRepairResult FlipRepair;
  /// Quality of the final map (flipped triangles, quasi-conformal and area distortion).
  MapDistortion Distortion;
};

/// Maps a closed, connected, consistently oriented genus-0 triangle mesh to the unit sphere.
/// Never throws; on failure returns Success = false with a message naming the problem (the
/// topology problems come from DescribeTopologyProblems) and no points.
ConformalMapResult ComputeSphericalConformalMap(const Points& points, const Triangles& triangles,
  const ConformalMapParameters& parameters = ConformalMapParameters());
}

#endif
