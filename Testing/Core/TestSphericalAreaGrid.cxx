// Exact area rasterization of spherical maps: exactness (a tiling weighted by its own spherical
// areas gives lambda = 1 in every cell, whatever the triangle sizes, poles and seam), area
// conservation, a one-column shift under a rotation by one cell, an analytic density (a Moebius
// inversion of the round sphere), and input validation.
#include "CoreTest.h"
#include "Icosphere.h"
#include "SphericalAreaGrid.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace
{
using mobius::Points;
using mobius::Triangles;
using mobius::Vector;

double SphericalTriangleArea(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  // Van Oosterom and Strackee: tan(E/2) = |a.(b x c)| / (1 + a.b + b.c + c.a).
  return 2.0 * std::atan2(std::abs(a.dot(b.cross(c))), 1.0 + a.dot(b) + b.dot(c) + c.dot(a));
}

Vector SphericalAreas(const Points& points, const Triangles& triangles)
{
  Vector areas(triangles.rows());
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    areas[t] = SphericalTriangleArea(points.row(triangles(t, 0)).transpose(),
      points.row(triangles(t, 1)).transpose(), points.row(triangles(t, 2)).transpose());
  }
  return areas;
}

void Rotate(Points& points, const Eigen::Matrix3d& rotation)
{
  for (Eigen::Index k = 0; k < points.rows(); ++k)
  {
    points.row(k) = (rotation * points.row(k).transpose()).transpose();
  }
}

Eigen::Matrix3d RandomRotation(std::mt19937& generator)
{
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(generator), normal(generator), normal(generator), normal(generator));
  return q.normalized().toRotationMatrix();
}

/// v <- (1 - |c|^2)(v + c)/|v + c|^2 + c: a Moebius transformation of the unit sphere.
void Invert(Points& points, const Eigen::Vector3d& c)
{
  for (Eigen::Index k = 0; k < points.rows(); ++k)
  {
    const Eigen::Vector3d w = points.row(k).transpose() + c;
    points.row(k) = ((1.0 - c.squaredNorm()) * w / w.squaredNorm() + c).transpose();
  }
}

mobius::SphericalAreaGridResult Rasterize(const Points& points, const Triangles& triangles,
  const Vector& areas, int n, mobius::ScaleFactorValue value = mobius::ScaleFactorValue::AreaRatio)
{
  mobius::SphericalAreaGridResult result;
  std::string error;
  const bool ok = mobius::RasterizeSphericalAreas(points, triangles, areas, n, value, result, error);
  if (!ok)
  {
    std::cerr << "unexpected failure: " << error << std::endl;
  }
  MOBIUS_CHECK(ok);
  return result;
}

double Integral(const mobius::SphericalAreaGridResult& grid, bool squared)
{
  const int n = grid.Resolution;
  double sum = 0.0;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double v = grid.Values[j * n + i];
      sum += (squared ? v * v : v) * mobius::SphericalGridCellArea(n, j);
    }
  }
  return sum;
}

double MaxDeviationFromOne(const mobius::SphericalAreaGridResult& grid)
{
  double deviation = 0.0;
  for (double v : grid.Values)
  {
    deviation = std::max(deviation, std::abs(v - 1.0));
  }
  return deviation;
}

