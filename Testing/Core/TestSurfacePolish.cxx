// Geometric polish: a map onto a rotated copy of a shape, slid along the surface by a smooth
// field (about 1.5 edge lengths on average: what the spectral map leaves on thin parts),
// comes back towards the identity, closer still when it matches the surfaces' curvature; so
// does one onto a mirrored copy when the polish is told the map reverses orientation; the
// result does not depend on the thread count. The polish trusts its rigid prior fully on
// those copies and less on a stretched one.
#include "CoreTest.h"
#include "CotangentLaplacian.h"
#include "Icosphere.h"
#include "Curvature.h"
#include "MeshAdjacency.h"
#include "SurfacePolish.h"
#include "SurfaceWalk.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

using namespace mobius;

namespace
{
// An ellipsoid with bumps of several sizes: no rigid motion but the identity maps it onto
// itself, and the bumps are the features that pin a sliding map (a smooth shape lets a map
// slide along it almost isometrically).
void MakeBlob(Points& points, Triangles& triangles)
{
  MakeIcosphere(4, points, triangles);
  const Eigen::Vector3d centers[4] = { { 0.6, 0.64, 0.48 }, { -0.8, 0.0, 0.6 },
    { 0.0, -0.9, -0.43 }, { -0.3, 0.5, -0.81 } };
  const double heights[4] = { 0.4, 0.25, 0.3, 0.2 }, sharpness[4] = { 8, 20, 12, 30 };
  for (Index i = 0; i < points.rows(); ++i)
  {
    const Eigen::Vector3d p = points.row(i);
    double bump = 0;
    for (int b = 0; b < 4; ++b)
    {
      bump += heights[b] * std::exp(-sharpness[b] * (p - centers[b]).squaredNorm());
    }
    points.row(i) << 1.6 * p.x() * (1 + bump), p.y() * (1 + bump), 0.7 * p.z() * (1 + bump);
  }
}

struct Map
{
  std::vector<Index> Triangle;
  std::vector<Eigen::Vector3d> Barycentric;
};

// Each source vertex sent to the target vertex nearest to its true image moved by a smooth
// field (`slide` long at most), as a corner of one of that vertex's triangles.
Map SlidMap(const Points& source, const Points& target, const Triangles& targetTriangles,
  const Eigen::Matrix3d& motion, double slide)
{
  const VertexLists corners = VertexTriangles(target.rows(), targetTriangles);
  Map map;
  for (Index i = 0; i < source.rows(); ++i)
  {
    const Eigen::Vector3d p = source.row(i);
    const Eigen::Vector3d moved = motion *
      (p + slide * Eigen::Vector3d(std::sin(3 * p.y()), std::cos(2 * p.z()), std::sin(2 * p.x())));
    Index nearest = 0;
    (target.rowwise() - moved.transpose()).rowwise().squaredNorm().minCoeff(&nearest);
    const Index t = corners.Items[corners.Begin(nearest)];
    Eigen::Vector3d weights = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
    {
      weights[k] = targetTriangles(t, k) == nearest ? 1.0 : 0.0;
    }
    map.Triangle.push_back(t);
    map.Barycentric.push_back(weights);
  }
  return map;
}

// Mean distance of the mapped points from the true images, over sqrt(area).
double MeanError(const Map& map, const Points& source, const Points& target,
  const Triangles& targetTriangles, const Eigen::Matrix3d& motion)
{
  double sum = 0;
  for (Index i = 0; i < source.rows(); ++i)
  {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
    {
      point += map.Barycentric[i][k] * target.row(targetTriangles(map.Triangle[i], k)).transpose();
    }
    sum += (point - motion * source.row(i).transpose()).norm();
  }
  return sum / source.rows() / std::sqrt(TriangleAreas(target, targetTriangles).sum());
}

void TestSlidMap(bool mirrored)
{
  Points source;
  Triangles triangles;
  MakeBlob(source, triangles);
  Eigen::Matrix3d motion =
    Eigen::AngleAxisd(2.3, Eigen::Vector3d(-1, 2, 0.5).normalized()).toRotationMatrix();
  Triangles targetTriangles = triangles;
  if (mirrored)
  {
    motion = motion * Eigen::Vector3d(-1, 1, 1).asDiagonal();
    targetTriangles.col(1).swap(targetTriangles.col(2)); // outward normals again
  }
  const Points target = source * motion.transpose();
  const VertexLists corners = VertexTriangles(target.rows(), targetTriangles);

  const Map start = SlidMap(source, target, targetTriangles, motion, 0.15);
  const double before = MeanError(start, source, target, targetTriangles, motion);
  SurfacePolishParameters parameters;
  parameters.ReverseOrientation = mirrored;
  Map polished = start;
  SurfacePolishInfo info;
  MOBIUS_CHECK(PolishSurfaceMap(source, triangles, target, targetTriangles, corners,
    polished.Triangle, polished.Barycentric, parameters, info));
  const double after = MeanError(polished, source, target, targetTriangles, motion);
  std::cout << (mirrored ? "mirrored" : "rotated") << " copy: slid map " << before
            << ", polished " << after << " (" << info.Rejected << " rejected, "
            << info.KeptSpectral << " kept)\n";
  // Measured 0.036 -> 0.0098 for both. What is left is a smooth slide, nearly an isometry of
  // this smooth shape, which the weak pull back to the start holds. Mirrored without
  // ReverseOrientation, every closest point is rejected (its normal faces the other way).
  MOBIUS_CHECK(before > 0.03);
  MOBIUS_CHECK(after < 0.6 * before);
  MOBIUS_CHECK(info.Rejected < source.rows() / 20);
  // A rigid copy: the rigid prior keeps its weight.
  std::cout << "  ARAP residual halfway " << info.RigidResidual << ", fit gain " << info.FitGain
            << "\n";
  MOBIUS_CHECK(info.RigidResidual < parameters.RigidResidual && info.FitGain == 1.0);

  // Matching the bumps' curvatures pins the slide that position alone leaves: the mean
  // curvature, the Gaussian curvature, and both (the default weights).
  const std::vector<CurvatureScale> scales(kPolishCurvatures.begin(), kPolishCurvatures.end());
  SurfacePolishParameters matching = parameters;
  matching.SourceCurvatures = SmoothedCurvatures(source, triangles, scales);
  matching.TargetCurvatures = SmoothedCurvatures(target, targetTriangles, scales);
  const auto polishWith = [&](const SurfacePolishParameters& withCurvature) {
    Map map = start;
    MOBIUS_CHECK(PolishSurfaceMap(source, triangles, target, targetTriangles, corners,
      map.Triangle, map.Barycentric, withCurvature, info));
    return MeanError(map, source, target, targetTriangles, motion);
  };
  SurfacePolishParameters meanOnly = matching, gaussianOnly = matching;
  meanOnly.CurvatureWeights[1] = 0;
  gaussianOnly.CurvatureWeights[0] = 0;
  const double mean = polishWith(meanOnly), gaussian = polishWith(gaussianOnly),
               both = polishWith(matching);
  std::cout << "  matching mean curvature " << mean << ", Gaussian " << gaussian << ", both "
            << both << "\n";
  // Measured 0.0089, 0.0089 and 0.0083 for both (positions alone 0.0098). A step the wrong
  // way along a curvature's gradient would leave more than positions alone; the two
  // curvatures together hold more than either.
  MOBIUS_CHECK(mean < 0.95 * after);
  MOBIUS_CHECK(gaussian < 0.95 * after);
  MOBIUS_CHECK(both < 0.96 * mean && both < 0.96 * gaussian);

  // Same result, bit for bit, on one thread and on three.
  parameters = matching;
  parameters.NumberOfThreads = 1;
  Map one = start;
  PolishSurfaceMap(source, triangles, target, targetTriangles, corners, one.Triangle,
    one.Barycentric, parameters, info);
  parameters.NumberOfThreads = 3;
  Map three = start;
  PolishSurfaceMap(source, triangles, target, targetTriangles, corners, three.Triangle,
    three.Barycentric, parameters, info);
  MOBIUS_CHECK(one.Triangle == three.Triangle && one.Barycentric == three.Barycentric);
}

// A target that is not a rigid copy: the blob stretched by a smooth field (lengths change by
// up to 40%), the identity its true map. The polish measures that its rigid prior does not
// hold and trusts the fit more for its second half. (Whether that pays is measured on real
// pose pairs, docs/accuracy.md: on this blob the curvatures change with the stretch too, and
// the map drifts about as far either way.)
// The blob stretched unevenly, vertex for vertex: not isometric, so the polish's fit gains.
Points StretchedCopy(const Points& source)
{
  Points target = source;
  for (Index i = 0; i < target.rows(); ++i)
  {
    const Eigen::Vector3d p = source.row(i);
    target.row(i) << p.x() * (1 + 0.4 * std::sin(2 * p.y())),
      p.y() * (1 + 0.3 * std::cos(2 * p.x())), p.z();
  }
  return target;
}

void TestStretchedTarget()
{
  Points source;
  Triangles triangles;
  MakeBlob(source, triangles);
  const Points target = StretchedCopy(source);
  const VertexLists corners = VertexTriangles(target.rows(), triangles);
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  // The true image of source vertex i is target vertex i: measure against the target.
  const Map start = SlidMap(target, target, triangles, identity, 0.15);
  const std::vector<CurvatureScale> scales(kPolishCurvatures.begin(), kPolishCurvatures.end());
  SurfacePolishParameters parameters;
  parameters.SourceCurvatures = SmoothedCurvatures(source, triangles, scales);
  parameters.TargetCurvatures = SmoothedCurvatures(target, triangles, scales);
  const auto polishWith = [&](const SurfacePolishParameters& chosen, SurfacePolishInfo& info) {
    Map map = start;
    MOBIUS_CHECK(PolishSurfaceMap(source, triangles, target, triangles, corners, map.Triangle,
      map.Barycentric, chosen, info));
    return MeanError(map, target, target, triangles, identity);
  };
  SurfacePolishParameters rigid = parameters;
  rigid.MaximumFitGain = 1;
  SurfacePolishInfo gained, kept;
  const double before = MeanError(start, target, target, triangles, identity);
  const double withGain = polishWith(parameters, gained), without = polishWith(rigid, kept);
  std::cout << "stretched copy: slid map " << before << ", polished " << withGain
            << " (ARAP residual halfway " << gained.RigidResidual << ", fit gain "
            << gained.FitGain << "), without the gain " << without << "\n";
  // Measured: residual 0.017, so the largest gain (2.5); the rigid copies above 0.0006.
  MOBIUS_CHECK(gained.RigidResidual > 2.5 * parameters.RigidResidual);
  MOBIUS_CHECK(gained.FitGain == parameters.MaximumFitGain);
  MOBIUS_CHECK(kept.FitGain == 1.0 && kept.RigidResidual == gained.RigidResidual);
  MOBIUS_CHECK(withGain != without); // the second half did run with the larger fit
}
// The polish run a few iterations at a time (SurfacePolisher, as the two directions of the
// refinement run it between their meetings) is the polish run at once, and a polish moved
// to a map (MoveTo) goes on from that map's points.
void TestPolishInSteps()
{
  Points source;
  Triangles triangles;
  MakeBlob(source, triangles);
  const Points target = StretchedCopy(source);
  const VertexLists corners = VertexTriangles(target.rows(), triangles);
  const Map start = SlidMap(target, target, triangles, Eigen::Matrix3d::Identity(), 0.15);
  SurfacePolishParameters parameters;
  Map atOnce = start;
  SurfacePolishInfo info;
  MOBIUS_CHECK(PolishSurfaceMap(source, triangles, target, triangles, corners, atOnce.Triangle,
    atOnce.Barycentric, parameters, info));

  SurfacePolisher polisher;
  MOBIUS_CHECK(polisher.Start(source, triangles, target, triangles, corners, start.Triangle,
    start.Barycentric, parameters));
  Map inSteps;
  while (polisher.Iterations() < parameters.Iterations)
  {
    MOBIUS_CHECK(polisher.Iterate(7)); // across the halfway measurement too
    polisher.CurrentMap(inSteps.Triangle, inSteps.Barycentric);
  }
  MOBIUS_CHECK(polisher.Iterations() == parameters.Iterations);
  MOBIUS_CHECK(polisher.Info().FitGain == info.FitGain);
  double largest = 0;
  for (Index i = 0; i < source.rows(); ++i)
  {
    MOBIUS_CHECK(inSteps.Triangle[i] == atOnce.Triangle[i]);
    largest = std::max(largest, (inSteps.Barycentric[i] - atOnce.Barycentric[i]).norm());
  }
  MOBIUS_CHECK(largest < 1e-12);

  SurfacePolisher moved;
  MOBIUS_CHECK(moved.Start(source, triangles, target, triangles, corners, start.Triangle,
    start.Barycentric, parameters));
  MOBIUS_CHECK(moved.Iterate(20));
  moved.MoveTo(start.Triangle, start.Barycentric);
  Map back;
  moved.CurrentMap(back.Triangle, back.Barycentric);
  const SurfaceWalker walker{ target, triangles, corners };
  double farthest = 0;
  for (Index i = 0; i < source.rows(); ++i)
  {
    farthest = std::max(farthest, (walker.Point(back.Triangle[i], back.Barycentric[i]) -
                                    walker.Point(start.Triangle[i], start.Barycentric[i]))
                                    .norm());
  }
  std::cout << "polish in steps of 7: largest barycentric difference " << largest
            << "; moved back to the start: " << farthest << "\n";
  MOBIUS_CHECK(farthest < 1e-9);
}
}

int main()
{
  TestSlidMap(false);
  TestSlidMap(true);
  TestStretchedTarget();
  TestPolishInSteps();
  return MOBIUS_TEST_RESULT();
}
