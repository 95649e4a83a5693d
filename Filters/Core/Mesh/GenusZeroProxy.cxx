#include "GenusZeroProxy.h"

#include "HandleCutting.h"
#include "HoleFilling.h"
#include "ManifoldSplit.h"
#include "MeshEdges.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <numeric>
#include <sstream>

namespace mobius
{
namespace
{
double TriangleArea(const Points& points, Index a, Index b, Index c)
{
  const Eigen::Vector3d pa = points.row(a), pb = points.row(b), pc = points.row(c);
  return 0.5 * (pb - pa).cross(pc - pa).norm();
}

// Keeps the triangles whose `keep` is set; the step's provenance.
MeshProvenance KeepTriangles(Points& points, Triangles& triangles, const std::vector<char>& keep)
{
  MeshProvenance step = IdentityProvenance(points.rows(), 0);
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    if (keep[t])
    {
      step.TriangleSource.push_back(t);
    }
  }
  Triangles kept(static_cast<Index>(step.TriangleSource.size()), 3);
  for (size_t i = 0; i < step.TriangleSource.size(); ++i)
  {
    kept.row(static_cast<Index>(i)) = triangles.row(step.TriangleSource[i]);
  }
  triangles.swap(kept);
  return step;
}

// Triangles with an index out of range, naming a point twice, or touching a point with a
// NaN or infinite coordinate: none has a place on a surface.
void RemoveUnusableTriangles(Points& points, Triangles& triangles, MeshProvenance& provenance, MeshRepairLog& log)
{
  const std::vector<char> valid = ValidTriangles(triangles, points.rows());
  std::vector<char> keep(valid.size(), 0);
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    if (!valid[t])
    {
      ++log.RemovedRepeatedVertexTriangles; // out-of-range ones too: VTK's checks refuse those first
      continue;
    }
    const bool finite = points.row(triangles(t, 0)).allFinite() &&
      points.row(triangles(t, 1)).allFinite() && points.row(triangles(t, 2)).allFinite();
    log.RemovedNonFiniteTriangles += finite ? 0 : 1;
    keep[t] = finite;
  }
  if (std::count(keep.begin(), keep.end(), 0) > 0)
  {
    ComposeProvenance(provenance, KeepTriangles(points, triangles, keep));
  }
}

// Duplicate triangles removed, then every vertex split into its fans.
void MakeManifold(Points& points, Triangles& triangles, MeshProvenance& provenance, MeshRepairLog& log)
{
  Index duplicates = 0;
  const MeshProvenance unique = RemoveDuplicateTriangles(points.rows(), triangles, &duplicates);
  if (duplicates > 0)
  {
    ComposeProvenance(provenance, unique);
    log.RemovedDuplicateTriangles += duplicates;
  }
  const FanSplit split = SplitVertexFans(points, triangles);
  ComposeProvenance(provenance, split.Provenance);
  log.SplitVertices += split.SplitVertices;
}

// Orients the triangles; where no orientation agrees, cuts the surface open along the
// edges that still disagree, and if some still do (disagreeing edges that do not form a
// path to cut along), removes one triangle at each (the hole is filled later).
void Orient(Points& points, Triangles& triangles, MeshProvenance& provenance, MeshRepairLog& log)
{
  std::vector<EdgeKey> disagreeing;
  Index reversed = 0;
  for (int attempt = 0; attempt < 2; ++attempt)
  {
    if (OrientConsistently(triangles, &reversed, &disagreeing))
    {
      log.ReversedTriangles += reversed;
      return;
    }
    log.OrientationCutEdges += static_cast<Index>(disagreeing.size());
    const FanSplit cut = SplitVertexFans(points, triangles, disagreeing);
    ComposeProvenance(provenance, cut.Provenance);
  }
  if (OrientConsistently(triangles, &reversed, &disagreeing))
  {
    log.ReversedTriangles += reversed;
    return;
  }
  std::vector<char> keep(static_cast<size_t>(triangles.rows()), 1);
  for (Index t = triangles.rows() - 1; t >= 0; --t)
  {
    for (int k = 0; k < 3 && keep[t]; ++k)
    {
      const EdgeKey edge = MakeEdgeKey(triangles(t, k), triangles(t, (k + 1) % 3));
      auto found = std::lower_bound(disagreeing.begin(), disagreeing.end(), edge);
      if (found != disagreeing.end() && *found == edge)
      {
        keep[t] = 0;
        disagreeing.erase(found); // the edge's other triangle stays
      }
    }
  }
  ComposeProvenance(provenance, KeepTriangles(points, triangles, keep));
  MakeManifold(points, triangles, provenance, log);
  OrientConsistently(triangles, &reversed, &disagreeing);
  log.ReversedTriangles += reversed;
}

// Per triangle, its edge-connected component (numbered from 0), and each component's area.
std::vector<Index> TriangleComponents(const Points& points, const Triangles& triangles, std::vector<double>& areas)
{
  UnionFind components(points.rows());
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    components.Union(triangles(t, 0), triangles(t, 1));
    components.Union(triangles(t, 0), triangles(t, 2));
  }
  std::vector<Index> number(static_cast<size_t>(points.rows()), -1), component(static_cast<size_t>(triangles.rows()));
  areas.clear();
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    Index& c = number[components.Find(triangles(t, 0))];
    if (c < 0)
    {
      c = static_cast<Index>(areas.size());
      areas.push_back(0.0);
    }
    component[t] = c;
    areas[c] += TriangleArea(points, triangles(t, 0), triangles(t, 1), triangles(t, 2));
  }
  return component;
}

