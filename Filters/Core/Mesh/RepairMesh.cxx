#include "RepairMesh.h"

#include "GenusZeroProxy.h"
#include "HoleFilling.h"

#include <sstream>
#include <utility>

namespace mobius
{
namespace
{
// The problems of a mesh that is still no topological sphere, and the option that would
// repair each.
std::string DescribeProblem(
  const MeshTopologyReport& report, bool oriented, const MeshRepairOptions& options)
{
  std::ostringstream message;
  message << DescribeTopologyProblems(report);
  // Edges left disagreeing where no edge is non-manifold: no orientation exists, which
  // "orientations disagree" alone does not tell (re-orienting the file would not help).
  if (!oriented && report.NonManifoldEdges == 0 && report.InconsistentlyOrientedEdges > 0)
  {
    message << " (no orientation of the triangles agrees on every edge: the surface is not "
               "orientable, like a Moebius strip or a Klein bottle)";
  }
  if (report.BoundaryLoops > 0 && !options.FillHoles)
  {
    message << ". Set FillHoles to close the holes";
  }
  if (report.ConnectedComponents > 1 && !options.KeepLargestComponent)
  {
    message << ". Set KeepLargestComponent to map only the largest component";
  }
  return message.str();
}

// The repairs done in every mode: a soup's duplicated points merged, zero-length edges
// collapsed, and in strict mode the largest component on request; then the unused points
// dropped. Returns the problem when no triangle has an area.
std::string AlwaysRepair(Points& points, Triangles& triangles, RepairedMesh& mesh,
  MeshTopologyReport& report, const MeshRepairOptions& options)
{
  // Only a mesh with open edges is a triangle soup to merge: a closed mesh may have two
  // vertices at the same position (CGAL's cow does) and merging would pinch it.
  mesh.Log.MergedDuplicatePoints = report.BoundaryEdges > 0 ? report.DuplicatePoints : 0;
  if (mesh.Log.MergedDuplicatePoints > 0)
  {
    ComposeProvenance(mesh.Provenance, MergeDuplicatePoints(points, triangles));
  }
  if (report.ZeroAreaTriangles > 0 && report.ZeroAreaTriangles == report.NumberOfTriangles)
  {
    return "every triangle has zero area (the points lie on a line or in one place)";
  }
  // Only a zero-area triangle can have a zero-length edge.
  if (report.ZeroAreaTriangles > 0)
  {
    ComposeProvenance(mesh.Provenance, CollapseZeroLengthEdges(points, triangles, &mesh.Log.CollapsedEdges));
  }
  const bool keepLargest = !options.Repair && options.KeepLargestComponent && report.ConnectedComponents > 1;
  if (keepLargest)
  {
    const Index trianglesBefore = triangles.rows();
    const double areaBefore = SurfaceArea(points, triangles);
    ComposeProvenance(mesh.Provenance, ExtractLargestComponent(points, triangles));
    mesh.Log.DroppedComponents = report.ConnectedComponents - 1;
    mesh.Log.DroppedComponentTriangles = trianglesBefore - triangles.rows();
    mesh.Log.DroppedComponentArea = areaBefore - SurfaceArea(points, triangles);
  }
  mesh.Log.DroppedUnusedPoints = report.UnusedPoints;
  // The report is recomputed only after a repair changed the mesh: on a clean mesh (the
  // usual case) it is still the first one, and the analysis is a large share of the map's
  // time outside the flow.
  bool changed = mesh.Log.MergedDuplicatePoints > 0 || mesh.Log.CollapsedEdges > 0 || keepLargest;
  const Index pointsBefore = points.rows();
  ComposeProvenance(mesh.Provenance, RemoveUnusedPoints(points, triangles));
  if (changed || points.rows() != pointsBefore)
  {
    report = AnalyzeMeshTopology(points, triangles);
  }
  return {};
}

// Strict mode: holes filled on request, the triangles oriented if they can be. Returns
// whether they could.
bool RepairOnRequest(Points& points, Triangles& triangles, RepairedMesh& mesh,
  MeshTopologyReport& report, const MeshRepairOptions& options)
{
  bool changed = false;
  if (options.FillHoles && report.BoundaryLoops > 0)
  {
    MeshProvenance filled;
    const HoleFillResult result = FillHoles(points, triangles, &filled);
    ComposeProvenance(mesh.Provenance, filled);
    mesh.Log.FilledHoles = result.Holes;
    mesh.Log.FilledBoundaryEdges = result.BoundaryEdges;
    mesh.Log.FilledArea = result.Area;
    changed = true;
  }
  // With every two-sided edge agreeing (and the report current), re-orienting would flip
  // no triangle: each breadth-first choice keeps its neighbour's orientation.
  bool oriented = true;
  if (changed || report.InconsistentlyOrientedEdges > 0)
  {
    oriented = OrientConsistently(triangles, &mesh.Log.ReversedTriangles);
    changed = changed || mesh.Log.ReversedTriangles > 0;
  }
  if (changed)
  {
    report = AnalyzeMeshTopology(points, triangles);
  }
  return oriented;
}
}

RepairedMesh RepairMesh(Points points, Triangles triangles, const MeshRepairOptions& options)
{
  RepairedMesh mesh;
  mesh.Provenance = IdentityProvenance(points.rows(), triangles.rows());
  MeshTopologyReport report = AnalyzeMeshTopology(points, triangles);
  const bool repair = options.Repair && !report.IsTopologicalSphere();
  if (!report.IsTopologicalSphere())
  {
    mesh.Log.InputArea = SurfaceArea(points, triangles);
  }
  mesh.Problem = AlwaysRepair(points, triangles, mesh, report, options);
  if (!mesh.Problem.empty())
  {
    return mesh;
  }
  bool oriented = true;
  if (repair && !report.IsTopologicalSphere())
  {
    mesh.Problem = RepairIntoGenusZeroProxy(points, triangles, mesh.Provenance, mesh.Log, options);
    report = AnalyzeMeshTopology(points, triangles);
  }
  else
  {
    oriented = RepairOnRequest(points, triangles, mesh, report, options);
  }
  if (mesh.Problem.empty() && !report.IsTopologicalSphere())
  {
    mesh.Problem = DescribeProblem(report, oriented, options);
  }
  mesh.Log.ProxyArea = mesh.Log.Any() ? SurfaceArea(points, triangles) : 0.0;
  mesh.Topology = report;
  mesh.Points = std::move(points);
  mesh.Triangles = std::move(triangles);
  return mesh;
}

MeshProvenance RemoveUnusedPoints(Points& points, Triangles& triangles)
{
  std::vector<Index> newIndex(points.rows(), -1);
  MeshProvenance provenance;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      newIndex[triangles(t, k)] = 0;
    }
  }
  for (Eigen::Index i = 0; i < points.rows(); ++i)
  {
    if (newIndex[i] == 0)
    {
      newIndex[i] = static_cast<Index>(provenance.PointSource.size());
      provenance.PointSource.push_back(i);
    }
  }
  Points kept(provenance.PointSource.size(), 3);
  for (size_t i = 0; i < provenance.PointSource.size(); ++i)
  {
    kept.row(i) = points.row(provenance.PointSource[i]);
  }
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    provenance.TriangleSource.push_back(t);
    for (int k = 0; k < 3; ++k)
    {
      triangles(t, k) = newIndex[triangles(t, k)];
    }
  }
  points.swap(kept);
  return provenance;
}
}
