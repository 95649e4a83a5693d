// Topology analysis and repairs on generated meshes whose answers are known by construction.
#include "CoreTest.h"
#include "HoleFilling.h"
#include "Icosphere.h"
#include "MeshTopology.h"
#include "RepairMesh.h"
#include "Torus.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace mobius;

namespace
{

Triangles WithoutRows(const Triangles& triangles, const std::vector<Index>& drop)
{
  Triangles kept(triangles.rows() - static_cast<Index>(drop.size()), 3);
  Index k = 0;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    if (std::find(drop.begin(), drop.end(), t) == drop.end())
    {
      kept.row(k++) = triangles.row(t);
    }
  }
  return kept;
}

void TestSphereAndTorus()
{
  Points p;
  Triangles t;
  MakeIcosphere(2, p, t);
  const MeshTopologyReport sphere = AnalyzeMeshTopology(p, t);
  MOBIUS_CHECK(sphere.IsTopologicalSphere());
  MOBIUS_CHECK(sphere.EulerCharacteristic == 2);
  MOBIUS_CHECK(sphere.Genus == 0);
  MOBIUS_CHECK(sphere.Edges == 3 * t.rows() / 2);
  MOBIUS_CHECK(DescribeTopologyProblems(sphere).empty());

  MakeTorus(12, 8, 2.0, 0.5, p, t);
  const MeshTopologyReport torus = AnalyzeMeshTopology(p, t);
  MOBIUS_CHECK(torus.IsClosedManifold());
  MOBIUS_CHECK(torus.EulerCharacteristic == 0);
  MOBIUS_CHECK(torus.Genus == 1);
  MOBIUS_CHECK(!torus.IsTopologicalSphere());
  MOBIUS_CHECK(DescribeTopologyProblems(torus).find("genus 1") != std::string::npos);
}

void TestHolesAndFilling()
{
  Points p;
  Triangles t;
  MakeIcosphere(2, p, t);
  // Two triangles far apart: two holes of three edges each.
  Index far = -1;
  for (Index s = 0; s < t.rows() && far < 0; ++s)
  {
    if (p.row(t(s, 0)).dot(p.row(t(0, 0))) < -0.9)
    {
      far = s;
    }
  }
  Triangles holed = WithoutRows(t, { 0, far });
  MeshTopologyReport r = AnalyzeMeshTopology(p, holed);
  MOBIUS_CHECK(r.BoundaryLoops == 2);
  MOBIUS_CHECK(r.BoundaryEdges == 6);
  MOBIUS_CHECK(r.Genus == -1);
  MOBIUS_CHECK(DescribeTopologyProblems(r).find("2 boundary loops") != std::string::npos);
  MeshProvenance provenance;
  MOBIUS_CHECK(FillHoles(p, holed, &provenance).Holes == 2);
  MOBIUS_CHECK(holed.rows() == t.rows()); // three-edge loops get one triangle, no new point
  MOBIUS_CHECK(AnalyzeMeshTopology(p, holed).IsTopologicalSphere());

  // Remove the fan of vertex 0 (degree 5 on an icosphere): one loop of five edges.
  MakeIcosphere(2, p, t);
  std::vector<Index> fan;
  for (Index s = 0; s < t.rows(); ++s)
  {
    if (t(s, 0) == 0 || t(s, 1) == 0 || t(s, 2) == 0)
    {
      fan.push_back(s);
    }
  }
  MOBIUS_CHECK(fan.size() == 5);
  holed = WithoutRows(t, fan);
  r = AnalyzeMeshTopology(p, holed);
  MOBIUS_CHECK(r.BoundaryLoops == 1);
  MOBIUS_CHECK(r.BoundaryEdges == 5);
  MOBIUS_CHECK(r.UnusedPoints == 1);
  const Index pointsBefore = p.rows();
  MOBIUS_CHECK(FillHoles(p, holed, &provenance).Holes == 1);
  MOBIUS_CHECK(p.rows() == pointsBefore + 1); // the fan's center
  MOBIUS_CHECK(provenance.PointSource.back() == -1);
  MOBIUS_CHECK(provenance.TriangleSource.back() == -1);
  r = AnalyzeMeshTopology(p, holed);
  MOBIUS_CHECK(r.IsClosedManifold() && r.InconsistentlyOrientedEdges == 0);
  ExtractLargestComponent(p, holed); // drops the now unused vertex 0
  MOBIUS_CHECK(AnalyzeMeshTopology(p, holed).IsTopologicalSphere());
}