std::string Percent(double part, double whole)
{
  std::ostringstream text;
  text.precision(3);
  text << 100 * part / whole << "%";
  return text.str();
}

// Drops the parts whose area is below kLooseComponentShare of the largest's; a larger part
// besides the largest is a problem unless KeepLargestComponent.
std::string DropLooseComponents(Points& points, Triangles& triangles, MeshProvenance& provenance,
  MeshRepairLog& log, bool keepLargestOnly)
{
  std::vector<double> areas;
  const std::vector<Index> component = TriangleComponents(points, triangles, areas);
  if (areas.size() < 2)
  {
    return {};
  }
  std::vector<Index> bySize(areas.size());
  std::iota(bySize.begin(), bySize.end(), Index(0));
  std::sort(bySize.begin(), bySize.end(), [&](Index a, Index b) { return areas[a] > areas[b]; });
  const Index largest = bySize[0], second = bySize[1];
  if (areas[second] >= kLooseComponentShare * areas[largest] && !keepLargestOnly)
  {
    double total = 0;
    for (double area : areas)
    {
      total += area;
    }
    return std::to_string(areas.size()) + " connected components, two of comparable size (" +
      Percent(areas[largest], total) + " and " + Percent(areas[second], total) +
      " of the area): which one to map is the user's choice. Set KeepLargestComponent to map "
      "only the largest";
  }
  std::vector<char> keep(static_cast<size_t>(triangles.rows()), 0);
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    keep[t] = component[t] == largest;
    log.DroppedComponentTriangles += keep[t] ? 0 : 1;
    log.DroppedComponentArea +=
      keep[t] ? 0.0 : TriangleArea(points, triangles(t, 0), triangles(t, 1), triangles(t, 2));
  }
  log.DroppedComponents += static_cast<Index>(areas.size()) - 1;
  ComposeProvenance(provenance, KeepTriangles(points, triangles, keep));
  ComposeProvenance(provenance, RemoveUnusedPoints(points, triangles));
  return {};
}

HoleFillResult CloseHoles(Points& points, Triangles& triangles, MeshProvenance& provenance)
{
  MeshProvenance step;
  const HoleFillResult filled = FillHoles(points, triangles, &step);
  ComposeProvenance(provenance, step);
  return filled;
}

// Cuts handles along short non-separating loops, closing each cut, until the genus is 0.
std::string CutHandles(Points& points, Triangles& triangles, MeshProvenance& provenance, MeshRepairLog& log)
{
  for (MeshTopologyReport report = AnalyzeMeshTopology(points, triangles); report.Genus > 0;
       report = AnalyzeMeshTopology(points, triangles))
  {
    if (static_cast<int>(log.HandleLoopLengths.size()) >= kMaximumHandleCuts)
    {
      return "genus " + std::to_string(report.Genus + log.HandleLoopLengths.size()) + " (" +
        std::to_string(kMaximumHandleCuts) + " handles cut, " + std::to_string(report.Genus) +
        " more left): more handles than a surface of one object has";
    }
    const SurfaceLoop loop = ShortNonSeparatingLoop(points, triangles);
    if (loop.Vertices.empty())
    {
      return "genus " + std::to_string(report.Genus) + ": no loop to cut the handle along was found";
    }
    std::vector<EdgeKey> cuts;
    for (size_t i = 0; i < loop.Vertices.size(); ++i)
    {
      cuts.push_back(MakeEdgeKey(loop.Vertices[i], loop.Vertices[(i + 1) % loop.Vertices.size()]));
    }
    std::sort(cuts.begin(), cuts.end());
    ComposeProvenance(provenance, SplitVertexFans(points, triangles, cuts).Provenance);
    CloseHoles(points, triangles, provenance); // the cut's two sides
    log.HandleLoopLengths.push_back(loop.Length);
  }
  return {};
}
}

double SurfaceArea(const Points& points, const Triangles& triangles)
{
  const std::vector<char> valid = ValidTriangles(triangles, points.rows());
  double area = 0;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    area += valid[t] ? TriangleArea(points, triangles(t, 0), triangles(t, 1), triangles(t, 2)) : 0.0;
  }
  return area;
}

std::string RepairIntoGenusZeroProxy(Points& points, Triangles& triangles,
  MeshProvenance& provenance, MeshRepairLog& log, const MeshRepairOptions& options)
{
  RemoveUnusableTriangles(points, triangles, provenance, log);
  MakeManifold(points, triangles, provenance, log);
  Orient(points, triangles, provenance, log);
  if (triangles.rows() == 0)
  {
    return "no triangles are left after removing the unusable ones";
  }
  const std::string loose = DropLooseComponents(points, triangles, provenance, log, options.KeepLargestComponent);
  if (!loose.empty())
  {
    return loose;
  }
  ComposeProvenance(provenance, RemoveUnusedPoints(points, triangles));
  const Index usable = triangles.rows();
  const HoleFillResult filled = CloseHoles(points, triangles, provenance);
  log.FilledHoles += filled.Holes;
  log.FilledBoundaryEdges += filled.BoundaryEdges;
  log.FilledArea += filled.Area;
  // A single triangle closed is two on the same points (a "pillow"): nothing encloses a volume
  // with fewer than four.
  if (triangles.rows() < 4)
  {
    return "no closed surface can be made of its " + std::to_string(usable) + " usable triangle" +
      (usable == 1 ? "" : "s") + " (a closed surface needs at least 4)";
  }
  return CutHandles(points, triangles, provenance, log);
}
}
