// Unit tests of the spherical point locator: every located triangle really holds the query,
// on uniform, Möbius-distorted and extremely squeezed maps, at vertices, edges, poles and the
// seam; holes give the nearest triangle, flagged as clamped; bad input gives clear errors.
#include "CoreTest.h"
#include "Icosphere.h"
#include "MobiusCentering.h"
#include "SphericalPointLocator.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace mobius;

namespace
{
Eigen::Vector3d Vertex(const Points& points, Index i)
{
  return points.row(i).transpose();
}

// A map that squeezes the neighbourhood of `axis` the way a conformal map squeezes a limb:
// polar angle theta -> pi (theta / pi)^power. Orientation-preserving, so the result is still a
// valid spherical map, with triangle sizes spanning many orders of magnitude.
void SqueezeAround(Eigen::Vector3d axis, double power, Points& points)
{
  axis.normalize();
  for (Index i = 0; i < points.rows(); ++i)
  {
    const Eigen::Vector3d x = Vertex(points, i);
    const Eigen::Vector3d side = x - x.dot(axis) * axis;
    if (side.norm() == 0.0)
    {
      continue;
    }
    const double theta = std::atan2(x.cross(axis).norm(), x.dot(axis));
    const double squeezed = M_PI * std::pow(theta / M_PI, power);
    points.row(i) =
      (std::cos(squeezed) * axis + std::sin(squeezed) * side.normalized()).normalized().transpose();
  }
}

// Barycentric coordinates of p in triangle t, computed independently of the locator: signed
// volumes det(p, b, c), ... in extended precision, written with differences (b - p) so that
// they stay accurate for triangles 1e-11 wide.
Eigen::Vector3d ReferenceBarycentric(
  const Points& points, const Triangles& triangles, Index t, const Eigen::Vector3d& p)
{
  using Long = long double;
  Long q[3], d[3][3];
  for (int k = 0; k < 3; ++k)
  {
    q[k] = p[k];
  }
  for (int v = 0; v < 3; ++v)
  {
    for (int k = 0; k < 3; ++k)
    {
      d[v][k] = static_cast<Long>(points(triangles(t, v), k)) - q[k];
    }
  }
  auto volume = [&](const Long* x, const Long* y)
  {
    return q[0] * (x[1] * y[2] - x[2] * y[1]) + q[1] * (x[2] * y[0] - x[0] * y[2]) +
      q[2] * (x[0] * y[1] - x[1] * y[0]);
  };
  const Long alpha = volume(d[1], d[2]);
  const Long beta = volume(d[2], d[0]);
  const Long gamma = volume(d[0], d[1]);
  const Long sum = alpha + beta + gamma;
  return Eigen::Vector3d(static_cast<double>(alpha / sum), static_cast<double>(beta / sum),
    static_cast<double>(gamma / sum));
}

// The point the location stands for: (alpha a + beta b + gamma c) normalized.
Eigen::Vector3d LocatedPoint(
  const Points& points, const Triangles& triangles, const SphericalLocation& location)
{
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
  {
    x += location.Barycentric[k] * Vertex(points, triangles(location.Triangle, k));
  }
  return x.normalized();
}

// Checks that `location` is a proper, unclamped location of p; counts failures instead of
// printing every one, so a broken locator does not flood the log.
struct LocationChecker
{
  LocationChecker(const Points& meshPoints, const Triangles& meshTriangles)
    : points(meshPoints)
    , triangles(meshTriangles)
  {
  }

  const Points& points;
  const Triangles& triangles;
  int failures = 0;
  std::string first;

  void Check(const Eigen::Vector3d& p, const SphericalLocation& location)
  {
    std::string problem;
    if (location.Triangle < 0 || location.Triangle >= triangles.rows())
    {
      problem = "no triangle";
    }
    else if (location.Clamped || location.AngularDistance != 0.0)
    {
      problem = "clamped";
    }
    else if (std::abs(location.Barycentric.sum() - 1.0) > 1e-12 ||
      location.Barycentric.minCoeff() < 0.0)
    {
      problem = "barycentric coordinates not in [0, 1] with sum 1";
    }
    else if (ReferenceBarycentric(points, triangles, location.Triangle, p).minCoeff() < -1e-12)
    {
      problem = "triangle does not hold the point";
    }
    else if ((LocatedPoint(points, triangles, location) - p).norm() > 1e-12)
    {
      problem = "barycentric coordinates do not reproduce the point";
    }
    if (!problem.empty() && failures++ == 0)
    {
      std::ostringstream message;
      message.precision(17);
      message << problem << " at p = (" << p.transpose() << "), triangle " << location.Triangle;
      first = message.str();
    }
  }