void TestSoup()
{
  Points p;
  Triangles t;
  MakeIcosphere(1, p, t);
  const Index originalPoints = p.rows();
  // Every triangle with its own three points, plus one triangle that becomes degenerate.
  Points soup(3 * t.rows() + 3, 3);
  Triangles soupTriangles(t.rows() + 1, 3);
  for (Index s = 0; s < t.rows(); ++s)
  {
    for (int k = 0; k < 3; ++k)
    {
      soup.row(3 * s + k) = p.row(t(s, k));
      soupTriangles(s, k) = 3 * s + k;
    }
  }
  const Index last = 3 * t.rows();
  soup.row(last) = p.row(0);
  soup.row(last + 1) = p.row(1);
  soup.row(last + 2) = p.row(0);
  soupTriangles.row(t.rows()) << last, last + 1, last + 2;
  MeshTopologyReport r = AnalyzeMeshTopology(soup, soupTriangles);
  MOBIUS_CHECK(r.BoundaryEdges > 0);
  MOBIUS_CHECK(r.DuplicatePoints == soup.rows() - originalPoints);
  MOBIUS_CHECK(DescribeTopologyProblems(r).find("duplicates") != std::string::npos);
  const MeshProvenance provenance = MergeDuplicatePoints(soup, soupTriangles);
  MOBIUS_CHECK(soup.rows() == originalPoints);
  MOBIUS_CHECK(soupTriangles.rows() == t.rows()); // the degenerate one was dropped
  MOBIUS_CHECK(provenance.TriangleSource.back() == t.rows() - 1);
  r = AnalyzeMeshTopology(soup, soupTriangles);
  MOBIUS_CHECK(r.IsTopologicalSphere());
  MOBIUS_CHECK(r.DuplicatePoints == 0);
}

void TestNonManifold()
{
  Points p;
  Triangles t;
  MakeIcosphere(1, p, t);
  // A fin on edge (t(0,0), t(0,1)): three triangles on that edge.
  Points fin(p.rows() + 1, 3);
  fin << p, Eigen::RowVector3d(3, 3, 3);
  Triangles finTriangles(t.rows() + 1, 3);
  finTriangles << t, Eigen::Matrix<Index, 1, 3>(t(0, 0), t(0, 1), p.rows());
  MeshTopologyReport r = AnalyzeMeshTopology(fin, finTriangles);
  MOBIUS_CHECK(r.NonManifoldEdges == 1);
  MOBIUS_CHECK(r.BoundaryEdges == 2);
  MOBIUS_CHECK(!OrientConsistently(finTriangles));

  // Two tetrahedra touching at one vertex: manifold edges, one non-manifold vertex.
  Points bow(7, 3);
  bow << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, -1, 0, 0, 0, -1;
  Triangles bowTriangles(8, 3);
  bowTriangles << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 0, 4, 5, 0, 6, 4, 0, 5, 6, 4, 6, 5;
  r = AnalyzeMeshTopology(bow, bowTriangles);
  MOBIUS_CHECK(r.NonManifoldEdges == 0);
  MOBIUS_CHECK(r.NonManifoldVertices == 1);
  MOBIUS_CHECK(r.ConnectedComponents == 1);
  MOBIUS_CHECK(!r.IsTopologicalSphere());
}

