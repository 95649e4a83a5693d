// Unit tests of the ground-truth scoring of dense maps: the identity scores 0, a known shift
// scores its length (exactly along grid lines of a flat grid, within the zigzag of edge paths in
// other directions), geodesic >= Euclidean, antipodes of a sphere are about pi r apart, A* and
// Dijkstra agree, the summary statistics of a hand-made example, the subsample cap, true images
// inside triangles, and bad input.
#include "CoreTest.h"
#include "CorrespondenceScore.h"
#include "Icosphere.h"
#include "SphericalPointLocator.h"

#include <Eigen/Geometry>

#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace mobius;

namespace
{
// A flat (m + 1) x (m + 1) grid of [0, 1]^2 at z = 0, each square split along the diagonal
// from its lower-left to its upper-right corner: lower triangle (00, 10, 11), upper (00, 11, 01).
struct Grid
{
  int M;
  double H;
  Points P;
  Triangles T;

  explicit Grid(int m)
    : M(m)
    , H(1.0 / m)
  {
    P.resize((m + 1) * (m + 1), 3);
    for (int j = 0; j <= m; ++j)
    {
      for (int i = 0; i <= m; ++i)
      {
        P.row(Vertex(i, j)) << i * H, j * H, 0.0;
      }
    }
    T.resize(2 * m * m, 3);
    for (int j = 0; j < m; ++j)
    {
      for (int i = 0; i < m; ++i)
      {
        T.row(2 * (j * m + i)) << Vertex(i, j), Vertex(i + 1, j), Vertex(i + 1, j + 1);
        T.row(2 * (j * m + i) + 1) << Vertex(i, j), Vertex(i + 1, j + 1), Vertex(i, j + 1);
      }
    }
  }

  Index Vertex(int i, int j) const { return static_cast<Index>(j) * (M + 1) + i; }

  // The triangle and barycentric weights of the point (x, y) of the grid.
  SurfacePoint Locate(double x, double y) const
  {
    int i = std::min(M - 1, std::max(0, static_cast<int>(std::floor(x / H))));
    int j = std::min(M - 1, std::max(0, static_cast<int>(std::floor(y / H))));
    const double u = x / H - i, v = y / H - j;
    SurfacePoint point;
    if (u >= v)
    {
      point.Triangle = 2 * (j * M + i);
      point.Barycentric << 1.0 - u, u - v, v;
    }
    else
    {
      point.Triangle = 2 * (j * M + i) + 1;
      point.Barycentric << 1.0 - v, u, v - u;
    }
    return point;
  }
};

// A triangle holding vertex v, with weight 1 at v.
std::vector<SurfacePoint> VertexLocations(const Points& points, const Triangles& triangles)
{
  std::vector<SurfacePoint> locations(points.rows());
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      SurfacePoint& location = locations[triangles(t, k)];
      location.Triangle = t;
      location.Barycentric = Eigen::Vector3d::Unit(k);
    }
  }
  return locations;
}

std::vector<Index> Identity(Index n)
{
  std::vector<Index> truth(n);
  for (Index i = 0; i < n; ++i)
  {
    truth[i] = i;
  }
  return truth;
}