  void Report(const char* what)
  {
    if (failures > 0)
    {
      std::cerr << what << ": " << failures << " bad locations; first: " << first << std::endl;
    }
    MOBIUS_CHECK(failures == 0);
  }
};

Points RandomDirections(int count, unsigned seed)
{
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal;
  Points directions(count, 3);
  for (int i = 0; i < count; ++i)
  {
    const Eigen::Vector3d x(normal(random), normal(random), normal(random));
    directions.row(i) = x.normalized().transpose();
  }
  return directions;
}

struct TestMesh
{
  std::string Name;
  Points Sphere;
  Triangles Faces;
};

std::vector<TestMesh> TestMeshes()
{
  std::vector<TestMesh> meshes(4);
  meshes[0].Name = "uniform icosphere";
  MakeIcosphere(5, meshes[0].Sphere, meshes[0].Faces);
  meshes[1].Name = "Moebius |c| = 0.9";
  MakeIcosphere(5, meshes[1].Sphere, meshes[1].Faces);
  ApplyInversion(Eigen::Vector3d(0.3, -0.5, 0.8).normalized() * 0.9, meshes[1].Sphere);
  meshes[2].Name = "Moebius |c| = 0.95, toward a pole";
  MakeIcosphere(5, meshes[2].Sphere, meshes[2].Faces);
  ApplyInversion(Eigen::Vector3d(0.0, 0.0, -0.95), meshes[2].Sphere);
  // Squeezing around a generic axis makes triangles 5e-11 .. 4e-2 wide: 9 orders of magnitude.
  meshes[3].Name = "squeezed limb";
  MakeIcosphere(6, meshes[3].Sphere, meshes[3].Faces);
  SqueezeAround(Eigen::Vector3d(0.3, -0.5, 0.8), 4.0, meshes[3].Sphere);
  return meshes;
}

void TestRandomQueries(const TestMesh& mesh)
{
  SphericalPointLocator locator;
  std::string error;
  MOBIUS_CHECK(locator.Build(mesh.Sphere, mesh.Faces, error));
  LocationChecker checker{ mesh.Sphere, mesh.Faces };
  const Points queries = RandomDirections(20000, 7);
  for (Index i = 0; i < queries.rows(); ++i)
  {
    const Eigen::Vector3d p = queries.row(i).transpose();
    checker.Check(p, locator.Locate(p));
  }
  // Queries concentrated where the triangles are smallest, around the pre-image of the
  // squeezed region: the images of random points near the original vertices.
  for (Index v = 0; v < mesh.Sphere.rows(); v += 7)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index t = (v * 3 + k) % mesh.Faces.rows();
      const Eigen::Vector3d p = (0.2 * Vertex(mesh.Sphere, mesh.Faces(t, 0)) +
        0.3 * Vertex(mesh.Sphere, mesh.Faces(t, 1)) + 0.5 * Vertex(mesh.Sphere, mesh.Faces(t, 2)))
                                  .normalized();
      checker.Check(p, locator.Locate(p));
    }
  }
  checker.Report(("random queries, " + mesh.Name).c_str());
}

