// Spherical conformal map (conformalized mean curvature flow) on generated meshes: a sphere
// must map to itself, an ellipsoid and a sphere with needle triangles must map without folds
// and with small quasi-conformal distortion, bad inputs must fail with a precise message.
#include "ConformalMap.h"
#include "CotangentLaplacian.h"
#include "CoreTest.h"
#include "FlowInput.h"
#include "Icosphere.h"
#include "LinearSphericalMap.h"
#include "MapDistortion.h"
#include "MobiusCentering.h"
#include "SparseCholesky.h"
#include "Torus.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace mobius;

namespace
{
bool Contains(const std::string& text, const std::string& part)
{
  const bool found = text.find(part) != std::string::npos;
  if (!found)
  {
    std::cerr << "message \"" << text << "\" lacks \"" << part << "\"" << std::endl;
  }
  return found;
}

bool AllOnUnitSphere(const Points& x)
{
  for (Index i = 0; i < x.rows(); ++i)
  {
    if (!x.row(i).allFinite() || std::abs(x.row(i).norm() - 1.0) > 1e-12)
    {
      return false;
    }
  }
  return true;
}

// Distances between the map and the best rotation of `reference` onto it (Kabsch).
Eigen::VectorXd DistancesUpToRotation(const Points& map, const Points& reference)
{
  const Eigen::Matrix3d covariance = reference.transpose() * map;
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() > 0 ? 1.0 : -1.0;
  const Eigen::Matrix3d rotation = svd.matrixU() * d * svd.matrixV().transpose();
  return ((reference * rotation) - map).rowwise().norm();
}

double DistanceUpToRotation(const Points& map, const Points& reference)
{
  return DistancesUpToRotation(map, reference).maxCoeff();
}

void TestSphereMapsToItself()
{
  Points p;
  Triangles t;
  MakeIcosphere(3, p, t);
  // Scale and move it: the map must not care.
  const Points input = (2.5 * p).rowwise() + Eigen::RowVector3d(1, -2, 3);
  const ConformalMapResult r = ComputeSphericalConformalMap(input, t);
  MOBIUS_CHECK(r.Success);
  MOBIUS_CHECK(r.Converged);
  MOBIUS_CHECK(r.SpherePoints.rows() == p.rows());
  MOBIUS_CHECK(AllOnUnitSphere(r.SpherePoints));
  MOBIUS_CHECK(!r.Reflected);
  MOBIUS_CHECK(r.Distortion.FlippedTriangles == 0);
  MOBIUS_CHECK_NEAR(r.Distortion.MeanQuasiConformal, 1.0, 2e-3);
  MOBIUS_CHECK(DistanceUpToRotation(r.SpherePoints, p) < 5e-3);
}

// Ellipsoid with axes 1, 1.6, 0.7 from a subdivided icosahedron.
void MakeEllipsoid(int levels, Points& p, Triangles& t)
{
  MakeIcosphere(levels, p, t);
  p.col(1) *= 1.6;
  p.col(2) *= 0.7;
}

void TestEllipsoid()
{
  // The flat triangles' map is the linear interpolant of a smooth conformal map, so its
  // quasi-conformal distortion is 1 + O(h): it must halve roughly with each subdivision
  // (measured 1.054 at level 3, 1.026 at level 4, 1.013 at level 5).
  Points p;
  Triangles t;
  MakeEllipsoid(3, p, t);
  const ConformalMapResult coarse = ComputeSphericalConformalMap(p, t);
  MOBIUS_CHECK(coarse.Success);
  MOBIUS_CHECK(coarse.Distortion.FlippedTriangles == 0);
  MakeEllipsoid(4, p, t);
  ConformalMapResult r = ComputeSphericalConformalMap(p, t);
  MOBIUS_CHECK(r.Success);
  MOBIUS_CHECK(r.Converged);
  MOBIUS_CHECK(r.Iterations < ConformalMapParameters().MaximumNumberOfIterations);
  MOBIUS_CHECK(r.RelativeChange <= ConformalMapParameters().ConvergenceTolerance);
  MOBIUS_CHECK(AllOnUnitSphere(r.SpherePoints));
  MOBIUS_CHECK(r.Distortion.FlippedTriangles == 0);
  MOBIUS_CHECK(r.Distortion.MeanQuasiConformal < 1.03);
  MOBIUS_CHECK(r.Distortion.MaxQuasiConformal < 1.06);
  MOBIUS_CHECK(r.Distortion.MeanQuasiConformal - 1.0 <
    0.6 * (coarse.Distortion.MeanQuasiConformal - 1.0));
  // An ellipsoid is not a sphere: the map must squeeze the long axis' ends (about 0.24)
  // and stretch the flat sides (about 1.8), and not wildly more.
  MOBIUS_CHECK(r.Distortion.MinAreaRatio > 0.15 && r.Distortion.MinAreaRatio < 0.35);
  MOBIUS_CHECK(r.Distortion.MaxAreaRatio > 1.5 && r.Distortion.MaxAreaRatio < 2.2);

  // The mirrored ellipsoid (triangles facing inward) maps to outward-facing triangles.
  Triangles inward = t;
  inward.col(1).swap(inward.col(2));
  r = ComputeSphericalConformalMap(p, inward);
  MOBIUS_CHECK(r.Success);
  MOBIUS_CHECK(r.Reflected);
  MOBIUS_CHECK(r.Distortion.FlippedTriangles == 0);
  MOBIUS_CHECK(r.Distortion.MeanQuasiConformal < 1.03);
}

// An icosphere where many triangles get a point inserted at 1e-4 of the way from a corner to
// the opposite edge: the two thin triangles have angles near 0.005 degrees, whose cotangent
// weights (about 1e4, and negative across from the obtuse angle) break a plain Laplacian.
void TestNeedleTriangles()
{
  Points p;
  Triangles t;
  MakeIcosphere(3, p, t);
  const Index original = t.rows();
  const Index needles = original / 3;
  Points q(p.rows() + needles, 3);
  q.topRows(p.rows()) = p;
  Triangles s(original + 2 * needles, 3);
  s.topRows(original) = t;
  for (Index k = 0; k < needles; ++k)
  {
    const Index f = 3 * k;
    const Index a = t(f, 0), b = t(f, 1), c = t(f, 2);
    const Index m = p.rows() + k;
    q.row(m) = (1.0 - 1e-4) * p.row(a) + 0.5e-4 * (p.row(b) + p.row(c));
    s.row(f) << a, b, m;
    s.row(original + 2 * k) << b, c, m;
    s.row(original + 2 * k + 1) << c, a, m;
  }
  for (bool intrinsic : { true, false })
  {
    ConformalMapParameters parameters;
    parameters.IntrinsicDelaunay = intrinsic;
    const ConformalMapResult r = ComputeSphericalConformalMap(q, s, parameters);
    MOBIUS_CHECK(r.Success);
    MOBIUS_CHECK(AllOnUnitSphere(r.SpherePoints));
    MOBIUS_CHECK(r.Distortion.FlippedTriangles == 0);
    MOBIUS_CHECK(std::isfinite(r.Distortion.MaxQuasiConformal));
    if (intrinsic)
    {
      MOBIUS_CHECK(r.IntrinsicFlips >= needles); // each needle's long edge is flipped
      MOBIUS_CHECK(r.Distortion.MeanQuasiConformal < 1.05);
    }
  }
}

// The linear map alone, Möbius-centered, as the flow would start from it.
LinearSphericalMapResult LinearMap(const Points& input, const Triangles& t)
{
  Points x = input;
  Vector mass = LumpedMass(x, t);
  const double area = mass.sum();
  x.rowwise() -= (mass.transpose() * x) / area;
  x /= std::sqrt(area);
  mass /= area;
  SparseMatrix stiffness;
  CotangentStiffnessInfo info;
  SparseCholesky solver;
  if (!BuildCotangentStiffness(x, t, true, stiffness, info) || !solver.Analyze(stiffness))
  {
    return LinearSphericalMapResult();
  }
  LinearSphericalMapResult r = ComputeLinearSphericalMap(x, t, stiffness, mass, solver);
  MobiusCenteringResult centering;
  if (r.Success &&
    !CenterSphericalMap(r.SpherePoints, t, TriangleAreas(input, t), MobiusCenteringParameters(),
      centering))
  {
    r.Success = false;
  }
  return r;
}

// The linear start: on its own already a conformal map that faces outward, and the flow
// started from it converges in fewer steps to the same map as the flow from the surface.
void TestLinearStart()
{
  // A round sphere: the linear map is the identity up to a rotation (after centering), to
  // discretization error (a wrong right-hand side, e.g. a missing or non-orthogonal
  // imaginary part, gives a map far from it; a mirrored one has every triangle flipped).
  Points p;
  Triangles t;
  MakeIcosphere(4, p, t);
  LinearSphericalMapResult linear = LinearMap(p, t);
  MOBIUS_CHECK(linear.Success);
  MOBIUS_CHECK(linear.PoleTriangle >= 0 && linear.PoleTriangle < t.rows());
  MOBIUS_CHECK(AllOnUnitSphere(linear.SpherePoints));
  MapDistortion d = MeasureMapDistortion(p, linear.SpherePoints, t);
  MOBIUS_CHECK(d.FlippedTriangles == 0);
  MOBIUS_CHECK(d.MeanQuasiConformal < 1.1); // measured 1.075 (the flow's map: 1.000)
  MOBIUS_CHECK(DistancesUpToRotation(linear.SpherePoints, p).mean() < 0.03); // measured 0.012

  // An ellipsoid: the linear map is close to conformal already; the flow from it takes
  // fewer steps (measured: 6 instead of 8) to the same map.
  MakeEllipsoid(4, p, t);
  linear = LinearMap(p, t);
  MOBIUS_CHECK(linear.Success);
  d = MeasureMapDistortion(p, linear.SpherePoints, t);
  MOBIUS_CHECK(d.FlippedTriangles == 0);
  MOBIUS_CHECK(d.MeanQuasiConformal < 1.12); // measured 1.080 (the flow's map: 1.026)
  ConformalMapParameters parameters;
  parameters.LinearStart = false;
  parameters.ReuseFactorization = false;
  const ConformalMapResult fromSurface = ComputeSphericalConformalMap(p, t, parameters);
  MOBIUS_CHECK(fromSurface.Factorizations == fromSurface.Iterations);
  MOBIUS_CHECK(fromSurface.ConjugateGradientIterations == 0);
  parameters.LinearStart = true;
  const ConformalMapResult factorizingEachStep = ComputeSphericalConformalMap(p, t, parameters);
  MOBIUS_CHECK(factorizingEachStep.Factorizations == factorizingEachStep.Iterations + 1);
  parameters.ReuseFactorization = true;
  const ConformalMapResult smallMesh = ComputeSphericalConformalMap(p, t, parameters);
  MOBIUS_CHECK(smallMesh.Factorizations == factorizingEachStep.Factorizations); // below 50K
  parameters.ReuseFactorizationMinimumSize = 0;
  const ConformalMapResult fromLinear = ComputeSphericalConformalMap(p, t, parameters);
  // Reusing the first step's factorization: the linear start's and the first step's are
  // the only ones, a few conjugate gradient iterations per later step (measured 3-4), and
  // the same steps and map as factorizing each step's matrix.
  MOBIUS_CHECK(fromLinear.Factorizations == 2);
  MOBIUS_CHECK(fromLinear.ConjugateGradientIterations > 0);
  MOBIUS_CHECK(fromLinear.ConjugateGradientIterations <= 5 * (fromLinear.Iterations - 1));
  MOBIUS_CHECK(fromLinear.Iterations == factorizingEachStep.Iterations);
  MOBIUS_CHECK(DistanceUpToRotation(fromLinear.SpherePoints, factorizingEachStep.SpherePoints) < 1e-8);
  MOBIUS_CHECK(fromSurface.Success && fromLinear.Success);
  MOBIUS_CHECK(!fromSurface.LinearStart && fromSurface.PoleTriangle == -1);
  MOBIUS_CHECK(fromLinear.LinearStart && fromLinear.LinearStartError.empty());
  MOBIUS_CHECK(fromLinear.Converged);
  MOBIUS_CHECK(fromLinear.Iterations + 2 <= fromSurface.Iterations);
  MOBIUS_CHECK(!fromLinear.Reflected);
  MOBIUS_CHECK(fromLinear.Distortion.FlippedTriangles == 0);
  MOBIUS_CHECK_NEAR(fromLinear.Distortion.MeanQuasiConformal,
    fromSurface.Distortion.MeanQuasiConformal, 1e-4);
  // Both maps are Möbius-centered, so they agree up to a rotation.
  MOBIUS_CHECK(DistancesUpToRotation(fromLinear.SpherePoints, fromSurface.SpherePoints).mean() < 1e-3);
  // The linear map itself is near the flow's result (measured 0.014).
  MOBIUS_CHECK(DistancesUpToRotation(linear.SpherePoints, fromSurface.SpherePoints).mean() < 0.03);

  // A turned copy gets the turned map (the linear map is turned to the surface's
  // orientation, and the flow commutes with rotations), as from the surface. Up to the
  // flow's tolerance, not to rounding: after rounding the turned copy may pick another,
  // equally good pole triangle (here it does: measured 9e-4; without the turn to the
  // surface's orientation both maps would be the same, up to 0.96 apart).
  const Eigen::Matrix3d turn =
    Eigen::AngleAxisd(1.0, Eigen::Vector3d(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  const Points turned = p * turn.transpose();
  const ConformalMapResult turnedMap = ComputeSphericalConformalMap(turned, t, parameters);
  MOBIUS_CHECK(turnedMap.Success && turnedMap.LinearStart);
  MOBIUS_CHECK(((fromLinear.SpherePoints * turn.transpose()) - turnedMap.SpherePoints)
                 .rowwise().norm().maxCoeff() < 5e-3);
  // ... and ends near the orientation of the flow from the surface (measured 3.5e-4).
  MOBIUS_CHECK((fromLinear.SpherePoints - fromSurface.SpherePoints).rowwise().norm().mean() < 5e-3);

  // Plain CMCF (no centering between steps) is the published flow from the surface.
  ConformalMapParameters plain;
  plain.MobiusCentering = false;
  plain.MaximumNumberOfIterations = 3;
  const ConformalMapResult plainFlow = ComputeSphericalConformalMap(p, t, plain);
  MOBIUS_CHECK(plainFlow.Success && !plainFlow.LinearStart && plainFlow.PoleTriangle == -1);

  // The input's triangles facing inward: the linear start's map faces outward by
  // construction; it is still reported as a mirror image of the surface.
  Triangles inward = t;
  inward.col(1).swap(inward.col(2));
  const ConformalMapResult mirrored = ComputeSphericalConformalMap(p, inward);
  MOBIUS_CHECK(mirrored.Success && mirrored.LinearStart && mirrored.Reflected);
  MOBIUS_CHECK(mirrored.Distortion.FlippedTriangles == 0);
  MOBIUS_CHECK(mirrored.Iterations == fromLinear.Iterations);
}

void TestInvalidInputs()
{
  Points p;
  Triangles t;
  MakeIcosphere(2, p, t);

  // A hole.
  Triangles holed = t.topRows(t.rows() - 1);
  ConformalMapResult r = ComputeSphericalConformalMap(p, holed);
  MOBIUS_CHECK(!r.Success);
  MOBIUS_CHECK(r.SpherePoints.rows() == 0);
  MOBIUS_CHECK(Contains(r.Message, "1 boundary loop (holes)"));

  // A NaN coordinate.
  Points bad = p;
  bad(7, 0) = std::numeric_limits<double>::quiet_NaN();
  r = ComputeSphericalConformalMap(bad, t);
  MOBIUS_CHECK(!r.Success);
  MOBIUS_CHECK(Contains(r.Message, "NaN"));

  // Two coincident points joined by an edge (a zero-length edge).
  bad = p;
  bad.row(t(0, 1)) = bad.row(t(0, 0));
  r = ComputeSphericalConformalMap(bad, t);
  MOBIUS_CHECK(!r.Success);
  MOBIUS_CHECK(Contains(r.Message, "zero-length edge") || Contains(r.Message, "zero-area"));

  // A torus: genus 1.
  Points torus;
  Triangles torusT;
  MakeTorus(16, 8, 2.0, 0.6, torus, torusT);
  r = ComputeSphericalConformalMap(torus, torusT);
  MOBIUS_CHECK(!r.Success);
  MOBIUS_CHECK(Contains(r.Message, "genus 1"));

  // A sliver of three points on a line (m on the edge (a, b), closing the triangle split at
  // m): mapped on the intrinsic Delaunay triangulation, refused by name without it.
  Points withMidpoint;
  Triangles split;
  InsertSliver(p, t, (p.row(t(0, 0)) + p.row(t(0, 1))) / 2, withMidpoint, split);
  ConformalMapParameters withoutIntrinsic;
  withoutIntrinsic.IntrinsicDelaunay = false;
  withoutIntrinsic.IntrinsicDelaunayWhenFolded = false;
  r = ComputeSphericalConformalMap(withMidpoint, split, withoutIntrinsic);
  MOBIUS_CHECK(!r.Success && Contains(r.Message, "zero-area triangles (1, three points on a line)"));
  r = ComputeSphericalConformalMap(withMidpoint, split);
  MOBIUS_CHECK(r.Success && AllOnUnitSphere(r.SpherePoints));

  // Parameters.
  ConformalMapParameters parameters;
  parameters.TimeStep = -1.0;
  MOBIUS_CHECK(!ComputeSphericalConformalMap(p, t, parameters).Success);
  parameters = ConformalMapParameters();
  parameters.MaximumNumberOfIterations = 0;
  MOBIUS_CHECK(!ComputeSphericalConformalMap(p, t, parameters).Success);
}

void TestHooksAndAbort()
{
  Points p;
  Triangles t;
  MakeEllipsoid(2, p, t);
  ConformalMapParameters parameters;
  int calls = 0;
  parameters.BetweenSteps = [&calls](Points&, int iteration) {
    ++calls;
    return iteration == calls; // called once per step, in order
  };
  std::vector<double> reported;
  parameters.Progress = [&reported](double progress) {
    reported.push_back(progress);
    return true;
  };
  ConformalMapResult r = ComputeSphericalConformalMap(p, t, parameters);
  MOBIUS_CHECK(r.Success);
  MOBIUS_CHECK(calls == r.Iterations);
  // Once before the flow and once per step, increasing, and well past the start by the
  // end (a long map's progress bar must move, not stay at steps / iteration limit).
  MOBIUS_CHECK(static_cast<int>(reported.size()) == r.Iterations + 1);
  MOBIUS_CHECK(std::is_sorted(reported.begin(), reported.end()));
  MOBIUS_CHECK(reported.front() > 0.0 && reported.back() < 1.0);
  MOBIUS_CHECK(r.Iterations < 5 || reported.back() > 0.5);

  // Abort from the progress callback after the second step (0.05, then 0.185, 0.30).
  calls = 0;
  parameters.BetweenSteps = [&calls](Points&, int) { return ++calls > 0; };
  parameters.Progress = [](double progress) { return progress < 0.25; };
  r = ComputeSphericalConformalMap(p, t, parameters);
  MOBIUS_CHECK(!r.Success);
  MOBIUS_CHECK(Contains(r.Message, "aborted"));
  MOBIUS_CHECK(r.SpherePoints.rows() == 0);
  MOBIUS_CHECK(calls == 2);

  // A fixed number of steps: tolerance 0 never converges.
  parameters = ConformalMapParameters();
  parameters.ConvergenceTolerance = 0.0;
  parameters.MaximumNumberOfIterations = 5;
  r = ComputeSphericalConformalMap(p, t, parameters);
  MOBIUS_CHECK(r.Success);
  MOBIUS_CHECK(!r.Converged);
  MOBIUS_CHECK(r.Iterations == 5);
}
}

// The flow's input preparation: an exact power-of-two rescaling, outward-facing triangles,
// and areas that double precision cannot hold refused with the triangle named.
void TestFlowInput()
{
  Points p;
  Triangles t;
  MakeIcosphere(1, p, t);
  Points huge = p * 1e100;
  const int exponent = ScaleToUnitOrder(huge, t);
  MOBIUS_CHECK(huge.cwiseAbs().maxCoeff() >= 1.0 && huge.cwiseAbs().maxCoeff() < 2.0);
  // A point no triangle uses, far away: the scale is the surface's.
  Points stray(p.rows() + 1, 3);
  stray.topRows(p.rows()) = p;
  stray.row(p.rows()) << 1e100, 0, 0;
  MOBIUS_CHECK(ScaleToUnitOrder(stray, t) == std::ilogb(p.cwiseAbs().maxCoeff()));
  MOBIUS_CHECK(((huge * std::ldexp(1.0, exponent)).array() == (p * 1e100).array()).all());
  Vector areas;
  std::string problem;
  MOBIUS_CHECK(TriangleAreasAtScale(huge, t, exponent, areas, problem) && problem.empty());
  Vector unitAreas;
  MOBIUS_CHECK(TriangleAreasAtScale(p, t, 0, unitAreas, problem));
  MOBIUS_CHECK_NEAR(areas.sum() / (unitAreas.sum() * 1e200), 1.0, 1e-12);
  // At 2^600 the areas overflow double precision: refused, naming triangle 0.
  MOBIUS_CHECK(!TriangleAreasAtScale(huge, t, exponent + 600, areas, problem));
  MOBIUS_CHECK(problem.find("triangle 0:") != std::string::npos);

  Triangles inward = t;
  inward.col(1).swap(inward.col(2));
  MOBIUS_CHECK(FaceOutward(p, inward));
  MOBIUS_CHECK(inward == t);
  MOBIUS_CHECK(!FaceOutward(p, inward));
  MOBIUS_CHECK(EnclosedVolume(p, inward) > 0);
}

int main()
{
  TestSphereMapsToItself();
  TestEllipsoid();
  TestNeedleTriangles();
  TestLinearStart();
  TestInvalidInputs();
  TestHooksAndAbort();
  TestFlowInput();
  return MOBIUS_TEST_RESULT();
}