void TestComponentsAndOrientation()
{
  Points small, large;
  Triangles smallT, largeT;
  MakeIcosphere(1, small, smallT);
  MakeIcosphere(2, large, largeT);
  Points both(small.rows() + large.rows(), 3);
  both << small, (large.array() + 5.0).matrix();
  Triangles bothT(smallT.rows() + largeT.rows(), 3);
  bothT << smallT, (largeT.array() + small.rows()).matrix();
  MOBIUS_CHECK(AnalyzeMeshTopology(both, bothT).ConnectedComponents == 2);
  const MeshProvenance provenance = ExtractLargestComponent(both, bothT);
  MOBIUS_CHECK(both.rows() == large.rows());
  MOBIUS_CHECK(bothT.rows() == largeT.rows());
  MOBIUS_CHECK(provenance.PointSource[0] == small.rows()); // first point of the large sphere
  MOBIUS_CHECK_NEAR(both(0, 0), large(0, 0) + 5.0, 0.0);
  MOBIUS_CHECK(AnalyzeMeshTopology(both, bothT).IsTopologicalSphere());

  // Reverse three triangles: their edges disagree with the neighbours; orienting fixes it.
  Triangles t = largeT;
  for (Index s : { 3, 17, 40 })
  {
    std::swap(t(s, 1), t(s, 2));
  }
  MOBIUS_CHECK(AnalyzeMeshTopology(large, t).InconsistentlyOrientedEdges == 9);
  Index reversed = -1;
  MOBIUS_CHECK(OrientConsistently(t, &reversed));
  MOBIUS_CHECK(reversed == 3);
  MOBIUS_CHECK(t == largeT);

  // A Moebius strip cannot be oriented.
  const int n = 9;
  const double pi = std::acos(-1.0);
  Points strip(2 * n, 3);
  for (int i = 0; i < n; ++i)
  {
    const double u = 2 * pi * i / n;
    for (int s = 0; s < 2; ++s)
    {
      const double w = s == 0 ? -0.3 : 0.3;
      strip.row(2 * i + s) << (1 + w * std::cos(u / 2)) * std::cos(u),
        (1 + w * std::cos(u / 2)) * std::sin(u), w * std::sin(u / 2);
    }
  }
  Triangles stripT(2 * n, 3);
  for (int i = 0; i < n; ++i)
  {
    const Index a = 2 * i, b = 2 * i + 1;
    // The last quad connects with a half twist: bottom of i meets top of 0.
    const Index c = i + 1 < n ? 2 * (i + 1) : 1, d = i + 1 < n ? 2 * (i + 1) + 1 : 0;
    stripT.row(2 * i) << a, c, b;
    stripT.row(2 * i + 1) << b, c, d;
  }
  const Triangles before = stripT;
  MOBIUS_CHECK(!OrientConsistently(stripT));
  MOBIUS_CHECK(stripT == before);
  // Its one boundary curve has 2n edges (it goes around twice).
  MOBIUS_CHECK(AnalyzeMeshTopology(strip, stripT).BoundaryEdges == 2 * n);
}

void TestBadValues()
{
  Points p;
  Triangles t;
  MakeIcosphere(1, p, t);
  p(4, 1) = std::numeric_limits<double>::quiet_NaN();
  MeshTopologyReport r = AnalyzeMeshTopology(p, t);
  MOBIUS_CHECK(r.NonFinitePoints == 1);
  MOBIUS_CHECK(!r.IsTopologicalSphere());
  MOBIUS_CHECK(DescribeTopologyProblems(r).find("NaN") != std::string::npos);

  MakeIcosphere(1, p, t);
  t(5, 2) = p.rows(); // out of range
  t(6, 2) = t(6, 0);  // repeated point
  r = AnalyzeMeshTopology(p, t);
  MOBIUS_CHECK(r.InvalidTriangles == 1);
  MOBIUS_CHECK(r.RepeatedVertexTriangles == 1);

  // Collinear points: no area.
  Points line(3, 3);
  line << 0, 0, 0, 1, 0, 0, 2, 0, 0;
  Triangles one(1, 3);
  one << 0, 1, 2;
  r = AnalyzeMeshTopology(line, one);
  MOBIUS_CHECK(r.ZeroAreaTriangles == 1);
  MOBIUS_CHECK(r.BoundaryLoops == 1);
}
}