// Triangles weighted by their own spherical areas tile the sphere with density exactly 1.
void TestExactTiling()
{
  std::mt19937 generator(11);
  for (int level : { 0, 1, 3 })
  {
    Points points;
    Triangles triangles;
    mobius::MakeIcosphere(level, points, triangles);
    // Orientations: random; a vertex on each pole; a face center on the north pole (one
    // triangle contains the pole, another the south pole); an edge midpoint on the pole.
    std::vector<Eigen::Matrix3d> rotations = { RandomRotation(generator), RandomRotation(generator) };
    const Eigen::Vector3d vertex = points.row(0).transpose();
    rotations.push_back(Eigen::Quaterniond::FromTwoVectors(vertex, Eigen::Vector3d::UnitZ()).toRotationMatrix());
    const Eigen::Vector3d face = (points.row(triangles(0, 0)) + points.row(triangles(0, 1)) +
      points.row(triangles(0, 2))).transpose().normalized();
    rotations.push_back(Eigen::Quaterniond::FromTwoVectors(face, Eigen::Vector3d::UnitZ()).toRotationMatrix());
    const Eigen::Vector3d edge =
      (points.row(triangles(0, 0)) + points.row(triangles(0, 1))).transpose().normalized();
    rotations.push_back(Eigen::Quaterniond::FromTwoVectors(edge, Eigen::Vector3d::UnitZ()).toRotationMatrix());
    for (size_t r = 0; r < rotations.size(); ++r)
    {
      Points rotated = points;
      Rotate(rotated, rotations[r]);
      if (r == 2)
      {
        // Put the vertices exactly on the poles (x = y = 0), the hardest case for azimuths.
        for (Eigen::Index k = 0; k < rotated.rows(); ++k)
        {
          if (std::abs(std::abs(rotated(k, 2)) - 1.0) < 1e-12)
          {
            rotated.row(k) << 0.0, 0.0, rotated(k, 2) > 0 ? 1.0 : -1.0;
          }
        }
      }
      const Vector areas = SphericalAreas(rotated, triangles);
      for (int n : { 4, 6, 32, 128 })
      {
        const auto grid = Rasterize(rotated, triangles, areas, n);
        const double deviation = MaxDeviationFromOne(grid);
        if (deviation > 1e-9)
        {
          std::cerr << "level " << level << ", rotation " << r << ", N = " << n
                    << ": max |lambda - 1| = " << deviation << std::endl;
        }
        MOBIUS_CHECK_NEAR(deviation, 0.0, 1e-9);
      }
    }
  }

  // Strongly non-uniform map: a Moebius inversion shrinks one region by ~30x in area.
  Points points;
  Triangles triangles;
  mobius::MakeIcosphere(4, points, triangles);
  Invert(points, Eigen::Vector3d(0.3, -0.4, 0.5).normalized() * 0.7);
  // Reverse half of the triangles: orientation must not matter (flipped triangles of a
  // spherical map still cover their geodesic triangle).
  for (Eigen::Index t = 0; t < triangles.rows(); t += 2)
  {
    std::swap(triangles(t, 1), triangles(t, 2));
  }
  const Vector areas = SphericalAreas(points, triangles);
  for (int n : { 16, 64, 256 })
  {
    const auto grid = Rasterize(points, triangles, areas, n);
    const double deviation = MaxDeviationFromOne(grid);
    std::cout << "inverted tiling, N = " << n << ": max |lambda - 1| = " << deviation << std::endl;
    MOBIUS_CHECK_NEAR(deviation, 0.0, 1e-9);
  }
}

// A randomly rotated icosphere (level 4) whose triangles carry random areas in [0.01, 1].
void MakeRandomMap(unsigned seed, Points& points, Triangles& triangles, Vector& areas)
{
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(0.01, 1.0);
  mobius::MakeIcosphere(4, points, triangles);
  Rotate(points, RandomRotation(generator));
  areas.resize(triangles.rows());
  for (Eigen::Index t = 0; t < areas.size(); ++t)
  {
    areas[t] = uniform(generator);
  }
}

void TestConservation()
{
  Points points;
  Triangles triangles;
  Vector areas;
  MakeRandomMap(5, points, triangles, areas);
  const double total = areas.sum();
  for (int n : { 4, 16, 64, 256 })
  {
    const auto ratio = Rasterize(points, triangles, areas, n);
    MOBIUS_CHECK_NEAR(ratio.TotalArea, total, 1e-12 * total);
    MOBIUS_CHECK_NEAR(Integral(ratio, false) / total, 1.0, 1e-9);
    const auto root =
      Rasterize(points, triangles, areas, n, mobius::ScaleFactorValue::SquareRootAreaRatio);
    MOBIUS_CHECK_NEAR(Integral(root, true) / total, 1.0, 1e-9);
    for (size_t k = 0; k < root.Values.size(); ++k)
    {
      MOBIUS_CHECK_NEAR(root.Values[k] * root.Values[k], ratio.Values[k], 1e-12 * (1.0 + ratio.Values[k]));
    }
  }
}

// Rotating the map about z by one cell width moves the grid by exactly one column.
void TestRotationShiftsOneColumn()
{
  Points points;
  Triangles triangles;
  Vector areas;
  MakeRandomMap(17, points, triangles, areas);
  for (int n : { 16, 128 })
  {
    Points rotated = points;
    Rotate(rotated, Eigen::AngleAxisd(2.0 * M_PI / n, Eigen::Vector3d::UnitZ()).toRotationMatrix());
    const auto before = Rasterize(points, triangles, areas, n);
    const auto after = Rasterize(rotated, triangles, areas, n);
    double difference = 0.0, largest = 0.0;
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        difference = std::max(
          difference, std::abs(after.Values[j * n + (i + 1) % n] - before.Values[j * n + i]));
        largest = std::max(largest, before.Values[j * n + i]);
      }
    }
    std::cout << "N = " << n << ": one-column shift, relative max difference "
              << difference / largest << std::endl;
    MOBIUS_CHECK_NEAR(difference / largest, 0.0, 1e-10);
  }
}

