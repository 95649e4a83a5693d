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

std::string FindConeVertices(
  const std::vector<Index>& inputIds, const Index coneIds[2], Index cones[2])
{
  for (int c = 0; c < 2 && coneIds[0] >= 0; ++c)
  {
    cones[c] = -1;
    for (size_t i = 0; i < inputIds.size(); ++i)
    {
      if (inputIds[i] == coneIds[c])
      {
        cones[c] = static_cast<Index>(i);
      }
    }
    if (cones[c] < 0)
    {
      std::ostringstream s;
      s << "cone " << coneIds[c]
        << " is not a vertex of the repaired surface (an unused or duplicate point the "
           "conformal map dropped)";
      return s.str();
    }
  }
  return std::string();
}

OrbifoldOutputMesh SelectOrbifoldOutput(const SphericalOrbifoldMapResult& result,
  const Points& surface, const Triangles& triangles, bool wholeCovering)
{
  const CyclicCovering& covering = result.Covering;
  const Index F = triangles.rows();
  const Index outputTriangles = wholeCovering ? covering.CoveringTriangles.rows() : F;
  const Vector areas = TriangleAreas(surface, triangles);
  OrbifoldOutputMesh mesh;
  mesh.OutputTriangles.resize(outputTriangles, 3);
  mesh.TriangleAreas.resize(outputTriangles);
  std::vector<Index> newId(covering.SourceVertex.size(), -1);
  std::vector<Index> used; // covering vertices in order of first use
  for (Index t = 0; t < outputTriangles; ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      const Index w = covering.CoveringTriangles(t, c);
      if (newId[w] < 0)
      {
        newId[w] = static_cast<Index>(used.size());
        used.push_back(w);
      }
      mesh.OutputTriangles(t, c) = newId[w];
    }
    mesh.TriangleCopy.push_back(static_cast<int>(t / F));
    mesh.TriangleAreas[t] = areas[t % F];
  }
  const Index n = static_cast<Index>(used.size());
  mesh.SpherePoints.resize(n, 3);
  mesh.SurfacePoints.resize(n, 3);
  for (Index i = 0; i < n; ++i)
  {
    const Index w = used[i];
    mesh.SourceVertex.push_back(covering.SourceVertex[w]);
    mesh.VertexCopy.push_back(covering.VertexCopy[w]);
    mesh.SpherePoints.row(i) = result.CoveringMap.row(w);
    mesh.SurfacePoints.row(i) = surface.row(covering.SourceVertex[w]);
  }
  return mesh;
}