// A face listed again, either way round, is a duplicate (and its edges non-manifold); so is
// the two-triangle "pillow" FillHoles makes of a single triangle.
void TestDuplicateTriangles()
{
  Points p;
  Triangles t;
  MakeIcosphere(1, p, t);
  MOBIUS_CHECK(AnalyzeMeshTopology(p, t).DuplicateTriangles == 0);
  for (const bool reversed : { false, true })
  {
    Triangles doubled(t.rows() + 1, 3);
    doubled.topRows(t.rows()) = t;
    doubled.row(t.rows()) << t(4, 0), t(4, reversed ? 2 : 1), t(4, reversed ? 1 : 2);
    const MeshTopologyReport r = AnalyzeMeshTopology(p, doubled);
    MOBIUS_CHECK(r.DuplicateTriangles == 1 && r.NonManifoldEdges == 3);
    MOBIUS_CHECK(!r.IsTopologicalSphere());
    MOBIUS_CHECK(DescribeTopologyProblems(r).find("1 duplicate triangle") != std::string::npos);
  }
  Points corners(3, 3);
  corners << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  Triangles single(1, 3);
  single << 0, 1, 2;
  MOBIUS_CHECK(FillHoles(corners, single).Holes == 1);
  const MeshTopologyReport pillow = AnalyzeMeshTopology(corners, single);
  MOBIUS_CHECK(pillow.IsClosedManifold() && pillow.DuplicateTriangles == 1);
  MOBIUS_CHECK(!pillow.IsTopologicalSphere());
}

// A vertex of high degree (its edges and triangles are sorted in long runs, not the few of
// an ordinary vertex): two cones of 50 triangles sharing their apex, each closed by a cap
// around its own centre. Manifold edges, one non-manifold vertex; one cone alone is a sphere.
void TestHubVertex()
{
  const int sides = 50;
  Points p(1 + 2 * (sides + 1), 3);
  std::vector<Eigen::Matrix<Index, 1, 3>> faces;
  p.row(0) << 0, 0, 0;
  for (int cone = 0; cone < 2; ++cone)
  {
    const Index rim = 1 + cone * (sides + 1), cap = rim + sides;
    const double z = cone == 0 ? 1.0 : -1.0;
    for (int i = 0; i < sides; ++i)
    {
      const double angle = 2.0 * M_PI * i / sides;
      p.row(rim + i) << std::cos(angle), std::sin(angle), z;
    }
    p.row(cap) << 0, 0, 2 * z;
    for (Index i = 0; i < sides; ++i)
    {
      const Index a = rim + i, b = rim + (i + 1) % sides;
      faces.push_back(cone == 0 ? Eigen::Matrix<Index, 1, 3>(0, b, a) : Eigen::Matrix<Index, 1, 3>(0, a, b));
      faces.push_back(cone == 0 ? Eigen::Matrix<Index, 1, 3>(cap, a, b) : Eigen::Matrix<Index, 1, 3>(cap, b, a));
    }
  }
  Triangles both(static_cast<Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f)
  {
    both.row(static_cast<Index>(f)) = faces[f];
  }
  MeshTopologyReport r = AnalyzeMeshTopology(p, both);
  MOBIUS_CHECK(r.Edges == 2 * 3 * sides);
  MOBIUS_CHECK(r.BoundaryEdges == 0 && r.NonManifoldEdges == 0);
  MOBIUS_CHECK(r.InconsistentlyOrientedEdges == 0);
  MOBIUS_CHECK(r.NonManifoldVertices == 1);
  MOBIUS_CHECK(r.DuplicateTriangles == 0 && r.ConnectedComponents == 1);

  Triangles one = both.topRows(2 * sides);
  Points onePoints = p.topRows(sides + 2);
  r = AnalyzeMeshTopology(onePoints, one);
  MOBIUS_CHECK(r.IsTopologicalSphere() && r.Edges == 3 * sides);
  // Reversing every other apex triangle leaves 2 * sides disagreeing edges; re-orienting
  // must restore all of them.
  for (Index f = 0; f < 2 * sides; f += 4)
  {
    std::swap(one(f, 1), one(f, 2));
  }
  r = AnalyzeMeshTopology(onePoints, one);
  MOBIUS_CHECK(r.InconsistentlyOrientedEdges > 0);
  Index reversed = 0;
  MOBIUS_CHECK(OrientConsistently(one, &reversed) && reversed > 0);
  MOBIUS_CHECK(AnalyzeMeshTopology(onePoints, one).IsTopologicalSphere());
  // Point numbers far beyond the mesh's size (OrientConsistently sees no point count):
  // sorted without a bucket per number, to the same result.
  Triangles dense = one;
  for (Index f = 0; f < 2 * sides; f += 4)
  {
    std::swap(dense(f, 1), dense(f, 2));
  }
  const Index offset = Index(1) << 40;
  Triangles sparse = dense;
  sparse.array() += offset;
  MOBIUS_CHECK(OrientConsistently(dense) && OrientConsistently(sparse, &reversed));
  MOBIUS_CHECK(reversed == 2 * sides - (2 * sides + 3) / 4);
  MOBIUS_CHECK(((sparse.array() - offset).matrix() - dense).cwiseAbs().maxCoeff() == 0);
  MOBIUS_CHECK(AnalyzeMeshTopology(onePoints, dense).IsTopologicalSphere());
  // The same mesh listed twice in a row: every triangle a duplicate.
  Triangles twice(2 * one.rows(), 3);
  twice << one, one;
  r = AnalyzeMeshTopology(onePoints, twice);
  MOBIUS_CHECK(r.DuplicateTriangles == one.rows() && r.NonManifoldEdges == 3 * sides);
}