void TestVerticesAndEdgeMidpoints(const TestMesh& mesh)
{
  SphericalPointLocator locator;
  std::string error;
  MOBIUS_CHECK(locator.Build(mesh.Sphere, mesh.Faces, error));
  LocationChecker checker{ mesh.Sphere, mesh.Faces };
  int wrongVertex = 0;
  for (Index v = 0; v < mesh.Sphere.rows(); ++v)
  {
    const Eigen::Vector3d p = Vertex(mesh.Sphere, v);
    const SphericalLocation location = locator.Locate(p);
    checker.Check(p, location);
    // At a vertex the coordinates are exactly (1, 0, 0) for some triangle of its star.
    bool found = false;
    for (int k = 0; k < 3 && location.Triangle >= 0; ++k)
    {
      found = found || (mesh.Faces(location.Triangle, k) == v && location.Barycentric[k] == 1.0);
    }
    wrongVertex += found ? 0 : 1;
  }
  MOBIUS_CHECK(wrongVertex == 0);

  int wrongEdge = 0;
  for (Index t = 0; t < mesh.Faces.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index from = mesh.Faces(t, k);
      const Index to = mesh.Faces(t, (k + 1) % 3);
      const Eigen::Vector3d p = (Vertex(mesh.Sphere, from) + Vertex(mesh.Sphere, to)).normalized();
      const SphericalLocation location = locator.Locate(p);
      checker.Check(p, location);
      // One of the two triangles of the edge, with (almost) no weight on the third vertex.
      int shared = 0;
      double otherWeight = 1.0;
      for (int j = 0; j < 3 && location.Triangle >= 0; ++j)
      {
        const Index corner = mesh.Faces(location.Triangle, j);
        if (corner == from || corner == to)
        {
          ++shared;
        }
        else
        {
          otherWeight = location.Barycentric[j];
        }
      }
      // The normalized midpoint is off the great circle by round-off (~1e-16), which is a
      // relative 1e-16 / length of a short edge's triangles.
      const double length = (Vertex(mesh.Sphere, from) - Vertex(mesh.Sphere, to)).norm();
      if (!(shared == 2 && otherWeight <= 1e-12 + 1e-15 / length) && wrongEdge++ == 0)
      {
        std::cerr << mesh.Name << ": edge " << from << "-" << to << " shared " << shared
                  << " other weight " << otherWeight << " length " << length << std::endl;
      }
    }
  }
  MOBIUS_CHECK(wrongEdge == 0);
  checker.Report(("vertices and edge midpoints, " + mesh.Name).c_str());
}

// Meshes so coarse that caps reach past a hemisphere (the regular tetrahedron's faces are
// 70.5 degrees in radius, their leaf a whole-sphere cap): the antipodal cone must be rejected.
void TestCoarseMeshes()
{
  std::vector<TestMesh> meshes(3);
  meshes[0].Name = "tetrahedron";
  meshes[0].Sphere.resize(4, 3);
  meshes[0].Sphere << 1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1;
  meshes[0].Sphere.rowwise().normalize();
  meshes[0].Faces.resize(4, 3);
  meshes[0].Faces << 0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2;
  meshes[1].Name = "octahedron";
  meshes[1].Sphere.resize(6, 3);
  meshes[1].Sphere << 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1;
  meshes[1].Faces.resize(8, 3);
  meshes[1].Faces << 0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5;
  meshes[2].Name = "icosahedron";
  MakeIcosphere(0, meshes[2].Sphere, meshes[2].Faces);
  for (const TestMesh& mesh : meshes)
  {
    for (Index t = 0; t < mesh.Faces.rows(); ++t)
    {
      const Eigen::Vector3d a = Vertex(mesh.Sphere, mesh.Faces(t, 0));
      MOBIUS_CHECK(
        a.dot(Vertex(mesh.Sphere, mesh.Faces(t, 1)).cross(Vertex(mesh.Sphere, mesh.Faces(t, 2)))) >
        0);
    }
    SphericalPointLocator locator;
    std::string error;
    MOBIUS_CHECK(locator.Build(mesh.Sphere, mesh.Faces, error));
    LocationChecker checker{ mesh.Sphere, mesh.Faces };
    const Points queries = RandomDirections(2000, 19);
    for (Index i = 0; i < queries.rows(); ++i)
    {
      checker.Check(queries.row(i).transpose(), locator.Locate(queries.row(i).transpose()));
    }
    for (Index v = 0; v < mesh.Sphere.rows(); ++v)
    {
      checker.Check(Vertex(mesh.Sphere, v), locator.Locate(Vertex(mesh.Sphere, v)));
    }
    checker.Report(mesh.Name.c_str());
  }
}

