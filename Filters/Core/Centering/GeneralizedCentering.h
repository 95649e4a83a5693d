// Generalized centering (Baden, Crane & Kazhdan 2018, Sections 5 and 6.1): the spherical map
// is moved until the original-surface area, seen as a density on the sphere, has no
// component along the spherical harmonics of degree 1 to L. Degree 1 is the Möbius
// centering of Algorithm 1; higher degrees spread area more evenly at the cost of
// conformality (the paper's Figure 5).
//
// The motion is advection along the gradient of phi = sum_i c_i e_i (e_i the real
// spherical harmonics of degree 1..L). With mu_i = sum_t A(t) e_i(C(t)) (A normalized
// original areas, C the normalized triangle centroids), moving the sphere along grad phi
// changes mu by J c with J_ij = sum_t A(t) grad e_i . grad e_j (symmetric positive
// definite), so each Newton step takes c = -J^-1 mu and advects the vertices by a step
// small enough that no triangle flips and |mu| decreases.
#ifndef mobius_GeneralizedCentering_h
#define mobius_GeneralizedCentering_h

#include "MeshTypes.h"

#include <string>

namespace mobius
{
struct GeneralizedCenteringParameters
{
  /// Highest spherical-harmonic degree L (>= 1) of the functions to center against.
  int Degree = 2;
  /// Stop when |mu| <= Tolerance (areas normalized to sum 1). 1e-10, as the Möbius
  /// centering's: the registration has always centered to it (vtkMobiusCenter).
  double Tolerance = 1e-10;
  int MaximumNumberOfIterations = 200;
  /// Largest angle (radians) a vertex may move in one advection step.
  double MaximumStepAngle = 0.05;
};

struct GeneralizedCenteringResult
{
  double InitialCenterOfMassNorm = 0.0;
  double CenterOfMassNorm = 0.0;
  int NumberOfIterations = 0;
  bool Converged = false;
  std::string Error;
};

/// The (L+1)^2 - 1 real, orthonormal spherical harmonics of degree 1..L at the unit vector x.
void EvaluateRealSphericalHarmonics(int degree, const Eigen::Vector3d& x, double* values);

/// The moments mu_i of the area density against the harmonics of degree 1..L.
Vector SphericalHarmonicMoments(
  const Points& points, const Triangles& triangles, const Vector& areas, int degree);

/// Centers the map in place. Needs triangles (with positive areas) and points on the unit
/// sphere. Returns false with an error on bad input or abort; the points are then unchanged.
bool CenterWithSphericalHarmonics(Points& points, const Triangles& triangles, const Vector& areas,
  const GeneralizedCenteringParameters& parameters, GeneralizedCenteringResult& result,
  const ProgressCallback& progress = {});
}

#endif