void TestSummary()
{
  Vector errors(6);
  errors << 0.5, 0.01, 0.2, std::numeric_limits<double>::quiet_NaN(), 0.06, 0.03;
  const CorrespondenceErrorSummary summary = SummarizeCorrespondenceErrors(errors);
  MOBIUS_CHECK(summary.Count == 5);
  MOBIUS_CHECK(summary.Unreachable == 0);
  MOBIUS_CHECK_NEAR(summary.Mean, 0.16, 1e-15);
  MOBIUS_CHECK_NEAR(summary.Median, 0.06, 1e-15);
  MOBIUS_CHECK_NEAR(summary.Percentile90, 0.2 + 0.6 * 0.3, 1e-15); // position 0.9 * 4 = 3.6
  MOBIUS_CHECK_NEAR(summary.Within[0], 0.2, 1e-15);
  MOBIUS_CHECK_NEAR(summary.Within[1], 0.4, 1e-15);
  MOBIUS_CHECK_NEAR(summary.Within[2], 0.6, 1e-15);
  MOBIUS_CHECK_NEAR(summary.Within[3], 0.8, 1e-15);

  // Even count: the median is the mean of the two middle values; a threshold itself is within.
  Vector even(4);
  even << 0.1, 0.025, 0.3, 0.05;
  const CorrespondenceErrorSummary evenSummary = SummarizeCorrespondenceErrors(even);
  MOBIUS_CHECK_NEAR(evenSummary.Median, 0.075, 1e-15);
  MOBIUS_CHECK_NEAR(evenSummary.Within[0], 0.25, 1e-15);
  MOBIUS_CHECK_NEAR(evenSummary.Within[1], 0.5, 1e-15);
  MOBIUS_CHECK_NEAR(evenSummary.Within[2], 0.75, 1e-15);
  MOBIUS_CHECK_NEAR(evenSummary.Within[3], 0.75, 1e-15);

  // An infinite error (no edge path) is counted, is never within, and makes the mean infinite.
  Vector unreachable(3);
  unreachable << 0.0, std::numeric_limits<double>::infinity(), 0.0;
  const CorrespondenceErrorSummary infinite = SummarizeCorrespondenceErrors(unreachable);
  MOBIUS_CHECK(infinite.Unreachable == 1 && std::isinf(infinite.Mean));
  MOBIUS_CHECK_NEAR(infinite.Median, 0.0, 0.0);
  MOBIUS_CHECK_NEAR(infinite.Within[3], 2.0 / 3.0, 1e-15);

  MOBIUS_CHECK(SummarizeCorrespondenceErrors(Vector()).Count == 0);
}

void TestFlatGrid()
{
  const Grid grid(40); // area 1, so errors are plain distances
  const Index n = grid.P.rows();
  std::string error;
  CorrespondenceScore score;

  // Identity.
  MOBIUS_CHECK(ScoreCorrespondence(grid.P, grid.T, VertexLocations(grid.P, grid.T), Identity(n), {},
                 score, error));
  MOBIUS_CHECK_NEAR(score.TargetArea, 1.0, 1e-12);
  MOBIUS_CHECK_NEAR(score.EuclideanSummary.Mean, 0.0, 0.0);
  MOBIUS_CHECK_NEAR(score.GeodesicSummary.Mean, 0.0, 0.0);
  MOBIUS_CHECK(score.GeodesicSummary.Count == n);
  MOBIUS_CHECK_NEAR(score.GeodesicSummary.Within[0], 1.0, 0.0);

  // Shifts along grid lines (x, and the diagonals of the split squares): the edge path is the
  // straight segment, so geodesic = Euclidean = the shift.
  for (const Eigen::Vector2d& shift :
    { Eigen::Vector2d(2.5 * grid.H, 0.0), Eigen::Vector2d(0.0, 7.25 * grid.H),
      Eigen::Vector2d(3.5 * grid.H, 3.5 * grid.H) })
  {
    std::vector<SurfacePoint> mapped;
    std::vector<Index> truth;
    for (int j = 0; j <= grid.M; ++j)
    {
      for (int i = 0; i <= grid.M; ++i)
      {
        const double x = i * grid.H + shift.x(), y = j * grid.H + shift.y();
        if (x <= 1.0 && y <= 1.0)
        {
          mapped.push_back(grid.Locate(x, y));
          truth.push_back(grid.Vertex(i, j));
        }
      }
    }
    MOBIUS_CHECK(ScoreCorrespondence(grid.P, grid.T, mapped, truth, {}, score, error));
    MOBIUS_CHECK_NEAR(score.EuclideanSummary.Mean, shift.norm(), 1e-12);
    MOBIUS_CHECK_NEAR(score.GeodesicSummary.Mean, shift.norm(), 1e-12);
    MOBIUS_CHECK_NEAR(score.GeodesicSummary.Percentile90, shift.norm(), 1e-12);
    MOBIUS_CHECK_NEAR(score.Geodesic.maxCoeff(), shift.norm(), 1e-12);
  }

  // A shift of length 0.3 at 0.4 rad (about 23 degrees), near the worst direction for edge
  // paths on this grid: the path zigzags between the x axis and the diagonal, at most
  // cos(22.5) + (sqrt 2 - 1) sin(22.5) = 1.082 times longer, plus up to an edge where it ends.
  {
    const Eigen::Vector2d shift = 0.3 * Eigen::Vector2d(std::cos(0.4), std::sin(0.4));
    std::vector<SurfacePoint> mapped;
    std::vector<Index> truth;
    for (int j = 0; j <= grid.M; ++j)
    {
      for (int i = 0; i <= grid.M; ++i)
      {
        const double x = i * grid.H + shift.x(), y = j * grid.H + shift.y();
        if (x <= 1.0 && y <= 1.0)
        {
          mapped.push_back(grid.Locate(x, y));
          truth.push_back(grid.Vertex(i, j));
        }
      }
    }
    MOBIUS_CHECK(ScoreCorrespondence(grid.P, grid.T, mapped, truth, {}, score, error));
    MOBIUS_CHECK_NEAR(score.EuclideanSummary.Mean, 0.3, 1e-12);
    MOBIUS_CHECK(score.Geodesic.minCoeff() >= 0.3 - 1e-12);
    MOBIUS_CHECK(score.Geodesic.maxCoeff() <= 0.3 * 1.083 + grid.H);
    MOBIUS_CHECK(score.GeodesicSummary.Mean > 0.3 * 1.02); // it does zigzag
    MOBIUS_CHECK_NEAR(score.GeodesicSummary.Within[3], 0.0, 0.0);
    std::cout << "grid, shift 0.3 at 23 degrees: edge path / straight = "
              << score.GeodesicSummary.Mean / 0.3 << std::endl;
  }

  // True images inside triangles: the same shift given as grid points (here: the vertices'
  // positions moved by a quarter cell) agrees with the straight segment in one triangle and with
  // the exact answer along a grid line.
  {
    std::vector<SurfacePoint> mapped, truth;
    const double x = 10.25 * grid.H, y = 10.1 * grid.H;
    truth.push_back(grid.Locate(x, y));
    mapped.push_back(grid.Locate(x + 0.5 * grid.H, y)); // same triangle
    truth.push_back(grid.Locate(x, y));
    mapped.push_back(grid.Locate(x + 6.0 * grid.H, y)); // along a grid line: exact
    MOBIUS_CHECK(ScoreCorrespondence(grid.P, grid.T, mapped, truth, {}, score, error));
    MOBIUS_CHECK_NEAR(score.Geodesic[0], 0.5 * grid.H, 1e-12);
    MOBIUS_CHECK_NEAR(score.Euclidean[1], 6.0 * grid.H, 1e-12);
    // Seeded at the three vertices of the true triangle, so no more than their offsets longer.
    MOBIUS_CHECK(score.Geodesic[1] >= 6.0 * grid.H - 1e-12);
    MOBIUS_CHECK(score.Geodesic[1] <= 6.0 * grid.H * 1.05);
  }
}