void TestPolesAndSeam()
{
  // Once with vertices at the poles and on the seam (the icosphere has them), once with the
  // poles and the seam inside triangles (a rotated, Möbius-distorted icosphere).
  for (int variant = 0; variant < 2; ++variant)
  {
    Points sphere;
    Triangles triangles;
    MakeIcosphere(4, sphere, triangles);
    if (variant == 1)
    {
      const Eigen::Matrix3d rotation =
        Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
      sphere = (sphere * rotation.transpose()).eval();
      ApplyInversion(Eigen::Vector3d(0.1, 0.6, 0.5), sphere);
    }
    SphericalPointLocator locator;
    std::string error;
    MOBIUS_CHECK(locator.Build(sphere, triangles, error));
    LocationChecker checker{ sphere, triangles };
    std::vector<Eigen::Vector3d> queries = { { 0, 0, 1 }, { 0, 0, -1 }, { 1, 0, 0 }, { 1, -0.0, 0 },
      { 1e-300, 0, 1 }, { -1e-300, 0, -1 } };
    for (int i = 0; i <= 64; ++i)
    {
      // The seam y = 0, x > 0 from pole to pole, and points just either side of it.
      const double theta = M_PI * i / 64.0;
      queries.emplace_back(std::sin(theta), 0.0, std::cos(theta));
      queries.emplace_back(std::sin(theta), 1e-15, std::cos(theta));
      queries.emplace_back(std::sin(theta), -1e-15, std::cos(theta));
    }
    for (const Eigen::Vector3d& q : queries)
    {
      checker.Check(q.normalized(), locator.Locate(q));
    }
    checker.Report(variant == 0 ? "poles and seam, vertices there" : "poles and seam, rotated");
  }
}

void TestAgainstBruteForce()
{
  Points sphere;
  Triangles triangles;
  MakeIcosphere(4, sphere, triangles);
  ApplyInversion(Eigen::Vector3d(-0.6, 0.2, 0.7), sphere); // |c| = 0.94
  SphericalPointLocator locator;
  std::string error;
  MOBIUS_CHECK(locator.Build(sphere, triangles, error));
  const Points queries = RandomDirections(3000, 11);
  int notInBruteForceSet = 0;
  int bruteForceEmpty = 0;
  for (Index i = 0; i < queries.rows(); ++i)
  {
    const Eigen::Vector3d p = queries.row(i).transpose();
    std::set<Index> holders;
    for (Index t = 0; t < triangles.rows(); ++t)
    {
      // The cone of the triangle, not its antipode: p . (a + b + c) > 0 for these small triangles.
      const Eigen::Vector3d centroid = Vertex(sphere, triangles(t, 0)) +
        Vertex(sphere, triangles(t, 1)) + Vertex(sphere, triangles(t, 2));
      if (p.dot(centroid) > 0.0 &&
        ReferenceBarycentric(sphere, triangles, t, p).minCoeff() >= -1e-12)
      {
        holders.insert(t);
      }
    }
    bruteForceEmpty += holders.empty() ? 1 : 0;
    const SphericalLocation location = locator.Locate(p);
    notInBruteForceSet += holders.count(location.Triangle) == 1 && !location.Clamped ? 0 : 1;
  }
  MOBIUS_CHECK(bruteForceEmpty == 0);
  MOBIUS_CHECK(notInBruteForceSet == 0);
}

// Angular distance from p to the geodesic arc u-w, written independently of the locator.
double AngleToArc(const Eigen::Vector3d& p, const Eigen::Vector3d& u, const Eigen::Vector3d& w)
{
  auto angle = [](const Eigen::Vector3d& x, const Eigen::Vector3d& y)
  { return std::atan2(x.cross(y).norm(), x.dot(y)); };
  double best = std::min(angle(p, u), angle(p, w));
  const Eigen::Vector3d n = u.cross(w).normalized();
  const Eigen::Vector3d foot = (p - p.dot(n) * n).normalized();
  if (std::abs(angle(u, foot) + angle(foot, w) - angle(u, w)) < 1e-12)
  {
    best = std::min(best, angle(p, foot));
  }
  return best;
}

double AngleToTriangle(
  const Points& sphere, const Triangles& triangles, Index t, const Eigen::Vector3d& p)
{
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k)
  {
    best = std::min(best,
      AngleToArc(p, Vertex(sphere, triangles(t, k)), Vertex(sphere, triangles(t, (k + 1) % 3))));
  }
  return best;
}