// The whole repair chain on an icosphere with two holes, a second component and an unused
// point: with both options it comes out a topological sphere whose provenance names the
// input rows; without them the problem names the options. Then a triangle soup with half
// its triangles reversed: merged and oriented.
void TestRepairMesh()
{
  Points p;
  Triangles t;
  MakeIcosphere(1, p, t);
  const Index spherePoints = p.rows();
  // Two one-triangle holes that share no point: triangle 0 and the first one apart from it.
  Index apart = 1;
  while ((t.row(apart).array() == t(0, 0) || t.row(apart).array() == t(0, 1) ||
           t.row(apart).array() == t(0, 2)).any())
  {
    ++apart;
  }
  const Triangles damaged = WithoutRows(t, { 0, apart });
  Points extended(spherePoints + 4, 3);
  extended.topRows(spherePoints) = p;
  extended.row(spherePoints) << 5, 5, 5;     // unused
  extended.row(spherePoints + 1) << 6, 5, 5; // a lone triangle: a second component
  extended.row(spherePoints + 2) << 5, 6, 5;
  extended.row(spherePoints + 3) << 5, 5, 6;
  Triangles withComponent(damaged.rows() + 1, 3);
  withComponent.topRows(damaged.rows()) = damaged;
  withComponent.row(damaged.rows()) << spherePoints + 1, spherePoints + 2, spherePoints + 3;

  const RepairedMesh refused = RepairMesh(extended, withComponent, { false, false, false });
  MOBIUS_CHECK(refused.Problem.find("Set FillHoles") != std::string::npos);
  MOBIUS_CHECK(refused.Problem.find("Set KeepLargestComponent") != std::string::npos);

  const RepairedMesh mesh = RepairMesh(extended, withComponent, { false, true, true });
  MOBIUS_CHECK(mesh.Problem.empty());
  MOBIUS_CHECK(mesh.Topology.IsTopologicalSphere());
  MOBIUS_CHECK(mesh.Log.FilledHoles == 2);
  MOBIUS_CHECK(mesh.Log.MergedDuplicatePoints == 0);
  MOBIUS_CHECK(mesh.Points.rows() == spherePoints);
  MOBIUS_CHECK(mesh.Triangles.rows() == t.rows());
  MOBIUS_CHECK(static_cast<Index>(mesh.Provenance.PointSource.size()) == mesh.Points.rows());
  for (Index i = 0; i < mesh.Points.rows(); ++i)
  {
    const Index source = mesh.Provenance.PointSource[i];
    MOBIUS_CHECK(source >= 0 && source < spherePoints);
    MOBIUS_CHECK(mesh.Points.row(i) == extended.row(source));
  }
  // A kept triangle names the points of its input row (in either orientation); the fills
  // are new.
  Index created = 0;
  for (Index f = 0; f < mesh.Triangles.rows(); ++f)
  {
    const Index source = mesh.Provenance.TriangleSource[f];
    if (source < 0)
    {
      ++created;
      continue;
    }
    std::vector<Index> repaired, original;
    for (int k = 0; k < 3; ++k)
    {
      repaired.push_back(mesh.Provenance.PointSource[mesh.Triangles(f, k)]);
      original.push_back(withComponent(source, k));
    }
    std::sort(repaired.begin(), repaired.end());
    std::sort(original.begin(), original.end());
    MOBIUS_CHECK(repaired == original);
  }
  MOBIUS_CHECK(created == 2);

  Points soup(3 * t.rows(), 3);
  Triangles soupTriangles(t.rows(), 3);
  for (Index f = 0; f < t.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      soup.row(3 * f + k) = p.row(t(f, k));
      soupTriangles(f, k) = 3 * f + k;
    }
    if (f % 2 == 1)
    {
      std::swap(soupTriangles(f, 1), soupTriangles(f, 2));
    }
  }
  const RepairedMesh merged = RepairMesh(soup, soupTriangles, { false, false, false });
  MOBIUS_CHECK(merged.Problem.empty());
  MOBIUS_CHECK(merged.Log.MergedDuplicatePoints == soup.rows() - spherePoints);
  MOBIUS_CHECK(merged.Points.rows() == spherePoints);
  MOBIUS_CHECK(merged.Topology.IsTopologicalSphere());
  MOBIUS_CHECK(merged.Topology.InconsistentlyOrientedEdges == 0);
}