// Icosphere of radius r with a rotated copy of its vertices located on it.
void TestSphere()
{
  Points unit;
  Triangles triangles;
  MakeIcosphere(4, unit, triangles); // 2562 vertices
  const double radius = 2.0;
  const Points points = radius * unit;
  const Index n = points.rows();
  EdgePathGeodesics geodesics;
  std::string error;
  MOBIUS_CHECK(geodesics.Build(points, triangles, error));
  MOBIUS_CHECK_NEAR(geodesics.GetSurfaceArea(), 4 * M_PI * radius * radius,
    0.01 * 4 * M_PI * radius * radius);

  SphericalPointLocator locator;
  MOBIUS_CHECK(locator.Build(unit, triangles, error));
  auto locate = [&](const Eigen::Vector3d& x) {
    const SphericalLocation location = locator.Locate(x);
    SurfacePoint point;
    point.Triangle = location.Triangle;
    point.Barycentric = location.Barycentric;
    return point;
  };

  // Antipodes (the vertex set is symmetric about the origin): within a few % of pi r.
  EdgePathGeodesics::Workspace workspace;
  double worst = 0.0;
  for (Index i = 0; i < n; i += 97)
  {
    const SurfacePoint antipode = locate(-unit.row(i).transpose());
    const double d = geodesics.Distance(i, antipode, workspace);
    worst = std::max(worst, std::abs(d / (M_PI * radius) - 1.0));
  }
  std::cout << "sphere, antipodes: edge path within " << 100 * worst << "% of pi r" << std::endl;
  MOBIUS_CHECK(worst < 0.08);

  // A rotated map: geodesic >= Euclidean, close to the arc; A* agrees with Dijkstra.
  const Eigen::Matrix3d rotation =
    Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<SurfacePoint> mapped(n);
  for (Index i = 0; i < n; ++i)
  {
    mapped[i] = locate(rotation * unit.row(i).transpose());
  }
  CorrespondenceScore score;
  MOBIUS_CHECK(ScoreCorrespondence(points, triangles, mapped, Identity(n), {}, score, error));
  MOBIUS_CHECK((score.Geodesic - score.Euclidean).minCoeff() >= -1e-12);
  // Chord and arc of each vertex's rotation; the faceted positions differ a little.
  double arcs = 0.0;
  for (Index i = 0; i < n; ++i)
  {
    const Eigen::Vector3d x = unit.row(i);
    arcs += radius * std::acos(std::min(1.0, x.dot(rotation * x)));
  }
  const double arcMean = arcs / n / score.Scale;
  std::cout << "sphere, rotation 0.3 rad: Euclidean " << score.EuclideanSummary.Mean
            << ", edge path " << score.GeodesicSummary.Mean << ", arc " << arcMean << std::endl;
  MOBIUS_CHECK(score.GeodesicSummary.Mean > 0.99 * arcMean);
  MOBIUS_CHECK(score.GeodesicSummary.Mean < 1.15 * arcMean); // 8 edges: discretization shows

  EdgePathGeodesics dijkstra;
  MOBIUS_CHECK(dijkstra.Build(points, triangles, error));
  dijkstra.SetUseAStar(false);
  EdgePathGeodesics::Workspace other;
  Index settledAStar = 0, settledDijkstra = 0;
  std::mt19937 random(7);
  for (int query = 0; query < 300; ++query)
  {
    const Index from = random() % n;
    SurfacePoint to;
    to.Triangle = random() % triangles.rows();
    to.Barycentric = Eigen::Vector3d::Random().cwiseAbs() + Eigen::Vector3d::Constant(0.01);
    to.Barycentric /= to.Barycentric.sum();
    const double a = geodesics.Distance(from, to, workspace);
    settledAStar += workspace.GetLastSettledCount();
    const double b = dijkstra.Distance(from, to, other);
    settledDijkstra += other.GetLastSettledCount();
    MOBIUS_CHECK_NEAR(a, b, 1e-12 * b);
  }
  std::cout << "random queries: A* settled " << settledAStar << " vertices, Dijkstra "
            << settledDijkstra << std::endl;
  MOBIUS_CHECK(settledAStar < settledDijkstra / 2);

  // The cap: an even, deterministic subsample of the geodesic queries.
  CorrespondenceScoreOptions options;
  options.MaximumGeodesicQueries = 100;
  options.NumberOfThreads = 2;
  CorrespondenceScore capped;
  MOBIUS_CHECK(ScoreCorrespondence(points, triangles, mapped, Identity(n), options, capped, error));
  MOBIUS_CHECK(capped.GeodesicSummary.Count == 100);
  MOBIUS_CHECK(capped.EuclideanSummary.Count == n);
  for (Index k = 0; k < 100; ++k)
  {
    const Index i = k * n / 100;
    MOBIUS_CHECK(capped.Geodesic[i] == score.Geodesic[i]);
  }
  MOBIUS_CHECK(std::isnan(capped.Geodesic[1]));

  // A true image given as a point on a triangle (weight 1 at the vertex) scores the same,
  // except that the straight segment is used whenever the two triangles share a vertex (for a
  // vertex: only when the mapped triangle holds it), which can only be shorter.
  const std::vector<SurfacePoint> atVertices = VertexLocations(points, triangles);
  CorrespondenceScore asPoints;
  MOBIUS_CHECK(ScoreCorrespondence(points, triangles, mapped, atVertices, {}, asPoints, error));
  MOBIUS_CHECK((asPoints.Euclidean - score.Euclidean).cwiseAbs().maxCoeff() < 1e-12);
  MOBIUS_CHECK((asPoints.Geodesic - score.Euclidean).minCoeff() >= -1e-12);
  MOBIUS_CHECK((asPoints.Geodesic - score.Geodesic).maxCoeff() <= 1e-12);
  Index same = 0;
  for (Index i = 0; i < n; ++i)
  {
    same += std::abs(asPoints.Geodesic[i] - score.Geodesic[i]) <= 1e-12 * score.Geodesic[i];
  }
  MOBIUS_CHECK(same > 0.95 * n);
}

