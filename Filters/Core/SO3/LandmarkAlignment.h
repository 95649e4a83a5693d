// Landmarks in the rotational alignment: points of the source's sphere whose places on the
// target's sphere the user knows. The correlation over SO(3) cannot tell a symmetric shape
// from its mirror image or its half-turned copy (their scale factors correlate equally
// well); a few landmarks can. Among the correlation's candidate transforms (and, from 3
// landmarks on, the orthogonal transform that fits the landmarks best in the least-squares
// sense), the one that brings the landmarks' sphere points closest together goes first.
#ifndef mobius_LandmarkAlignment_h
#define mobius_LandmarkAlignment_h

#include "MeshTypes.h"
#include "SO3Correlation.h"

#include <Eigen/Core>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace mobius
{
/// Landmarks on the two spheres: row k of Source goes to row k of Target (unit vectors).
struct SphereLandmarks
{
  Points Source;
  Points Target;
};

/// The first landmark (source and target point ids) naming a point outside its map's
/// `counts` points, e.g. "landmark 2 names point 5000 of the Target (port 1), which has 4000
/// points" (`names`: what messages call the two maps); empty if every one names a point.
std::string CheckLandmarkIds(const std::vector<std::pair<Index, Index>>& landmarks,
  const Index counts[2], const std::string names[2]);

/// Root mean square of the angles (radians) between T p_k and q_k: 0 when the transform
/// brings every landmark onto its target.
double LandmarkAngle(const Eigen::Matrix3d& transform, const SphereLandmarks& landmarks);

/// Per landmark, the angle (radians) between T p_k and q_k.
std::vector<double> LandmarkAngles(const Eigen::Matrix3d& transform, const SphereLandmarks& landmarks);

/// A landmark this far (radians) from its target on the centered spheres, under the rotation
/// a map starts from, disagrees with that map: 60 degrees. Landmarks in farthest-point order
/// on CGAL's meshes against stretched and inflated copies (5 each; 7 meshes, 2 copies) and
/// SMPL's man -> woman came within 42 degrees under the rotation the refinement kept; two
/// landmarks swapped, the mirror image with rotations only, another vertex numbering or a
/// --candidate against them left one or more 73 to 177 degrees away.
inline constexpr double kLandmarkDisagreementAngle = 1.0471975511965976;

/// The orthogonal T of determinant `determinant` (+1 or -1) minimizing sum |T p_k - q_k|^2
/// (Kabsch / orthogonal Procrustes, by an SVD of the landmarks' covariance).
Eigen::Matrix3d FitLandmarkTransform(const SphereLandmarks& landmarks, double determinant);

/// Landmarks from which the best-fit transform is offered as a candidate. With 2, their
/// covariance has rank 2: a rotation and a reflection fit them equally well, and an error
/// in one point turns the whole sphere about the other; from 3 on the fit is well posed.
inline constexpr int FittedTransformLandmarks = 3;

/// Puts first the candidate that brings the landmarks closest together (LandmarkAngle),
/// after adding, from FittedTransformLandmarks landmarks on, the best-fit transform(s) of
/// the determinant(s) `mode` allows as candidates scored by the correlation's `evaluate`
/// (C(T), RegistrationError, CorrelationCoefficient); the others follow in the order of
/// their landmark angles. Returns the landmark angle of each candidate, in the new order.
std::vector<double> OrderCandidatesByLandmarks(std::vector<SO3Candidate>& candidates,
  const SphereLandmarks& landmarks, SO3ReflectionMode mode,
  const std::function<SO3Candidate(const Eigen::Matrix3d&)>& evaluate);

/// The Möbius transformation of the sphere (or, with `reverseOrientation`, the Möbius
/// transformation after the reflection y -> -y) that sends the first 3 source landmarks
/// exactly onto their targets, applied to `points` (unit vectors, in place). A Möbius
/// transformation is fixed by 3 points and their images: on the stereographic plane,
/// f = W^-1 Z with Z the map sending the source points to 0, 1 and infinity and W the
/// same for the targets. False (points unchanged) if two of the 3 points coincide on a side.
/// Whether the first 3 landmarks go round the other way on the target's sphere than on the
/// source's: a Möbius transformation keeps the orientation of every triangle of points, so
/// only one after a reflection can send them onto their targets without turning the
/// sphere inside out.
bool LandmarksReverseOrientation(const SphereLandmarks& landmarks);

bool MoveByLandmarkMobius(
  const SphereLandmarks& landmarks, bool reverseOrientation, Points& points);
}

#endif