// The round sphere mapped by a Moebius inversion f: the density at y is
// lambda(y) = (|x + c|^2 / (1 - |c|^2))^2 with x = f^{-1}(y) = (1-|c|^2)(y-c)/|y-c|^2 - c.
// The rasterized grid approaches the exact cell averages as the mesh is refined (the only error
// is that the image of a geodesic triangle is not the geodesic triangle on the mapped vertices).
void TestAnalyticDensity()
{
  const Eigen::Vector3d c = Eigen::Vector3d(0.2, 0.5, -0.6).normalized() * 0.7;
  const double c2 = c.squaredNorm();
  const int n = 16, samples = 24;
  std::vector<double> exact(n * n);
  for (int j = 0; j < n; ++j)
  {
    const double u0 = -std::cos(M_PI * j / n), u1 = -std::cos(M_PI * (j + 1) / n);
    for (int i = 0; i < n; ++i)
    {
      double sum = 0.0; // midpoint rule in (phi, u), where the area element is dphi du
      for (int a = 0; a < samples; ++a)
      {
        for (int b = 0; b < samples; ++b)
        {
          const double u = u0 + (u1 - u0) * (a + 0.5) / samples;
          const double phi = 2.0 * M_PI * (i + (b + 0.5) / samples) / n;
          const double s = std::sqrt(std::max(0.0, 1.0 - u * u));
          const Eigen::Vector3d y(s * std::cos(phi), s * std::sin(phi), -u);
          const Eigen::Vector3d x = (1.0 - c2) * (y - c) / (y - c).squaredNorm() - c;
          sum += std::pow((x + c).squaredNorm() / (1.0 - c2), 2);
        }
      }
      exact[j * n + i] = sum / (samples * samples);
    }
  }
  double previous = HUGE_VAL;
  for (int level : { 3, 5, 7 })
  {
    Points points;
    Triangles triangles;
    mobius::MakeIcosphere(level, points, triangles);
    const Vector areas = SphericalAreas(points, triangles);
    Invert(points, c);
    const auto grid = Rasterize(points, triangles, areas, n);
    double error = 0.0, norm = 0.0;
    for (int k = 0; k < n * n; ++k)
    {
      const double cellArea = mobius::SphericalGridCellArea(n, k / n);
      error += std::abs(grid.Values[k] - exact[k]) * cellArea;
      norm += exact[k] * cellArea;
    }
    std::cout << "Moebius density, icosphere level " << level << ": relative L1 error "
              << error / norm << std::endl;
    MOBIUS_CHECK(error / norm < 0.5 * previous);
    previous = error / norm;
  }
  MOBIUS_CHECK(previous < 1e-3);
}

bool FailsWith(const Points& points, const Triangles& triangles, const Vector& areas, int n,
  const std::string& expected)
{
  mobius::SphericalAreaGridResult result;
  std::string error;
  const bool ok = mobius::RasterizeSphericalAreas(
    points, triangles, areas, n, mobius::ScaleFactorValue::AreaRatio, result, error);
  const bool matches = !ok && error.find(expected) != std::string::npos;
  if (!matches)
  {
    std::cerr << "expected failure mentioning '" << expected << "', got ok = " << ok
              << ", error '" << error << "'" << std::endl;
  }
  return matches;
}

void TestBadInput()
{
  Points points;
  Triangles triangles;
  mobius::MakeIcosphere(1, points, triangles);
  const Vector areas = SphericalAreas(points, triangles);
  MOBIUS_CHECK(FailsWith(points, triangles, areas, 7, "even"));
  MOBIUS_CHECK(FailsWith(points, triangles, areas, 2, "at least 4"));
  Points off = points;
  off.row(5) *= 1.001;
  MOBIUS_CHECK(FailsWith(off, triangles, areas, 8, "point 5 is not on the unit sphere"));
  off = points;
  off(3, 0) = std::nan("");
  MOBIUS_CHECK(FailsWith(off, triangles, areas, 8, "point 3"));
  Vector negative = areas;
  negative[4] = -1e-3;
  MOBIUS_CHECK(FailsWith(points, triangles, negative, 8, "triangle 4 has area"));
  Vector infinite = areas;
  infinite[2] = HUGE_VAL;
  MOBIUS_CHECK(FailsWith(points, triangles, infinite, 8, "finite"));
  MOBIUS_CHECK(FailsWith(points, triangles, areas.head(3), 8, "one area per triangle"));
  Triangles outOfRange = triangles;
  outOfRange(6, 1) = points.rows();
  MOBIUS_CHECK(FailsWith(points, outOfRange, areas, 8, "triangle 6 refers to point"));

  // Progress can abort.
  mobius::SphericalAreaGridResult result;
  std::string error;
  const bool ok = mobius::RasterizeSphericalAreas(points, triangles, areas, 8,
    mobius::ScaleFactorValue::AreaRatio, result, error, [](double) { return false; });
  MOBIUS_CHECK(!ok && error == "aborted");

  // Zero-area spherical images (collapsed triangles) still deposit their area.
  Points collapsed = points;
  collapsed.row(triangles(0, 1)) = collapsed.row(triangles(0, 0));
  Vector ones = Vector::Ones(triangles.rows());
  const auto grid = Rasterize(collapsed, triangles, ones, 8);
  MOBIUS_CHECK_NEAR(Integral(grid, false), double(triangles.rows()), 1e-9 * triangles.rows());
}
}

int main()
{
  TestExactTiling();
  TestConservation();
  TestRotationShiftsOneColumn();
  TestAnalyticDensity();
  TestBadInput();
  return MOBIUS_TEST_RESULT();
}
