// Canonical Möbius centering of a spherical map (Baden, Crane & Kazhdan 2018, Algorithm 1).
//
// The centre of mass of the original-surface area, pushed onto the sphere, is
// mu = sum_t A(t) C(t) with C(t) the normalized centroid of spherical triangle t and A the
// original areas normalized to sum 1 (for a point set: the points with equal weights).
// Centering finds the inversion eta_c(v) = (1-|c|^2)(v+c)/|v+c|^2 + c that moves mu to the
// origin, by Gauss-Newton steps c = -J^-1 mu with J = 2 sum_t A(t)(I - C C^T), each
// followed by a backtracking line search that keeps |c| < 1 and makes |mu| decrease.
//
// Every inversion eta_c is a Lorentz boost of the light cone {(x, 1) : |x| = 1}:
//   [X; W] = 1/(1-|c|^2) [ (1-|c|^2) I + 2 c c^T , 2 c ; 2 c^T , 1+|c|^2 ] [x; 1],
//   eta_c(x) = X / W.
// The composition of all steps is therefore one 4x4 Lorentz matrix, which we return so a
// user can apply the same Möbius transformation to any point of the sphere.
#ifndef mobius_MobiusCentering_h
#define mobius_MobiusCentering_h

#include "MeshTypes.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace mobius
{
struct MobiusCenteringParameters
{
  /// Stop when |mu| <= Tolerance (mu is computed with weights normalized to sum 1).
  double Tolerance = 1e-10;
  /// Upper bound on Gauss-Newton steps.
  int MaximumNumberOfIterations = 100;
  /// Largest |c| a single step may take; larger Gauss-Newton steps are shortened to it.
  /// Well below 1 so one step can never collapse the map onto a point.
  double MaximumStepRadius = 0.9;
};

struct MobiusCenteringResult
{
  /// |mu| before the first step and after the last one.
  double InitialCenterOfMassNorm = 0.0;
  double CenterOfMassNorm = 0.0;
  int NumberOfIterations = 0;
  bool Converged = false;
  /// The inversion centers applied, in order.
  std::vector<Eigen::Vector3d> InversionCenters;
  /// Composition of all applied inversions as a Lorentz matrix (see the file comment);
  /// identity if no step was taken.
  Eigen::Matrix4d LorentzTransform = Eigen::Matrix4d::Identity();
  std::string Error;
};

/// The Lorentz matrix of the inversion eta_c, |c| < 1.
Eigen::Matrix4d InversionLorentzMatrix(const Eigen::Vector3d& c);

/// Applies a Lorentz matrix to a point on the unit sphere: [X; W] = L [x; 1], x' = X / W.
Eigen::Vector3d ApplyLorentzTransform(const Eigen::Matrix4d& lorentz, const Eigen::Vector3d& x);

/// Applies eta_c to every point (in place), keeping the points exactly on the unit sphere.
void ApplyInversion(const Eigen::Vector3d& c, Points& points);

/// Area-weighted centre of mass mu of the spherical map (weights normalized to sum 1).
/// With no triangles, the points themselves with equal weights.
Eigen::Vector3d SphericalCenterOfMass(
  const Points& points, const Triangles& triangles, const Vector& triangleAreas);

/// Centers the spherical map in place. `points` must lie on the unit sphere;
/// `triangleAreas` holds one finite area per triangle, not negative and not all 0 (ignored
/// when there are no triangles: then the points are centered as a point set with unit
/// weights).
/// Returns false (and sets result.Error) on invalid input or on abort; the points are then
/// left as they were.
bool CenterSphericalMap(Points& points, const Triangles& triangles, const Vector& triangleAreas,
  const MobiusCenteringParameters& parameters, MobiusCenteringResult& result,
  const ProgressCallback& progress = {});
}

#endif