namespace
{
// The mesh's own spherical map (the given one, or the conformal flow's), centered, and its
// area distortion, into the result; or why there is none.
std::string CenteredPlainMap(const Points& points, const Triangles& triangles,
  const Points& plainMap, const SphericalOrbifoldMapParameters& parameters,
  const ProgressCallback& progress, SphericalOrbifoldMapResult& result)
{
  if (plainMap.rows() == 0)
  {
    ConformalMapParameters flow = parameters.Flow;
    flow.Progress = [&](double f) { return progress(0.3 * f); };
    ConformalMapResult plain = ComputeSphericalConformalMap(points, triangles, flow);
    if (!plain.Success)
    {
      return "the spherical map of the mesh failed: " + plain.Message;
    }
    result.PlainMap = plain.SpherePoints;
  }
  else if (plainMap.rows() != points.rows() || !plainMap.allFinite())
  {
    return "the given spherical map does not have one finite point per vertex";
  }
  else
  {
    result.PlainMap = plainMap.rowwise().normalized();
  }
  const Vector areas = TriangleAreas(points, triangles);
  MobiusCenteringResult centering;
  if (!CenterSphericalMap(result.PlainMap, triangles, areas, parameters.Centering, centering))
  {
    return "centering the mesh's spherical map failed: " + centering.Error;
  }
  result.PlainAreaDistortion = MeasureAreaDistortion(points, result.PlainMap, triangles);
  return {};
}

// The cones (given, or two far-apart vertices), the shortest edge path between them and
// the covering glued along it, into the result; `cutEdges` the path's length.
std::string CutAndCover(const Points& points, const Triangles& triangles,
  const SphericalOrbifoldMapParameters& parameters, SphericalOrbifoldMapResult& result,
  size_t& cutEdges)
{
  result.Cones[0] = parameters.Cones[0];
  result.Cones[1] = parameters.Cones[1];
  if (result.Cones[0] < 0)
  {
    const auto far = FarApartVertices(points, triangles);
    result.Cones[0] = far.first;
    result.Cones[1] = far.second;
    if (far.first < 0 || far.second < 0 || far.first == far.second)
    {
      return "cannot find two distinct cone vertices on the mesh";
    }
  }
  const std::vector<Index> cut =
    ShortestEdgePath(points, triangles, result.Cones[0], result.Cones[1]);
  if (cut.empty())
  {
    return "the two cone vertices are not connected by edges";
  }
  cutEdges = cut.size() - 1;
  if (!BuildCyclicCovering(points.rows(), triangles, cut, parameters.Copies, result.Covering))
  {
    return "cannot build the covering: " + result.Covering.Error;
  }
  return {};
}

// The flow on the covering, from the lifted map (after its first step, whose result from
// the copies lying on top of each other is discarded), into result.CoveringFlow and
// result.CoveringMap.
std::string FlowOnCovering(const Triangles& triangles, const Points& coveringPoints,
  const SphericalOrbifoldMapParameters& parameters, const ProgressCallback& progress,
  SphericalOrbifoldMapResult& result)
{
  Points lifted;
  std::string liftError;
  if (!LiftSphericalMapToCovering(result.PlainMap, triangles, result.Covering, lifted, liftError))
  {
    return liftError;
  }
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
  result.CoveringFlow =
    ComputeSphericalConformalMap(coveringPoints, result.Covering.CoveringTriangles, flow);
  if (!result.CoveringFlow.Success)
  {
    return "the conformal flow on the covering failed: " + result.CoveringFlow.Message;
  }
  result.CoveringMap = result.CoveringFlow.SpherePoints;
  return {};
}

// The covering's map centered with the covering's areas, turned so that the cone axis is
// z, and measured (symmetry, flips, area distortion).
std::string CenterAndMeasureCovering(const Points& coveringPoints,
  const SphericalOrbifoldMapParameters& parameters, SphericalOrbifoldMapResult& result)
{
  const CyclicCovering& covering = result.Covering;
  const Triangles& coveringTriangles = covering.CoveringTriangles;
  const Vector coveringAreas = TriangleAreas(coveringPoints, coveringTriangles);
  if (!CenterSphericalMap(result.CoveringMap, coveringTriangles, coveringAreas,
        parameters.Centering, result.CoveringCentering))
  {
    return "centering the covering's map failed: " + result.CoveringCentering.Error;
  }
  const Eigen::Vector3d a = result.CoveringMap.row(covering.ConeVertices[0]);
  const Eigen::Vector3d b = result.CoveringMap.row(covering.ConeVertices[1]);
  result.ConeAntipodality = (a + b).norm();
  if (!((b - a).norm() > 0.0))
  {
    return "the covering's map sends both cones to the same point";
  }
  const Eigen::Matrix3d toZ = RotationTaking(b - a, Eigen::Vector3d::UnitZ());
  result.CoveringMap = (result.CoveringMap * toZ.transpose()).eval();
  result.Symmetry = MeasureCyclicSymmetry(
    result.CoveringMap, covering.NextCopyVertex, Eigen::Vector3d::UnitZ(), parameters.Copies);
  result.FlippedTriangles =
    MeasureMapDistortion(coveringPoints, result.CoveringMap, coveringTriangles).FlippedTriangles;
  result.OrbifoldAreaDistortion =
    MeasureAreaDistortion(coveringPoints, result.CoveringMap, coveringTriangles);
  return {};
}
}

SphericalOrbifoldMapResult ComputeSphericalOrbifoldMap(const Points& points,
  const Triangles& triangles, const Points& plainMap,
  const SphericalOrbifoldMapParameters& parameters)
{
  SphericalOrbifoldMapResult result;
  const int n = parameters.Copies;
  std::string error =
    CheckOrbifoldParameters(points.rows(), n, parameters.Cones[0], parameters.Cones[1]);
  const ProgressCallback progress = [&](double fraction) {
    return !parameters.Progress || parameters.Progress(fraction);
  };
  size_t cutEdges = 0;
  if (!error.empty() ||
    !(error = CenteredPlainMap(points, triangles, plainMap, parameters, progress, result))
       .empty() ||
    !(error = CutAndCover(points, triangles, parameters, result, cutEdges)).empty())
  {
    return Fail(result, error);
  }
  if (!progress(0.35))
  {
    return Fail(result, "aborted");
  }
  const Points coveringPoints = result.Covering.CoveringPoints(points);
  if (!(error = FlowOnCovering(triangles, coveringPoints, parameters, progress, result)).empty() ||
    !(error = CenterAndMeasureCovering(coveringPoints, parameters, result)).empty())
  {
    return Fail(result, error);
  }
  if (!progress(1.0))
  {
    return Fail(result, "aborted");
  }
  std::ostringstream s;
  s << n << "-fold orbifold map: cones " << result.Cones[0] << " and " << result.Cones[1]
    << ", cut of " << cutEdges << " edges; symmetry error " << result.Symmetry.MaximumDistance
    << ", std of log area ratio " << result.OrbifoldAreaDistortion.StdLogAreaRatio
    << " (plain map: " << result.PlainAreaDistortion.StdLogAreaRatio << ")";
  result.Message = s.str();
  result.Success = true;
  return result;
}
}