// Triangles without area are geometry, not topology: a sliver closing a T-junction is kept;
// a triangle with two corners at one position loses its zero-length edge (the two points
// merged, the two triangles on the edge dropped), which gives back the mesh it came from.
void TestZeroAreaRepairs()
{
  Points p;
  Triangles t;
  MakeIcosphere(1, p, t);
  const Index a = t(0, 0), m = p.rows();
  Points sliver;
  Triangles split;
  InsertSliver(p, t, (p.row(a) + p.row(t(0, 1))) / 2, sliver, split);
  const RepairedMesh kept = RepairMesh(sliver, split, { false, false, false });
  MOBIUS_CHECK(kept.Problem.empty());
  MOBIUS_CHECK(kept.Topology.ZeroAreaTriangles == 1);
  MOBIUS_CHECK(kept.Log.CollapsedEdges == 0);
  MOBIUS_CHECK(kept.Points.rows() == m + 1 && kept.Triangles.rows() == split.rows());

  Points coincident = sliver;
  coincident.row(m) = p.row(a);
  const RepairedMesh collapsed = RepairMesh(coincident, split, { false, false, false });
  MOBIUS_CHECK(collapsed.Problem.empty());
  MOBIUS_CHECK(collapsed.Log.CollapsedEdges == 1);
  MOBIUS_CHECK(collapsed.Topology.IsTopologicalSphere());
  MOBIUS_CHECK(collapsed.Topology.ZeroAreaTriangles == 0);
  MOBIUS_CHECK(collapsed.Points.rows() == m && collapsed.Triangles.rows() == t.rows());
  for (Index i = 0; i < collapsed.Points.rows(); ++i)
  {
    MOBIUS_CHECK(collapsed.Provenance.PointSource[i] == i); // m, merged into a, is gone
  }

  // Nothing but zero-area triangles: no surface to map.
  Points line(4, 3);
  line << 0, 0, 0, 1, 2, 3, 2, 4, 6, 3, 6, 9;
  Triangles tetrahedron(4, 3);
  tetrahedron << 0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2;
  const RepairedMesh flat = RepairMesh(line, tetrahedron, { false, false, false });
  MOBIUS_CHECK(flat.Problem.find("every triangle has zero area") != std::string::npos);
}

int main()
{
  TestSphereAndTorus();
  TestHolesAndFilling();
  TestSoup();
  TestNonManifold();
  TestComponentsAndOrientation();
  TestBadValues();
  TestDuplicateTriangles();
  TestHubVertex();
  TestRepairMesh();
  TestZeroAreaRepairs();
  return MOBIUS_TEST_RESULT();
}