void TestHolesAreClampedToTheNearestTriangle()
{
  Points sphere;
  Triangles full;
  MakeIcosphere(4, sphere, full);
  ApplyInversion(Eigen::Vector3d(0.2, 0.3, -0.4), sphere);

  // One triangle removed: its centroid lies in no triangle.
  const Index removed = 1234;
  Triangles holed(full.rows() - 1, 3);
  holed << full.topRows(removed), full.bottomRows(full.rows() - removed - 1);
  SphericalPointLocator locator;
  std::string error;
  MOBIUS_CHECK(locator.Build(sphere, holed, error));
  const Eigen::Vector3d centroid = (Vertex(sphere, full(removed, 0)) +
    Vertex(sphere, full(removed, 1)) + Vertex(sphere, full(removed, 2)))
                                     .normalized();
  const SphericalLocation location = locator.Locate(centroid);
  MOBIUS_CHECK(location.Clamped);
  MOBIUS_CHECK(location.Triangle >= 0);
  MOBIUS_CHECK(location.AngularDistance > 0.0);
  if (location.Triangle >= 0)
  {
    MOBIUS_CHECK(location.Barycentric.minCoeff() >= 0.0);
    MOBIUS_CHECK_NEAR(location.Barycentric.sum(), 1.0, 1e-12);
    // The reported distance is the distance to the located point, and that is the distance to
    // the nearest triangle (brute force).
    const Eigen::Vector3d located = LocatedPoint(sphere, holed, location);
    MOBIUS_CHECK_NEAR(std::atan2(located.cross(centroid).norm(), located.dot(centroid)),
      location.AngularDistance, 1e-12);
    double nearest = std::numeric_limits<double>::infinity();
    for (Index t = 0; t < holed.rows(); ++t)
    {
      nearest = std::min(nearest, AngleToTriangle(sphere, holed, t, centroid));
    }
    MOBIUS_CHECK_NEAR(location.AngularDistance, nearest, 1e-12);
    // The nearest triangle shares an edge with the hole.
    int shared = 0;
    for (int j = 0; j < 3; ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        shared += holed(location.Triangle, j) == full(removed, k) ? 1 : 0;
      }
    }
    MOBIUS_CHECK(shared == 2);
  }

  // A whole polar cap removed: the pole is far from every triangle, so the search must leave
  // the pole's neighbourhood. Points outside the hole are still found normally.
  std::vector<Index> kept;
  for (Index t = 0; t < full.rows(); ++t)
  {
    double lowest = 1.0;
    for (int k = 0; k < 3; ++k)
    {
      lowest = std::min(lowest, sphere(full(t, k), 2));
    }
    if (lowest < 0.6)
    {
      kept.push_back(t);
    }
  }
  Triangles capless(static_cast<Index>(kept.size()), 3);
  for (std::size_t i = 0; i < kept.size(); ++i)
  {
    capless.row(static_cast<Index>(i)) = full.row(kept[i]);
  }
  MOBIUS_CHECK(locator.Build(sphere, capless, error));
  const Eigen::Vector3d pole(0, 0, 1);
  const SphericalLocation atPole = locator.Locate(pole);
  MOBIUS_CHECK(atPole.Clamped);
  double nearest = std::numeric_limits<double>::infinity();
  for (Index t = 0; t < capless.rows(); ++t)
  {
    nearest = std::min(nearest, AngleToTriangle(sphere, capless, t, pole));
  }
  MOBIUS_CHECK(nearest > 0.3);
  MOBIUS_CHECK_NEAR(atPole.AngularDistance, nearest, 1e-12);
  if (atPole.Triangle >= 0)
  {
    MOBIUS_CHECK_NEAR(AngleToTriangle(sphere, capless, atPole.Triangle, pole), nearest, 1e-12);
  }
  LocationChecker checker{ sphere, capless };
  const Points queries = RandomDirections(5000, 3);
  int clampedOutside = 0;
  for (Index i = 0; i < queries.rows(); ++i)
  {
    const Eigen::Vector3d p = queries.row(i).transpose();
    if (p.z() < 0.5)
    {
      const SphericalLocation l = locator.Locate(p);
      checker.Check(p, l);
      clampedOutside += l.Clamped ? 1 : 0;
    }
  }
  MOBIUS_CHECK(clampedOutside == 0);
  checker.Report("outside the polar hole");
}

