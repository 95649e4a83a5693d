// Spherical orbifold maps (paper §7.2) on a generated, lopsided, elongated surface:
// - the n-fold cyclic covering is a closed genus-0 mesh with n (V - 2) + 2 vertices whose
//   deck transformation permutes its triangles; bad cut paths are refused with reasons;
// - for n = 2, 3, 4 the centered map of the covering is n-fold rotationally symmetric about z
//   (each vertex rotated by 2 pi / n lands on its copy in the next sheet), its cones are
//   antipodal, no triangle is flipped, and it distorts area less than the plain map;
// - the same map after a Möbius transformation (another conformal map of the covering, not
//   centered) is far from symmetric, and centering it again restores the symmetry;
// - the symmetry is there from the flow's lifted start on, and every flow step keeps it
//   (with or without centering between the steps);
// - bad parameters (cones out of range or equal, n outside 2..8) fail with their reason.
#include "CoreTest.h"
#include "CutPath.h"
#include "Icosphere.h"
#include "MeshTopology.h"
#include "SphericalOrbifoldMap.h"
#include "CotangentLaplacian.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace
{
using mobius::Index;

// An elongated, lopsided closed surface (no symmetry the map could lean on).
void MakeSurface(mobius::Points& points, mobius::Triangles& triangles)
{
  mobius::MakeIcosphere(3, points, triangles);
  for (Index i = 0; i < points.rows(); ++i)
  {
    const double x = points(i, 0), y = points(i, 1), z = points(i, 2);
    const double bump = 1.0 + 0.25 * std::sin(3.0 * x + 1.0) * std::cos(2.0 * y - 0.5) + 0.15 * z * x;
    points.row(i) << 2.5 * x * bump, y * bump, 0.7 * z * bump;
  }
}

// Symmetry error of a covering map about the axis through its two cones.
double SymmetryAboutConeAxis(const mobius::Points& map, const mobius::CyclicCovering& covering)
{
  const Eigen::Vector3d a = map.row(covering.ConeVertices[0]);
  const Eigen::Vector3d b = map.row(covering.ConeVertices[1]);
  return mobius::MeasureCyclicSymmetry(map, covering.NextCopyVertex, (b - a).normalized(),
    covering.Copies)
    .MaximumDistance;
}

void TestCovering(const mobius::Points& points, const mobius::Triangles& triangles)
{
  const auto cones = mobius::FarApartVertices(points, triangles);
  MOBIUS_CHECK(cones.first >= 0 && cones.second >= 0 && cones.first != cones.second);
  const std::vector<Index> cut =
    mobius::ShortestEdgePath(points, triangles, cones.first, cones.second);
  MOBIUS_CHECK(cut.size() >= 3);
  for (int n = 2; n <= 8; ++n)
  {
    mobius::CyclicCovering covering;
    MOBIUS_CHECK(mobius::BuildCyclicCovering(points.rows(), triangles, cut, n, covering));
    const mobius::Points coveringPoints = covering.CoveringPoints(points);
    MOBIUS_CHECK(coveringPoints.rows() == n * (points.rows() - 2) + 2);
    MOBIUS_CHECK(covering.CoveringTriangles.rows() == n * triangles.rows());
    const mobius::MeshTopologyReport report =
      mobius::AnalyzeMeshTopology(coveringPoints, covering.CoveringTriangles);
    MOBIUS_CHECK(report.IsTopologicalSphere());
    // The deck transformation sends triangle t of copy i onto triangle t of copy i + 1.
    const Index F = triangles.rows();
    bool deck = true;
    for (Index t = 0; t < n * F; ++t)
    {
      for (int c = 0; c < 3; ++c)
      {
        deck = deck &&
          covering.NextCopyVertex[covering.CoveringTriangles(t, c)] ==
            covering.CoveringTriangles((t + F) % (n * F), c);
      }
    }
    MOBIUS_CHECK(deck);
  }
  // Refused cut paths.
  mobius::CyclicCovering covering;
  MOBIUS_CHECK(!mobius::BuildCyclicCovering(points.rows(), triangles, { cut[0], cut[1] }, 3, covering));
  MOBIUS_CHECK(covering.Error.find("two edges") != std::string::npos);
  std::vector<Index> gap = cut;
  gap.erase(gap.begin() + 1);
  MOBIUS_CHECK(!mobius::BuildCyclicCovering(points.rows(), triangles, gap, 3, covering));
  MOBIUS_CHECK(covering.Error.find("share an edge") != std::string::npos);
  MOBIUS_CHECK(!mobius::BuildCyclicCovering(points.rows(), triangles, cut, 1, covering));
}

// The filter's output: one copy has as many triangles as the mesh, each on the surface area
// of the mesh triangle it copies, its vertices numbered by first use; the covering has n
// times the triangles and uses every covering vertex once.
void TestOutputMesh(const mobius::Points& points, const mobius::Triangles& triangles,
  const mobius::SphericalOrbifoldMapResult& result)
{
  const mobius::Vector areas = mobius::TriangleAreas(points, triangles);
  const int n = result.Covering.Copies;
  for (const bool whole : { false, true })
  {
    const mobius::OrbifoldOutputMesh mesh =
      mobius::SelectOrbifoldOutput(result, points, triangles, whole);
    const mobius::Index F = triangles.rows();
    MOBIUS_CHECK(mesh.OutputTriangles.rows() == (whole ? n * F : F));
    MOBIUS_CHECK(mesh.OutputTriangles(0, 0) == 0 && mesh.OutputTriangles(0, 1) == 1);
    MOBIUS_CHECK(mesh.OutputTriangles.maxCoeff() + 1 == mesh.SpherePoints.rows());
    if (whole)
    {
      MOBIUS_CHECK(mesh.SpherePoints.rows() ==
        static_cast<mobius::Index>(result.Covering.SourceVertex.size()));
    }
    for (mobius::Index t = 0; t < mesh.OutputTriangles.rows(); ++t)
    {
      MOBIUS_CHECK(mesh.TriangleCopy[t] == t / F);
      MOBIUS_CHECK(mesh.TriangleAreas[t] == areas[t % F]);
      // Each output corner is a copy of the mesh triangle's corner, at its surface point.
      for (int k = 0; k < 3; ++k)
      {
        const mobius::Index w = mesh.OutputTriangles(t, k);
        MOBIUS_CHECK(mesh.SourceVertex[w] == triangles(t % F, k));
        MOBIUS_CHECK(mesh.SurfacePoints.row(w) == points.row(triangles(t % F, k)));
      }
    }
  }
}

void TestOrbifoldMap(const mobius::Points& points, const mobius::Triangles& triangles, int n)
{
  mobius::SphericalOrbifoldMapParameters parameters;
  parameters.Copies = n;
  const mobius::SphericalOrbifoldMapResult result =
    mobius::ComputeSphericalOrbifoldMap(points, triangles, mobius::Points(), parameters);
  std::cout << result.Message << "; flow steps " << result.CoveringFlow.Iterations
            << ", cones antipodal to " << result.ConeAntipodality << std::endl;
  MOBIUS_CHECK(result.Success);
  if (!result.Success)
  {
    return;
  }
  // Tolerance: the copies' maps differ only by the flow's rounding (the flow treats them
  // alike, and the centering fixes the Möbius freedom to 1e-10), so they match to far below
  // the vertex spacing on the sphere (~0.05 here); 1e-6 leaves room for the factorization's
  // rounding on a 10^4-vertex system.
  MOBIUS_CHECK(result.Symmetry.MaximumDistance < 1e-6);
  MOBIUS_CHECK(result.ConeAntipodality < 1e-6);
  MOBIUS_CHECK(result.FlippedTriangles == 0);
  MOBIUS_CHECK(result.CoveringCentering.Converged);
  const mobius::CyclicCovering& covering = result.Covering;
  MOBIUS_CHECK_NEAR(result.CoveringMap(covering.ConeVertices[1], 2), 1.0, 1e-9);
  MOBIUS_CHECK_NEAR(result.CoveringMap(covering.ConeVertices[0], 2), -1.0, 1e-6);
  // The point of orbifold maps: less area distortion than the plain map.
  MOBIUS_CHECK(result.OrbifoldAreaDistortion.StdLogAreaRatio <
    result.PlainAreaDistortion.StdLogAreaRatio);

  // Another conformal map of the covering: the same one after an inversion. Not centered,
  // not symmetric; centering it makes it symmetric again (the centering is unique up to a
  // rotation, and commutes with the deck transformation).
  mobius::Points uncentered = result.CoveringMap;
  mobius::ApplyInversion(Eigen::Vector3d(0.35, -0.2, 0.25), uncentered);
  const double uncenteredError = SymmetryAboutConeAxis(uncentered, covering);
  std::cout << "  uncentered symmetry error " << uncenteredError << std::endl;
  MOBIUS_CHECK(uncenteredError > 0.05);
  const mobius::Points coveringPoints = covering.CoveringPoints(points);
  mobius::MobiusCenteringResult centering;
  MOBIUS_CHECK(mobius::CenterSphericalMap(uncentered, covering.CoveringTriangles,
    mobius::TriangleAreas(coveringPoints, covering.CoveringTriangles),
    mobius::MobiusCenteringParameters(), centering));
  const double recenteredError = SymmetryAboutConeAxis(uncentered, covering);
  std::cout << "  re-centered symmetry error " << recenteredError << std::endl;
  MOBIUS_CHECK(recenteredError < 1e-6);

  TestOutputMesh(points, triangles, result);

  // Where the symmetry comes from (as the README says): the lifted start is already
  // symmetric about z and every flow step keeps it, with the centering between the steps
  // or without it; the final centering only keeps it too.
  for (const bool centerBetweenSteps : { true, false })
  {
    mobius::SphericalOrbifoldMapParameters traced = parameters;
    traced.Cones[0] = result.Cones[0];
    traced.Cones[1] = result.Cones[1];
    traced.Flow.MobiusCentering = centerBetweenSteps;
    double worst = 0.0;
    int steps = 0;
    traced.Flow.BetweenSteps = [&](mobius::Points& positions, int) {
      const mobius::Points onSphere = positions.rowwise().normalized();
      worst = std::max(worst, mobius::MeasureCyclicSymmetry(onSphere, covering.NextCopyVertex,
                                Eigen::Vector3d::UnitZ(), n).MaximumDistance);
      ++steps;
      return true;
    };
    // The plain map given, so that the hook sees only the covering's flow.
    const mobius::SphericalOrbifoldMapResult again =
      mobius::ComputeSphericalOrbifoldMap(points, triangles, result.PlainMap, traced);
    std::cout << "  centering between steps " << centerBetweenSteps << ": " << steps
              << " flow steps, symmetry about z at most " << worst << ", final "
              << again.Symmetry.MaximumDistance << std::endl;
    MOBIUS_CHECK(again.Success && steps >= 2);
    MOBIUS_CHECK(worst < 1e-9);
    MOBIUS_CHECK(again.Symmetry.MaximumDistance < 1e-9);
  }
}

void TestErrors(const mobius::Points& points, const mobius::Triangles& triangles)
{
  const Index V = points.rows();
  MOBIUS_CHECK(mobius::CheckOrbifoldParameters(V, 3, -1, -1).empty());
  MOBIUS_CHECK(mobius::CheckOrbifoldParameters(V, 3, 0, 5).empty());
  MOBIUS_CHECK(mobius::CheckOrbifoldParameters(V, 1, -1, -1).find("between 2 and 8") != std::string::npos);
  MOBIUS_CHECK(mobius::CheckOrbifoldParameters(V, 9, -1, -1).find("not 9") != std::string::npos);
  MOBIUS_CHECK(mobius::CheckOrbifoldParameters(V, 3, 0, V).find("does not exist") != std::string::npos);
  MOBIUS_CHECK(mobius::CheckOrbifoldParameters(V, 3, -1, 4).find("does not exist") != std::string::npos);
  MOBIUS_CHECK(mobius::CheckOrbifoldParameters(V, 3, 7, 7).find("same vertex") != std::string::npos);
  // Neighbouring cones: refused when the covering is built.
  mobius::SphericalOrbifoldMapParameters parameters;
  parameters.Cones[0] = triangles(0, 0);
  parameters.Cones[1] = triangles(0, 1);
  const mobius::SphericalOrbifoldMapResult result =
    mobius::ComputeSphericalOrbifoldMap(points, triangles, mobius::Points(), parameters);
  MOBIUS_CHECK(!result.Success);
  MOBIUS_CHECK(result.Message.find("neighbours") != std::string::npos);
  parameters.Cones[1] = triangles(0, 0);
  MOBIUS_CHECK(!mobius::ComputeSphericalOrbifoldMap(points, triangles, mobius::Points(), parameters).Success);

  // Cones by input point id: the last vertex carrying it; an id no vertex carries is named.
  const std::vector<mobius::Index> inputIds = { 10, 11, 12, 11, 14 };
  mobius::Index cones[2] = { -1, -1 };
  const mobius::Index automatic[2] = { -1, -1 };
  MOBIUS_CHECK(mobius::FindConeVertices(inputIds, automatic, cones).empty());
  MOBIUS_CHECK(cones[0] == -1 && cones[1] == -1);
  const mobius::Index given[2] = { 14, 11 };
  MOBIUS_CHECK(mobius::FindConeVertices(inputIds, given, cones).empty());
  MOBIUS_CHECK(cones[0] == 4 && cones[1] == 3);
  const mobius::Index dropped[2] = { 10, 13 };
  MOBIUS_CHECK(mobius::FindConeVertices(inputIds, dropped, cones).find("cone 13 is not a vertex") == 0);
}
}

int main()
{
  mobius::Points points;
  mobius::Triangles triangles;
  MakeSurface(points, triangles);
  TestCovering(points, triangles);
  for (int n = 2; n <= 4; ++n)
  {
    TestOrbifoldMap(points, triangles, n);
  }
  TestErrors(points, triangles);
  return MOBIUS_TEST_RESULT();
}
