// The landmarks' part of the rotational alignment (LandmarkAlignment.h): the best-fit
// transform recovers a known rotation and a known reflection from 3 landmarks (and from 5
// noisy ones, nearly); the candidates are put in the order of their landmark angles, the
// fitted transform added from 3 landmarks on; the Möbius transformation sends 3 points
// exactly onto their targets, keeps every point on the sphere, and is a reflection's when
// the landmarks go round the other way.
#include "CoreTest.h"
#include "LandmarkAlignment.h"
#include "Rotation.h"

#include <Eigen/Geometry>

#include <cmath>
#include <random>

namespace
{
mobius::Points RandomUnitVectors(int count, unsigned seed)
{
  std::mt19937 generator(seed);
  std::normal_distribution<double> normal;
  mobius::Points points(count, 3);
  for (int k = 0; k < count; ++k)
  {
    Eigen::Vector3d p(normal(generator), normal(generator), normal(generator));
    points.row(k) = p.normalized().transpose();
  }
  return points;
}

mobius::SphereLandmarks Moved(const mobius::Points& source, const Eigen::Matrix3d& transform)
{
  mobius::SphereLandmarks landmarks;
  landmarks.Source = source;
  landmarks.Target = (source * transform.transpose()).eval();
  return landmarks;
}
}

int main()
{
  const Eigen::Matrix3d rotation = mobius::EulerZYZToMatrix(0.3, 2.1, -1.2);
  const Eigen::Matrix3d reflection = -mobius::EulerZYZToMatrix(-2.0, 0.7, 0.4);
  const mobius::Points three = RandomUnitVectors(3, 1);
  // Exact landmarks: the fit is the transform, of either determinant asked for.
  {
    const mobius::SphereLandmarks landmarks = Moved(three, rotation);
    MOBIUS_CHECK((mobius::FitLandmarkTransform(landmarks, 1.0) - rotation).norm() < 1e-12);
    MOBIUS_CHECK_NEAR(mobius::LandmarkAngle(rotation, landmarks), 0.0, 1e-12);
    MOBIUS_CHECK(mobius::FitLandmarkTransform(landmarks, -1.0).determinant() < 0);
    MOBIUS_CHECK(!mobius::LandmarksReverseOrientation(landmarks));
  }
  {
    const mobius::SphereLandmarks landmarks = Moved(three, reflection);
    MOBIUS_CHECK((mobius::FitLandmarkTransform(landmarks, -1.0) - reflection).norm() < 1e-12);
    MOBIUS_CHECK(mobius::LandmarksReverseOrientation(landmarks));
  }
  // Five landmarks, each moved off by about a degree: the fit within a few degrees.
  {
    mobius::SphereLandmarks landmarks = Moved(RandomUnitVectors(5, 2), rotation);
    landmarks.Target += 0.02 * RandomUnitVectors(5, 3);
    landmarks.Target.rowwise().normalize();
    const Eigen::Matrix3d fit = mobius::FitLandmarkTransform(landmarks, 1.0);
    const double angle = Eigen::AngleAxisd(fit * rotation.transpose()).angle();
    MOBIUS_CHECK(angle < 0.05);
  }
  // Ordering: the correlation's candidates are the half turn and the identity of a
  // symmetric shape, both equally good; the landmarks say the rotation, which the fit adds.
  {
    const mobius::SphereLandmarks landmarks = Moved(three, rotation);
    std::vector<mobius::SO3Candidate> candidates(2);
    candidates[0].Transform = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()).toRotationMatrix() * rotation;
    candidates[1].Transform = rotation * Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()).toRotationMatrix();
    const auto evaluate = [](const Eigen::Matrix3d& transform) {
      mobius::SO3Candidate candidate;
      candidate.Transform = transform;
      return candidate;
    };
    const std::vector<double> angles = mobius::OrderCandidatesByLandmarks(
      candidates, landmarks, mobius::SO3ReflectionMode::RotationsOnly, evaluate);
    MOBIUS_CHECK(candidates.size() == 3 && angles.size() == 3);
    MOBIUS_CHECK((candidates[0].Transform - rotation).norm() < 1e-12); // the fit
    MOBIUS_CHECK(angles[0] < 1e-12 && angles[1] < angles[2]);
    MOBIUS_CHECK(angles[2] > 1.0); // the half turn last
  }
  // The Möbius transformation through 3 points, of either orientation.
  for (bool reverse : { false, true })
  {
    mobius::SphereLandmarks landmarks;
    landmarks.Source = three;
    landmarks.Target = RandomUnitVectors(3, reverse ? 5 : 4);
    if (mobius::LandmarksReverseOrientation(landmarks) != reverse)
    {
      landmarks.Target.row(0).swap(landmarks.Target.row(1));
      landmarks.Source.row(0).swap(landmarks.Source.row(1));
    }
    MOBIUS_CHECK(mobius::LandmarksReverseOrientation(landmarks) == reverse);
    mobius::Points points(13, 3);
    points << landmarks.Source, RandomUnitVectors(8, 6), 0, 0, 1, 0, 0, -1;
    mobius::Points moved = points;
    MOBIUS_CHECK(mobius::MoveByLandmarkMobius(landmarks, reverse, moved));
    MOBIUS_CHECK((moved.topRows(3) - landmarks.Target).norm() < 1e-9);
    MOBIUS_CHECK((moved.rowwise().norm().array() - 1.0).abs().maxCoeff() < 1e-12);
    // Orientation: the triangle of the first 3 points keeps (or reverses) its turn.
    const mobius::Points p = points.topRows(3), q = moved.topRows(3);
    const double before = p.row(0).dot(p.row(1).cross(p.row(2)));
    const double after = q.row(0).dot(q.row(1).cross(q.row(2)));
    MOBIUS_CHECK((before * after < 0) == reverse);
  }
  // Two landmarks at one point: no Möbius transformation, and the points stay.
  {
    mobius::SphereLandmarks landmarks = Moved(three, rotation);
    landmarks.Source.row(1) = landmarks.Source.row(0);
    mobius::Points points = three;
    MOBIUS_CHECK(!mobius::MoveByLandmarkMobius(landmarks, false, points));
    MOBIUS_CHECK(points == three);
  }
  return MOBIUS_TEST_RESULT();
}