void TestFoldedAndDegenerateTriangles()
{
  Points sphere;
  Triangles triangles;
  MakeIcosphere(4, sphere, triangles);
  // Fold: push vertex 0 past its neighbour (its star folds over). Degenerate: collapse another
  // edge so that its two triangles have zero area. The map still covers the sphere (degree 1),
  // so no point may be clamped.
  const Index folded = triangles(0, 0);
  const Index neighbour = triangles(0, 1);
  sphere.row(folded) =
    (Vertex(sphere, folded) + 1.5 * (Vertex(sphere, neighbour) - Vertex(sphere, folded)))
      .normalized()
      .transpose();
  const Index collapsed = triangles(5000, 0);
  sphere.row(collapsed) = sphere.row(triangles(5000, 1));
  int flipped = 0;
  int degenerate = 0;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    const Eigen::Vector3d a = Vertex(sphere, triangles(t, 0));
    const double volume =
      a.dot((Vertex(sphere, triangles(t, 1)) - a).cross(Vertex(sphere, triangles(t, 2)) - a));
    flipped += volume < 0.0 ? 1 : 0;
    degenerate += volume == 0.0 ? 1 : 0;
  }
  MOBIUS_CHECK(flipped > 0);
  MOBIUS_CHECK(degenerate == 2);

  SphericalPointLocator locator;
  std::string error;
  MOBIUS_CHECK(locator.Build(sphere, triangles, error));
  LocationChecker checker{ sphere, triangles };
  const Points queries = RandomDirections(20000, 5);
  std::mt19937_64 random(9);
  std::normal_distribution<double> normal;
  for (Index i = 0; i < queries.rows(); ++i)
  {
    const Eigen::Vector3d p = queries.row(i).transpose();
    checker.Check(p, locator.Locate(p));
    // And densely around the fold and the collapsed edge.
    const Eigen::Vector3d around = i % 2 == 0 ? Vertex(sphere, folded) : Vertex(sphere, collapsed);
    const Eigen::Vector3d q =
      (around + 0.03 * Eigen::Vector3d(normal(random), normal(random), normal(random)))
        .normalized();
    checker.Check(q, locator.Locate(q));
  }
  for (const Index v : { folded, neighbour, collapsed })
  {
    checker.Check(Vertex(sphere, v), locator.Locate(Vertex(sphere, v)));
  }
  checker.Report("folded and degenerate triangles");
}

void TestBadInput()
{
  Points sphere;
  Triangles triangles;
  MakeIcosphere(1, sphere, triangles);
  SphericalPointLocator locator;
  std::string error;
  auto fails = [&](const Points& p, const Triangles& t, const std::string& keyword)
  {
    const bool built = locator.Build(p, t, error);
    MOBIUS_CHECK(!built);
    MOBIUS_CHECK(!locator.IsBuilt());
    if (error.find(keyword) == std::string::npos)
    {
      std::cerr << "error message \"" << error << "\" does not mention \"" << keyword << "\""
                << std::endl;
      MOBIUS_CHECK(false);
    }
  };
  fails(Points(0, 3), triangles, "empty");
  fails(sphere, Triangles(0, 3), "empty");
  Triangles badIndex = triangles;
  badIndex(3, 1) = sphere.rows();
  fails(sphere, badIndex, "out of range");
  badIndex(3, 1) = -1;
  fails(sphere, badIndex, "out of range");
  Points offSphere = sphere;
  offSphere.row(5) *= 1.01;
  fails(offSphere, triangles, "not on the unit sphere");
  Points notANumber = sphere;
  notANumber(7, 2) = std::numeric_limits<double>::quiet_NaN();
  fails(notANumber, triangles, "non-finite");

  // Not built: nothing located, LocateAll reports failure.
  MOBIUS_CHECK(locator.Locate(Eigen::Vector3d(0, 0, 1)).Triangle == -1);
  std::vector<SphericalLocation> out;
  MOBIUS_CHECK(!locator.LocateAll(sphere, out));

  // Points within 1e-6 of the sphere are accepted; unusable queries give no triangle.
  Points nearSphere = sphere;
  nearSphere.row(5) *= 1.0 + 5e-7;
  MOBIUS_CHECK(locator.Build(nearSphere, triangles, error));
  MOBIUS_CHECK(error.empty());
  MOBIUS_CHECK(locator.Locate(Eigen::Vector3d::Zero()).Triangle == -1);
  MOBIUS_CHECK(
    locator.Locate(Eigen::Vector3d(std::numeric_limits<double>::quiet_NaN(), 0, 1)).Triangle == -1);
  MOBIUS_CHECK(locator.Locate(Eigen::Vector3d(3, 0, 0)).Triangle >= 0); // normalized first
}