// Scoring every vertex of a 40K-vertex sphere under a rotation takes seconds, not minutes.
void TestSpeed()
{
  Points unit;
  Triangles triangles;
  MakeIcosphere(6, unit, triangles); // 40962 vertices
  SphericalPointLocator locator;
  std::string error;
  MOBIUS_CHECK(locator.Build(unit, triangles, error));
  const Eigen::Matrix3d rotation =
    Eigen::AngleAxisd(0.2, Eigen::Vector3d(3, -1, 2).normalized()).toRotationMatrix();
  const Index n = unit.rows();
  std::vector<SurfacePoint> mapped(n);
  for (Index i = 0; i < n; ++i)
  {
    const SphericalLocation location = locator.Locate(rotation * unit.row(i).transpose());
    mapped[i].Triangle = location.Triangle;
    mapped[i].Barycentric = location.Barycentric;
  }
  const auto start = std::chrono::steady_clock::now();
  CorrespondenceScore score;
  MOBIUS_CHECK(ScoreCorrespondence(unit, triangles, mapped, Identity(n), {}, score, error));
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "40962-vertex sphere, rotation 0.2 rad: " << seconds << " s, mean error "
            << score.GeodesicSummary.Mean << ", " << score.SettledVertices / n
            << " vertices settled per query" << std::endl;
  MOBIUS_CHECK(score.GeodesicSummary.Count == n);
  MOBIUS_CHECK(seconds < 60.0);
}

