// RepairMesh's Repair mode on generated meshes whose defects and answers are known by
// construction: each comes out a topological sphere, with the repair logged and sized, and
// every proxy point that came from the input still where it was.
#include "CoreTest.h"
#include "Icosphere.h"
#include "RepairMesh.h"
#include "Torus.h"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace mobius;

namespace
{
constexpr double kPi = 3.14159265358979323846;
const MeshRepairOptions kRepair{ true, false, false };

Triangles Appended(const Triangles& triangles, std::initializer_list<std::array<Index, 3>> rows)
{
  Triangles more(triangles.rows() + static_cast<Index>(rows.size()), 3);
  more.topRows(triangles.rows()) = triangles;
  Index r = triangles.rows();
  for (const auto& row : rows)
  {
    more.row(r++) << row[0], row[1], row[2];
  }
  return more;
}

bool Mentions(const RepairedMesh& mesh, const std::string& phrase)
{
  for (const std::string& repair : mesh.Log.Describe())
  {
    if (repair.find(phrase) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

// A sphere, and every proxy point that came from the input at its input position.
void CheckProxy(const RepairedMesh& mesh, const Points& input, const char* what)
{
  if (!mesh.Problem.empty() || !mesh.Topology.IsTopologicalSphere())
  {
    std::cerr << what << ": not repaired: " << mesh.Problem << "\n";
  }
  MOBIUS_CHECK(mesh.Problem.empty());
  MOBIUS_CHECK(mesh.Topology.IsTopologicalSphere());
  MOBIUS_CHECK(static_cast<Index>(mesh.Provenance.PointSource.size()) == mesh.Points.rows());
  MOBIUS_CHECK(static_cast<Index>(mesh.Provenance.TriangleSource.size()) == mesh.Triangles.rows());
  for (Index i = 0; i < mesh.Points.rows(); ++i)
  {
    const Index source = mesh.Provenance.PointSource[i];
    MOBIUS_CHECK(source < input.rows());
    if (source >= 0 && !(mesh.Points.row(i) == input.row(source)))
    {
      std::cerr << what << ": proxy point " << i << " is not at its input point " << source << "\n";
      ++mobius_test::Failures();
      return;
    }
  }
}

// A clean sphere is left exactly as it is.
void TestCleanMeshUntouched()
{
  Points p;
  Triangles t;
  MakeIcosphere(3, p, t);
  const RepairedMesh mesh = RepairMesh(p, t, kRepair);
  MOBIUS_CHECK(mesh.Problem.empty() && !mesh.Log.Any() && mesh.Log.Describe().empty());
  MOBIUS_CHECK(mesh.Points == p && mesh.Triangles == t);
}

// One face listed twice (either way round): the copy is removed, nothing else changes; in
// strict mode the mesh is refused as before.
void TestDuplicateTriangle()
{
  Points p;
  Triangles t;
  MakeIcosphere(2, p, t);
  for (const bool reversed : { false, true })
  {
    const Triangles doubled = Appended(t, { { t(4, 0), t(4, reversed ? 2 : 1), t(4, reversed ? 1 : 2) } });
    const RepairedMesh mesh = RepairMesh(p, doubled, kRepair);
    CheckProxy(mesh, p, "duplicate triangle");
    MOBIUS_CHECK(mesh.Log.RemovedDuplicateTriangles == 1 && mesh.Triangles.rows() == t.rows());
    MOBIUS_CHECK(mesh.Points.rows() == p.rows() && mesh.Log.SplitVertices == 0);
    MOBIUS_CHECK(Mentions(mesh, "1 duplicate triangle removed"));
    const RepairedMesh strict = RepairMesh(p, doubled, { false, true, true });
    MOBIUS_CHECK(strict.Problem.find("1 duplicate triangle") != std::string::npos);
  }
}

// A fin: a triangle hanging off an edge of the sphere (three triangles on one edge). Its two
// corners on the edge are split off, and the fin, a loose part, is dropped.
void TestFin()
{
  Points p;
  Triangles t;
  MakeIcosphere(2, p, t);
  Points withTip(p.rows() + 1, 3);
  withTip.topRows(p.rows()) = p;
  withTip.row(p.rows()) = 1.5 * (p.row(t(0, 0)) + p.row(t(0, 1))) / 2;
  const RepairedMesh mesh = RepairMesh(withTip, Appended(t, { { t(0, 1), t(0, 0), p.rows() } }), kRepair);
  CheckProxy(mesh, withTip, "fin");
  MOBIUS_CHECK(mesh.Log.SplitVertices == 2 && mesh.Log.DroppedComponents == 1);
  MOBIUS_CHECK(mesh.Triangles.rows() == t.rows() && mesh.Points.rows() == p.rows());
  MOBIUS_CHECK(Mentions(mesh, "1 loose part dropped (1 triangle"));
}

// Two spheres of one size touching at a vertex: split there, they are two parts of
// comparable size, refused unless the largest is asked for; a small sphere touching a large
// one is a loose part, dropped.
void TestTouchingSpheres()
{
  Points p;
  Triangles t;
  MakeIcosphere(2, p, t);
  for (const double scale : { 1.0, 0.2 })
  {
    // The second sphere's vertex 0 is the first one's.
    const Eigen::RowVector3d offset = (1 + scale) * p.row(0);
    Points both(2 * p.rows() - 1, 3);
    both.topRows(p.rows()) = p;
    for (Index i = 1; i < p.rows(); ++i)
    {
      both.row(p.rows() + i - 1) = offset - scale * p.row(i);
    }
    Triangles bothT(2 * t.rows(), 3);
    bothT.topRows(t.rows()) = t;
    for (Index f = 0; f < t.rows(); ++f)
    {
      for (int k = 0; k < 3; ++k)
      {
        bothT(t.rows() + f, k) = t(f, k) == 0 ? 0 : t(f, k) + p.rows() - 1;
      }
    }
    const RepairedMesh mesh = RepairMesh(both, bothT, kRepair);
    if (scale == 1.0)
    {
      MOBIUS_CHECK(mesh.Problem.find("comparable size") != std::string::npos);
      MOBIUS_CHECK(mesh.Problem.find("KeepLargestComponent") != std::string::npos);
      CheckProxy(RepairMesh(both, bothT, { true, false, true }), both, "touching spheres, largest");
    }
    else
    {
      CheckProxy(mesh, both, "touching small sphere");
      MOBIUS_CHECK(mesh.Log.SplitVertices == 1 && mesh.Log.DroppedComponents == 1);
      MOBIUS_CHECK(mesh.Triangles.rows() == t.rows());
    }
  }
}

// The triangles around a vertex reversed: turned back.
void TestFlippedPatch()
{
  Points p;
  Triangles t;
  MakeIcosphere(2, p, t);
  Index flipped = 0;
  for (Index f = 0; f < t.rows(); ++f)
  {
    if ((t.row(f).array() == 5).any())
    {
      std::swap(t(f, 1), t(f, 2));
      ++flipped;
    }
  }
  const RepairedMesh mesh = RepairMesh(p, t, kRepair);
  CheckProxy(mesh, p, "flipped patch");
  MOBIUS_CHECK(mesh.Log.ReversedTriangles == flipped || mesh.Log.ReversedTriangles == t.rows() - flipped);
}

// A cap of the unit sphere cut away (30 degrees around +z): the patch follows the sphere,
// faces the same way as the rest and has the rim's spacing.
void TestFilledCap()
{
  Points p;
  Triangles t;
  MakeIcosphere(4, p, t);
  std::vector<std::array<Index, 3>> kept;
  for (Index f = 0; f < t.rows(); ++f)
  {
    const Eigen::Vector3d centre = (p.row(t(f, 0)) + p.row(t(f, 1)) + p.row(t(f, 2))).transpose() / 3;
    if (centre.normalized().z() < std::cos(30 * kPi / 180))
    {
      kept.push_back({ t(f, 0), t(f, 1), t(f, 2) });
    }
  }
  Triangles holed(static_cast<Index>(kept.size()), 3);
  for (size_t f = 0; f < kept.size(); ++f)
  {
    holed.row(static_cast<Index>(f)) << kept[f][0], kept[f][1], kept[f][2];
  }
  const RepairedMesh mesh = RepairMesh(p, holed, kRepair);
  CheckProxy(mesh, p, "cap");
  MOBIUS_CHECK(mesh.Log.FilledHoles == 1 && mesh.Log.FilledBoundaryEdges > 30);
  // The cap's true area is 2 pi (1 - cos 30 deg) = 0.842 of the unit sphere's 12.57.
  const double share = mesh.Log.FilledArea / mesh.Log.ProxyArea;
  double worst = 0;
  Index created = 0, outward = 0, patch = 0;
  for (Index i = 0; i < mesh.Points.rows(); ++i)
  {
    if (mesh.Provenance.PointSource[i] < 0)
    {
      worst = std::max(worst, std::abs(mesh.Points.row(i).norm() - 1));
      ++created;
    }
  }
  std::cout << "cap: " << created << " new points, area share " << share;
  for (Index f = 0; f < mesh.Triangles.rows(); ++f)
  {
    if (mesh.Provenance.TriangleSource[f] < 0)
    {
      const Eigen::Vector3d a = mesh.Points.row(mesh.Triangles(f, 0)), b = mesh.Points.row(mesh.Triangles(f, 1)),
                            c = mesh.Points.row(mesh.Triangles(f, 2));
      outward += (b - a).cross(c - a).dot(a + b + c) > 0 ? 1 : 0;
      ++patch;
    }
  }
  std::cout << ", largest distance from the sphere " << worst << ", " << outward << " of "
            << patch << " patch triangles facing out\n";
  MOBIUS_CHECK(std::abs(share - 0.842 / (4 * kPi)) < 0.01);
  // Measured 0.042 (the patch is a little flatter than the sphere; a flat disc would be 0.13
  // away at its middle): the rim rows make it leave the surface along its tangent.
  MOBIUS_CHECK(worst < 0.06);
  MOBIUS_CHECK(outward == patch);
}

// A torus: one handle, cut around the tube (length 2 pi 0.5), not along it (2 pi 1.5).
void TestTorusHandle()
{
  Points p;
  Triangles t;
  MakeTorus(48, 24, 2.0, 0.5, p, t);
  const RepairedMesh mesh = RepairMesh(p, t, kRepair);
  CheckProxy(mesh, p, "torus");
  MOBIUS_CHECK(mesh.Log.HandleLoopLengths.size() == 1 && mesh.Log.FilledHoles == 0);
  const double length = mesh.Log.HandleLoopLengths.empty() ? 0 : mesh.Log.HandleLoopLengths[0];
  std::cout << "torus: handle loop length " << length << " (the tube's circumference " << kPi << ")\n";
  MOBIUS_CHECK(length > 0.95 * kPi && length < 1.1 * kPi);
  MOBIUS_CHECK(Mentions(mesh, "1 handle cut (loop length "));
}

// A point with a NaN coordinate: its triangles are removed and the hole filled.
void TestNonFinitePoint()
{
  Points p;
  Triangles t;
  MakeIcosphere(2, p, t);
  p(7, 1) = std::numeric_limits<double>::quiet_NaN();
  const RepairedMesh mesh = RepairMesh(p, t, kRepair);
  CheckProxy(mesh, p, "NaN point");
  MOBIUS_CHECK(mesh.Log.RemovedNonFiniteTriangles >= 5 && mesh.Log.FilledHoles == 1);
  MOBIUS_CHECK(mesh.Points.allFinite());
}

// A Moebius band: no orientation agrees; cut open and filled, it is a sphere.
void TestMoebiusBand()
{
  const int around = 40;
  Points p(2 * around, 3);
  for (int i = 0; i < around; ++i)
  {
    const double u = 2 * kPi * i / around;
    for (int side = 0; side < 2; ++side)
    {
      const double v = side == 0 ? -0.3 : 0.3;
      p.row(2 * i + side) << (1 + v * std::cos(u / 2)) * std::cos(u), (1 + v * std::cos(u / 2)) * std::sin(u),
        v * std::sin(u / 2);
    }
  }
  Triangles t(2 * around, 3);
  for (int i = 0; i < around; ++i)
  {
    const bool last = i == around - 1; // the band closes with its sides swapped
    const Index a = 2 * i, b = 2 * i + 1, c = last ? 1 : 2 * i + 2, d = last ? 0 : 2 * i + 3;
    t.row(2 * i) << a, c, b;
    t.row(2 * i + 1) << b, c, d;
  }
  const RepairedMesh mesh = RepairMesh(p, t, kRepair);
  CheckProxy(mesh, p, "Moebius band");
  MOBIUS_CHECK(mesh.Log.OrientationCutEdges > 0 && mesh.Log.FilledHoles >= 1);
}
}

int main()
{
  TestCleanMeshUntouched();
  TestDuplicateTriangle();
  TestFin();
  TestTouchingSpheres();
  TestFlippedPatch();
  TestFilledCap();
  TestTorusHandle();
  TestNonFinitePoint();
  TestMoebiusBand();
  return mobius_test::Failures() == 0 ? 0 : 1;
}
