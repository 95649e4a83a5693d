#include "SphericalOrbifoldMap.h"

#include "CotangentLaplacian.h"
#include "CoveringLift.h"
#include "CutPath.h"

#include <sstream>

namespace mobius
{
namespace
{
SphericalOrbifoldMapResult Fail(SphericalOrbifoldMapResult& result, const std::string& message)
{
  result.Success = false;
  result.Message = message;
  result.CoveringMap.resize(0, 3);
  return result;
}
}

std::string CheckOrbifoldParameters(Index numberOfPoints, int copies, Index cone0, Index cone1)
{
  std::ostringstream s;
  if (copies < MinimumOrbifoldCopies || copies > MaximumOrbifoldCopies)
  {
    s << "the number of copies (the symmetry order) must be between " << MinimumOrbifoldCopies
      << " and " << MaximumOrbifoldCopies << ", not " << copies;
    return s.str();
  }
  if (cone0 == -1 && cone1 == -1)
  {
    return std::string();
  }
  for (const Index cone : { cone0, cone1 })
  {
    if (cone < 0 || cone >= numberOfPoints)
    {
      s << "cone vertex " << cone << " does not exist (the mesh has " << numberOfPoints
        << " vertices; give both cones, or -1 and -1 for automatic cones)";
      return s.str();
    }
  }
  if (cone0 == cone1)
  {
    s << "the two cone vertices are the same vertex (" << cone0 << ")";
    return s.str();
  }
  return std::string();
}

SphericalOrbifoldMapResult ComputeSphericalOrbifoldMap(const Points& points,
  const Triangles& triangles, const Points& plainMap,
  const SphericalOrbifoldMapParameters& parameters)
{
  SphericalOrbifoldMapResult result;
  const int n = parameters.Copies;
  const std::string problem =
    CheckOrbifoldParameters(points.rows(), n, parameters.Cones[0], parameters.Cones[1]);
  if (!problem.empty())
  {
    return Fail(result, problem);
  }
  auto progress = [&](double fraction) {
    return !parameters.Progress || parameters.Progress(fraction);
  };

  // The mesh's own map, centered.
  if (plainMap.rows() == 0)
  {
    ConformalMapParameters flow = parameters.Flow;
    flow.Progress = [&](double f) { return progress(0.3 * f); };
    ConformalMapResult plain = ComputeSphericalConformalMap(points, triangles, flow);
    if (!plain.Success)
    {
      return Fail(result, "the spherical map of the mesh failed: " + plain.Message);
    }
    result.PlainMap = plain.SpherePoints;
  }
  else if (plainMap.rows() != points.rows() || !plainMap.allFinite())
  {
    return Fail(result, "the given spherical map does not have one finite point per vertex");
  }
  else
  {
    result.PlainMap = plainMap.rowwise().normalized();
  }
  const Vector areas = TriangleAreas(points, triangles);
  {
    MobiusCenteringResult centering;
    if (!CenterSphericalMap(result.PlainMap, triangles, areas, parameters.Centering, centering))
    {
      return Fail(result, "centering the mesh's spherical map failed: " + centering.Error);
    }
  }
  result.PlainAreaDistortion = MeasureAreaDistortion(points, result.PlainMap, triangles);

  // Cones and the cut.
  result.Cones[0] = parameters.Cones[0];
  result.Cones[1] = parameters.Cones[1];
  if (result.Cones[0] < 0)
  {
    const auto far = FarApartVertices(points, triangles);
    result.Cones[0] = far.first;
    result.Cones[1] = far.second;
    if (far.first < 0 || far.second < 0 || far.first == far.second)
    {
      return Fail(result, "cannot find two distinct cone vertices on the mesh");
    }
  }
  const std::vector<Index> cut =
    ShortestEdgePath(points, triangles, result.Cones[0], result.Cones[1]);
  if (cut.empty())
  {
    return Fail(result, "the two cone vertices are not connected by edges");
  }
  if (!BuildCyclicCovering(points.rows(), triangles, cut, n, result.Covering))
  {
    return Fail(result, "cannot build the covering: " + result.Covering.Error);
  }
  if (!progress(0.35))
  {
    return Fail(result, "aborted");
  }

  // The flow on the covering, from the lifted map (after its first step, whose result from
  // the copies lying on top of each other is discarded).
  const CyclicCovering& covering = result.Covering;
  const Triangles& coveringTriangles = covering.CoveringTriangles;
  Points lifted;
  std::string liftError;
  if (!LiftSphericalMapToCovering(result.PlainMap, triangles, covering, lifted, liftError))
  {
    return Fail(result, liftError);
  }
  const Points coveringPoints = covering.CoveringPoints(points);
  ConformalMapParameters flow = parameters.Flow;
  flow.MaximumNumberOfIterations = parameters.Flow.MaximumNumberOfIterations + 1;
  // The start is the lifted map, put in after the first step: a linear start would be
  // computed only to be discarded.
  flow.LinearStart = false;
  const FlowStepHook userHook = parameters.Flow.BetweenSteps;
  flow.BetweenSteps = [&](Points& positions, int iteration) {
    if (iteration == 1)
    {
      positions = lifted;
    }
    return !userHook || userHook(positions, iteration);
  };
  flow.Progress = [&](double f) { return progress(0.35 + 0.6 * f); };
  result.CoveringFlow = ComputeSphericalConformalMap(coveringPoints, coveringTriangles, flow);
  if (!result.CoveringFlow.Success)
  {
    return Fail(result, "the conformal flow on the covering failed: " + result.CoveringFlow.Message);
  }
  result.CoveringMap = result.CoveringFlow.SpherePoints;

  // Center with the covering's areas, then turn the cone axis to z.
  const Vector coveringAreas = TriangleAreas(coveringPoints, coveringTriangles);
  if (!CenterSphericalMap(result.CoveringMap, coveringTriangles, coveringAreas,
        parameters.Centering, result.CoveringCentering))
  {
    return Fail(result, "centering the covering's map failed: " + result.CoveringCentering.Error);
  }
  const Eigen::Vector3d a = result.CoveringMap.row(covering.ConeVertices[0]);
  const Eigen::Vector3d b = result.CoveringMap.row(covering.ConeVertices[1]);
  result.ConeAntipodality = (a + b).norm();
  if (!((b - a).norm() > 0.0))
  {
    return Fail(result, "the covering's map sends both cones to the same point");
  }
  const Eigen::Matrix3d toZ = RotationTaking(b - a, Eigen::Vector3d::UnitZ());
  result.CoveringMap = (result.CoveringMap * toZ.transpose()).eval();
  result.Symmetry = MeasureCyclicSymmetry(
    result.CoveringMap, covering.NextCopyVertex, Eigen::Vector3d::UnitZ(), n);
  result.FlippedTriangles =
    MeasureMapDistortion(coveringPoints, result.CoveringMap, coveringTriangles).FlippedTriangles;
  result.OrbifoldAreaDistortion =
    MeasureAreaDistortion(coveringPoints, result.CoveringMap, coveringTriangles);
  if (!progress(1.0))
  {
    return Fail(result, "aborted");
  }
  std::ostringstream s;
  s << n << "-fold orbifold map: cones " << result.Cones[0] << " and " << result.Cones[1]
    << ", cut of " << cut.size() - 1 << " edges; symmetry error " << result.Symmetry.MaximumDistance
    << ", std of log area ratio " << result.OrbifoldAreaDistortion.StdLogAreaRatio
    << " (plain map: " << result.PlainAreaDistortion.StdLogAreaRatio << ")";
  result.Message = s.str();
  result.Success = true;
  return result;
}
}