void TestErrors()
{
  const Grid grid(4);
  std::vector<SurfacePoint> mapped = VertexLocations(grid.P, grid.T);
  std::vector<Index> truth = Identity(grid.P.rows());
  CorrespondenceScore score;
  std::string error;

  truth[3] = grid.P.rows();
  MOBIUS_CHECK(!ScoreCorrespondence(grid.P, grid.T, mapped, truth, {}, score, error));
  MOBIUS_CHECK(error.find("source vertex 3") != std::string::npos &&
    error.find("out of range") != std::string::npos);
  truth[3] = 3;

  mapped[5].Triangle = grid.T.rows();
  MOBIUS_CHECK(!ScoreCorrespondence(grid.P, grid.T, mapped, truth, {}, score, error));
  MOBIUS_CHECK(error.find("source vertex 5") != std::string::npos);
  mapped[5].Triangle = 0;
  mapped[5].Barycentric[1] = std::numeric_limits<double>::quiet_NaN();
  MOBIUS_CHECK(!ScoreCorrespondence(grid.P, grid.T, mapped, truth, {}, score, error));
  MOBIUS_CHECK(error.find("not finite") != std::string::npos);
  mapped[5].Barycentric = Eigen::Vector3d(1, 0, 0);

  truth.pop_back();
  MOBIUS_CHECK(!ScoreCorrespondence(grid.P, grid.T, mapped, truth, {}, score, error));
  MOBIUS_CHECK(error.find("source vertices") != std::string::npos);

  Triangles bad = grid.T;
  bad(2, 1) = -1;
  EdgePathGeodesics geodesics;
  MOBIUS_CHECK(!geodesics.Build(grid.P, bad, error));
  MOBIUS_CHECK(error.find("target triangle 2") != std::string::npos);
  MOBIUS_CHECK(geodesics.Build(grid.P, grid.T, error));
  EdgePathGeodesics::Workspace workspace;
  MOBIUS_CHECK(std::isnan(geodesics.Distance(grid.P.rows(), mapped[0], workspace)));
  MOBIUS_CHECK(std::isnan(geodesics.Distance(mapped[1], SurfacePoint(), workspace)));
  MOBIUS_CHECK(geodesics.Distance(0, mapped[grid.Vertex(3, 0)], workspace) == 3 * grid.H);

  // Two separate triangles: no edge path, an infinite error, counted as unreachable.
  Points two(6, 3);
  two << 0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 0, 0, 6, 0, 0, 5, 1, 0;
  Triangles pair(2, 3);
  pair << 0, 1, 2, 3, 4, 5;
  std::vector<SurfacePoint> across(1);
  across[0].Triangle = 1;
  across[0].Barycentric = Eigen::Vector3d(1, 0, 0);
  MOBIUS_CHECK(ScoreCorrespondence(two, pair, across, std::vector<Index>{ 0 }, {}, score, error));
  MOBIUS_CHECK(std::isinf(score.Geodesic[0]) && score.GeodesicSummary.Unreachable == 1);
  MOBIUS_CHECK_NEAR(score.Euclidean[0], 5.0, 1e-12);
}
}

int main()
{
  TestSummary();
  TestFlatGrid();
  TestSphere();
  TestSpeed();
  TestErrors();
  return MOBIUS_TEST_RESULT();
}
