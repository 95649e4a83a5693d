#include "LandmarkAlignment.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>
#include <string>

namespace mobius
{
std::vector<double> LandmarkAngles(const Eigen::Matrix3d& transform, const SphereLandmarks& landmarks)
{
  std::vector<double> angles;
  for (Index k = 0; k < landmarks.Source.rows(); ++k)
  {
    const Eigen::Vector3d p = transform * landmarks.Source.row(k).transpose();
    const Eigen::Vector3d q = landmarks.Target.row(k).transpose();
    angles.push_back(std::atan2(p.cross(q).norm(), p.dot(q)));
  }
  return angles;
}

double LandmarkAngle(const Eigen::Matrix3d& transform, const SphereLandmarks& landmarks)
{
  const std::vector<double> angles = LandmarkAngles(transform, landmarks);
  if (angles.empty())
  {
    return 0.0;
  }
  double sum = 0;
  for (double angle : angles)
  {
    sum += angle * angle;
  }
  return std::sqrt(sum / static_cast<double>(angles.size()));
}

Eigen::Matrix3d FitLandmarkTransform(const SphereLandmarks& landmarks, double determinant)
{
  // T = U diag(1, 1, s) V^T from the SVD of sum q_k p_k^T, s fixing the determinant.
  const Eigen::Matrix3d covariance = landmarks.Target.transpose() * landmarks.Source;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Vector3d signs(1, 1, 1);
  if ((svd.matrixU() * svd.matrixV().transpose()).determinant() * determinant < 0)
  {
    signs[2] = -1; // the smallest singular value's direction gives way
  }
  return svd.matrixU() * signs.asDiagonal() * svd.matrixV().transpose();
}

std::vector<double> OrderCandidatesByLandmarks(std::vector<SO3Candidate>& candidates,
  const SphereLandmarks& landmarks, SO3ReflectionMode mode,
  const std::function<SO3Candidate(const Eigen::Matrix3d&)>& evaluate)
{
  if (landmarks.Source.rows() >= FittedTransformLandmarks)
  {
    if (mode != SO3ReflectionMode::ReflectionsOnly)
    {
      candidates.push_back(evaluate(FitLandmarkTransform(landmarks, 1.0)));
    }
    if (mode != SO3ReflectionMode::RotationsOnly)
    {
      candidates.push_back(evaluate(FitLandmarkTransform(landmarks, -1.0)));
    }
  }
  std::vector<double> angles;
  for (const SO3Candidate& candidate : candidates)
  {
    angles.push_back(LandmarkAngle(candidate.Transform, landmarks));
  }
  std::vector<size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), 0);
  // Stable: equal angles (no landmarks) keep the correlation's order.
  std::stable_sort(
    order.begin(), order.end(), [&](size_t a, size_t b) { return angles[a] < angles[b]; });
  std::vector<SO3Candidate> sorted;
  std::vector<double> sortedAngles;
  for (size_t index : order)
  {
    sorted.push_back(candidates[index]);
    sortedAngles.push_back(angles[index]);
  }
  candidates.swap(sorted);
  return sortedAngles;
}

namespace
{
using Complex = std::complex<double>;
using Homogeneous = Eigen::Vector2cd; // (u, v): the point u / v of the extended plane
using MobiusMatrix = Eigen::Matrix2cd;

// Stereographic coordinates of a unit vector from the north pole, homogeneous so that the
// pole itself (infinity) is a point: (x + iy) / (1 - z) = (1 + z) / (x - iy).
Homogeneous ToPlane(const Eigen::Vector3d& p)
{
  if (p.z() < 0)
  {
    return Homogeneous(Complex(p.x(), p.y()), Complex(1.0 - p.z(), 0.0));
  }
  return Homogeneous(Complex(1.0 + p.z(), 0.0), Complex(p.x(), -p.y()));
}

Eigen::Vector3d ToSphere(const Homogeneous& w)
{
  const double uu = std::norm(w[0]), vv = std::norm(w[1]), s = uu + vv;
  const Complex xy = 2.0 * w[0] * std::conj(w[1]) / s;
  return Eigen::Vector3d(xy.real(), xy.imag(), (uu - vv) / s);
}

// The Möbius map sending a, b, c to 0, 1, infinity: z -> ((z - a)(b - c)) / ((z - c)(b - a)),
// written for homogeneous points.
MobiusMatrix ToZeroOneInfinity(const Homogeneous& a, const Homogeneous& b, const Homogeneous& c)
{
  // (z - a) ~ (u a1 - v a0)... as linear forms in (u, v): z - a ~ a1 u - a0 v.
  auto form = [](const Homogeneous& p) { return Eigen::RowVector2cd(p[1], -p[0]); };
  const Complex bc = (form(c) * b).value(), ba = (form(a) * b).value(); // (b - c), (b - a), homogeneous
  MobiusMatrix m;
  m.row(0) = bc * form(a);
  m.row(1) = ba * form(c);
  return m;
}
}

bool LandmarksReverseOrientation(const SphereLandmarks& landmarks)
{
  auto turn = [](const Points& p) {
    return p.row(0).dot(p.row(1).cross(p.row(2)));
  };
  return landmarks.Source.rows() >= 3 && turn(landmarks.Source) * turn(landmarks.Target) < 0;
}

bool MoveByLandmarkMobius(
  const SphereLandmarks& landmarks, bool reverseOrientation, Points& points)
{
  if (landmarks.Source.rows() < 3)
  {
    return false;
  }
  const Eigen::Vector3d mirror(1.0, reverseOrientation ? -1.0 : 1.0, 1.0);
  Homogeneous p[3], q[3];
  for (int k = 0; k < 3; ++k)
  {
    p[k] = ToPlane(mirror.cwiseProduct(landmarks.Source.row(k).transpose()));
    q[k] = ToPlane(landmarks.Target.row(k).transpose());
  }
  const MobiusMatrix z = ToZeroOneInfinity(p[0], p[1], p[2]);
  const MobiusMatrix w = ToZeroOneInfinity(q[0], q[1], q[2]);
  // Coinciding points make a matrix singular (the cross-ratio is undefined).
  const double scale = z.norm() * w.norm();
  if (!(std::abs(z.determinant()) * std::abs(w.determinant()) > 1e-12 * scale * scale))
  {
    return false;
  }
  const MobiusMatrix f = w.inverse() * z;
  for (Index i = 0; i < points.rows(); ++i)
  {
    const Homogeneous image = f * ToPlane(mirror.cwiseProduct(points.row(i).transpose()));
    points.row(i) = ToSphere(image).transpose();
  }
  return true;
}

std::string CheckLandmarkIds(const std::vector<std::pair<Index, Index>>& landmarks,
  const Index counts[2], const std::string names[2])
{
  for (size_t k = 0; k < landmarks.size(); ++k)
  {
    const Index points[2] = { landmarks[k].first, landmarks[k].second };
    for (int side = 0; side < 2; ++side)
    {
      if (points[side] < 0 || points[side] >= counts[side])
      {
        return "landmark " + std::to_string(k) + " names point " + std::to_string(points[side]) +
          " of the " + names[side] + ", which has " + std::to_string(counts[side]) + " points";
      }
    }
  }
  return {};
}
}
