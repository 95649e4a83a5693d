// Measures of bilateral symmetry (paper §7.3): how far a surface is from mirror-symmetric,
// read off the best orientation-reversing self-registration of its centered spherical map.
//
// - The symmetry distance compares the conformal scale-factor signal f (the low-passed
//   signal vtkSO3Register correlates) with its best reflection f∘T⁻¹. Both are made
//   mean-free and scaled to unit L2 norm (the mean and the overall size say nothing about
//   symmetry), and their L2 distance, which lies in [0, 2], is halved:
//       d = |f̂ - f̂∘T⁻¹| / 2 = sqrt((1 - ρ) / 2),
//   ρ the correlation coefficient of f with f∘T⁻¹ over the sphere. d lies in [0, 1]: 0 for a
//   perfectly symmetric signal, 1/√2 ≈ 0.71 for a reflection uncorrelated with the original
//   (where the paper's uncentered maps cluster in its Figure 8), 1 for an antisymmetric one.
// - The mirror plane: an orientation-reversing orthogonal T is a reflection in a plane
//   through the origin followed by a rotation about that plane's normal; for a symmetric
//   shape the rotation is the identity.
// - The per-vertex asymmetry: the symmetric map m sends every vertex to a point of the
//   surface; for an exact symmetry m(m(v)) = v. |v - m(m(v))| measures how far m is from an
//   involution at v.
#ifndef mobius_SymmetryMeasures_h
#define mobius_SymmetryMeasures_h

#include "MeshTypes.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace mobius
{
/// d = sqrt((1 - ρ) / 2) in [0, 1] from the correlation coefficient ρ in [-1, 1] (clamped).
double SymmetryDistance(double correlationCoefficient);

struct MirrorPlane
{
  /// Unit normal n of the plane (x · n = 0) on the sphere, sign fixed so that its largest
  /// component is positive.
  Eigen::Vector3d Normal = Eigen::Vector3d::UnitX();
  /// Angle (radians) of the rotation about n that T adds to the pure reflection
  /// I - 2 n nᵀ: 0 for a mirror symmetry, up to π for the antipodal map.
  double Twist = 0.0;
};

/// The plane of an orthogonal T with det T = -1: n is the eigenvector of T for the
/// eigenvalue -1 (of the symmetric part (T + Tᵀ)/2, its smallest eigenvalue's vector).
MirrorPlane MirrorPlaneOf(const Eigen::Matrix3d& reflection);

/// |x_v - m(m(v))| per vertex, where the symmetric map sends vertex v to the point with
/// barycentric coordinates `barycentric[v]` in triangle `mirrorTriangle[v]`, and
/// `mirrorPoints` (one row per vertex) is that point's position m(v). The map is
/// piecewise linear, so m(m(v)) = Σ_k b_k m(corner_k).
Vector MirrorAsymmetry(const Points& surface, const Triangles& triangles,
  const std::vector<Index>& mirrorTriangle, const std::vector<Eigen::Vector3d>& barycentric,
  const Points& mirrorPoints);

/// MirrorAsymmetry over sqrt(surface area), `areas` the triangles' areas: comparable
/// between surfaces of any size.
Vector RelativeMirrorAsymmetry(const Points& surface, const Triangles& triangles,
  const Vector& areas, const std::vector<Index>& mirrorTriangle,
  const std::vector<Eigen::Vector3d>& barycentric, const Points& mirrorPoints);

/// The candidate reflections of a reflective self-registration, best first: each one's
/// symmetry distance and mirror-plane normal, and the best one's reflection and plane.
struct MirrorCandidates
{
  std::vector<double> Distances;
  std::vector<double> Normals; ///< 3 per candidate
  Eigen::Matrix3d Best;
  MirrorPlane BestPlane;
};

/// The candidates of the `reflections` and their correlation coefficients (one each, best
/// first) into `candidates`: an empty string, or the problem (none, or the counts differ).
std::string DescribeMirrorCandidates(const std::vector<Eigen::Matrix3d>& reflections,
  const std::vector<double>& correlationCoefficients, MirrorCandidates& candidates);
}

#endif