void TestLocateAll()
{
  Points sphere;
  Triangles triangles;
  MakeIcosphere(5, sphere, triangles);
  ApplyInversion(Eigen::Vector3d(0.5, 0.5, 0.5), sphere);
  SphericalPointLocator locator;
  std::string error;
  MOBIUS_CHECK(locator.Build(sphere, triangles, error));
  const Points queries = RandomDirections(30000, 13);
  for (int threads : { 1, 2, 0 })
  {
    std::vector<SphericalLocation> locations;
    double lastProgress = 0.0;
    bool monotone = true;
    const bool ok = locator.LocateAll(queries, locations, threads,
      [&](double progress)
      {
        monotone = monotone && progress >= lastProgress && progress <= 1.0;
        lastProgress = progress;
        return true;
      });
    MOBIUS_CHECK(ok);
    MOBIUS_CHECK(monotone);
    MOBIUS_CHECK(locations.size() == static_cast<std::size_t>(queries.rows()));
    int different = 0;
    for (Index i = 0;
         i < queries.rows() && locations.size() == static_cast<std::size_t>(queries.rows()); ++i)
    {
      const SphericalLocation single = locator.Locate(queries.row(i).transpose());
      const SphericalLocation& many = locations[static_cast<std::size_t>(i)];
      different +=
        single.Triangle == many.Triangle && single.Barycentric == many.Barycentric ? 0 : 1;
    }
    MOBIUS_CHECK(different == 0);
  }
  std::vector<SphericalLocation> locations;
  MOBIUS_CHECK(!locator.LocateAll(queries, locations, 2, [](double) { return false; }));
  std::vector<SphericalLocation> none;
  MOBIUS_CHECK(locator.LocateAll(Points(0, 3), none));
  MOBIUS_CHECK(none.empty());
}

// The benchmark configuration of the design (327,680 triangles, 200K queries), timed for the
// log only: timings on shared machines are too noisy to assert.
void TimeLargeMeshes()
{
  using Clock = std::chrono::steady_clock;
  auto milliseconds = [](Clock::time_point start)
  { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); };
  Points uniform;
  Triangles triangles;
  MakeIcosphere(7, uniform, triangles);
  Points inverted = uniform;
  ApplyInversion(Eigen::Vector3d(0.3, -0.5, 0.8).normalized() * 0.9, inverted);
  const Points queries = RandomDirections(200000, 17);
  for (const Points* sphere : { &uniform, &inverted })
  {
    SphericalPointLocator locator;
    std::string error;
    const Clock::time_point buildStart = Clock::now();
    MOBIUS_CHECK(locator.Build(*sphere, triangles, error));
    const double build = milliseconds(buildStart);
    std::vector<SphericalLocation> locations;
    const Clock::time_point locateStart = Clock::now();
    MOBIUS_CHECK(locator.LocateAll(queries, locations));
    const double locate = milliseconds(locateStart);
    Index clamped = 0;
    for (const SphericalLocation& location : locations)
    {
      clamped += location.Clamped || location.Triangle < 0 ? 1 : 0;
    }
    MOBIUS_CHECK(clamped == 0);
    std::cout << (sphere == &uniform ? "uniform" : "Moebius |c| = 0.9") << ", " << triangles.rows()
              << " triangles: build " << build << " ms, 200000 queries " << locate << " ms, depth "
              << locator.GetDepth() << std::endl;
  }
}
}

int main()
{
  for (const TestMesh& mesh : TestMeshes())
  {
    TestRandomQueries(mesh);
    TestVerticesAndEdgeMidpoints(mesh);
  }
  TestCoarseMeshes();
  TestPolesAndSeam();
  TestAgainstBruteForce();
  TestHolesAreClampedToTheNearestTriangle();
  TestFoldedAndDegenerateTriangles();
  TestBadInput();
  TestLocateAll();
  TimeLargeMeshes();
  return MOBIUS_TEST_RESULT();
}
