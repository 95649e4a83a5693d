#include "RepairMesh.h"

#include <sstream>
#include <utility>

namespace mobius
{
namespace
{
// Composes a repair's provenance (rows of the mesh before it) with the provenance so far
// (rows of the original mesh): -1 stays -1.
std::vector<Index> Compose(const std::vector<Index>& before, const std::vector<Index>& step)
{
  std::vector<Index> composed(step.size());
  for (size_t i = 0; i < step.size(); ++i)
  {
    composed[i] = step[i] >= 0 ? before[step[i]] : -1;
  }
  return composed;
}

void Apply(MeshProvenance& provenance, const MeshProvenance& step)
{
  provenance.PointSource = Compose(provenance.PointSource, step.PointSource);
  provenance.TriangleSource = Compose(provenance.TriangleSource, step.TriangleSource);
}

MeshProvenance Identity(Index points, Index triangles)
{
  MeshProvenance identity;
  for (Index i = 0; i < points; ++i)
  {
    identity.PointSource.push_back(i);
  }
  for (Index t = 0; t < triangles; ++t)
  {
    identity.TriangleSource.push_back(t);
  }
  return identity;
}

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

RepairedMesh RepairMesh(Points points, Triangles triangles, const MeshRepairOptions& options)
{
  RepairedMesh mesh;
  mesh.Provenance = Identity(points.rows(), triangles.rows());
  MeshTopologyReport report = AnalyzeMeshTopology(points, triangles);
  // Only a mesh with open edges is a triangle soup to merge: a closed mesh may have two
  // vertices at the same position (CGAL's cow does) and merging would pinch it.
  mesh.MergedDuplicatePoints = report.BoundaryEdges > 0 ? report.DuplicatePoints : 0;
  if (mesh.MergedDuplicatePoints > 0)
  {
    Apply(mesh.Provenance, MergeDuplicatePoints(points, triangles));
  }
  if (report.ZeroAreaTriangles > 0 && report.ZeroAreaTriangles == report.NumberOfTriangles)
  {
    mesh.Problem = "every triangle has zero area (the points lie on a line or in one place)";
    return mesh;
  }
  // Only a zero-area triangle can have a zero-length edge.
  if (report.ZeroAreaTriangles > 0)
  {
    Apply(mesh.Provenance, CollapseZeroLengthEdges(points, triangles, &mesh.CollapsedEdges));
  }
  const bool keepLargest = options.KeepLargestComponent && report.ConnectedComponents > 1;
  if (keepLargest)
  {
    Apply(mesh.Provenance, ExtractLargestComponent(points, triangles));
  }
  // The report is recomputed only after a repair changed the mesh: on a clean mesh (the
  // usual case) it is still the first one, and the analysis is a large share of the map's
  // time outside the flow.
  bool changed = mesh.MergedDuplicatePoints > 0 || mesh.CollapsedEdges > 0 || keepLargest;
  const Index pointsBefore = points.rows();
  Apply(mesh.Provenance, RemoveUnusedPoints(points, triangles));
  changed = changed || points.rows() != pointsBefore;
  if (changed)
  {
    report = AnalyzeMeshTopology(points, triangles);
  }
  if (options.FillHoles && report.BoundaryLoops > 0)
  {
    MeshProvenance filled;
    mesh.FilledHoles = FillHoles(points, triangles, &filled);
    Apply(mesh.Provenance, filled);
    changed = true;
  }
  // With every two-sided edge agreeing (and the report current), re-orienting would flip
  // no triangle: each breadth-first choice keeps its neighbour's orientation.
  bool oriented = true;
  if (changed || report.InconsistentlyOrientedEdges > 0)
  {
    Index reversed = 0;
    oriented = OrientConsistently(triangles, &reversed);
    changed = changed || reversed > 0;
  }
  if (changed)
  {
    report = AnalyzeMeshTopology(points, triangles);
  }
  if (!report.IsTopologicalSphere())
  {
    mesh.Problem = DescribeProblem(report, oriented, options);
  }
  mesh.Topology = report;
  mesh.Points = std::move(points);
  mesh.Triangles = std::move(triangles);
  return mesh;
}
}
