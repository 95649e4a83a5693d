// Unit tests of the scoring at ground-truth samples (SampleScore.h) and of what it adds to the
// edge-path geodesics: vertex-to-vertex distances, exact along grid lines; landmark (ALT)
// bounds that leave every distance as plain Dijkstra finds it while settling far fewer
// vertices on a bent sheet, whose ends are close in space and far along the surface; two
// components; the nearest corner of a mapped point; per-sample errors and their bad input;
// the per-pair summary (mean, median, share above 10).
#include "CoreTest.h"
#include "CorridorGeodesics.h"
#include "SampleScore.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace mobius;

namespace
{
// A (columns + 1) x (rows + 1) grid of squares of side h, each split along a diagonal,
// optionally bent about the y axis into an arc of `bend` radians (a "C" seen from above).
void MakeStrip(int columns, int rows, double h, double bend, Points& points, Triangles& triangles)
{
  auto vertex = [&](int i, int j) { return static_cast<Index>(j) * (columns + 1) + i; };
  points.resize((columns + 1) * (rows + 1), 3);
  const double length = columns * h;
  const double radius = bend > 0 ? length / bend : 0.0;
  for (int j = 0; j <= rows; ++j)
  {
    for (int i = 0; i <= columns; ++i)
    {
      const double x = i * h;
      if (bend > 0)
      {
        const double angle = x / radius;
        points.row(vertex(i, j)) << radius * std::sin(angle), j * h, radius * (1 - std::cos(angle));
      }
      else
      {
        points.row(vertex(i, j)) << x, j * h, 0.0;
      }
    }
  }
  triangles.resize(2 * columns * rows, 3);
  for (int j = 0; j < rows; ++j)
  {
    for (int i = 0; i < columns; ++i)
    {
      const Index t = 2 * (static_cast<Index>(j) * columns + i);
      triangles.row(t) << vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1);
      triangles.row(t + 1) << vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1);
    }
  }
}

void TestVertexDistances()
{
  Points points;
  Triangles triangles;
  MakeStrip(10, 10, 0.1, 0.0, points, triangles);
  EdgePathGeodesics geodesics;
  std::string error;
  MOBIUS_CHECK(geodesics.Build(points, triangles, error));
  EdgePathGeodesics::Workspace workspace;
  // Along a grid line: exactly the edges' lengths; on the diagonal's direction, the diagonals.
  MOBIUS_CHECK_NEAR(geodesics.Distance(0, 7, workspace), 0.7, 1e-12);
  MOBIUS_CHECK_NEAR(geodesics.Distance(0, 4 * 11 + 4, workspace), 4 * std::sqrt(0.02), 1e-12);
  MOBIUS_CHECK(geodesics.Distance(5, 5, workspace) == 0.0);
  MOBIUS_CHECK(std::isnan(geodesics.Distance(0, points.rows(), workspace)));
  MOBIUS_CHECK(std::isnan(geodesics.Distance(-1, 3, workspace)));
}

void TestLandmarks()
{
  // A sheet 120 x 40 bent into an arc of 300 degrees: its ends are close in space, so the
  // straight-line bound lets a search spread over most of the sheet.
  Points points;
  Triangles triangles;
  MakeStrip(120, 40, 0.05, 300.0 * M_PI / 180.0, points, triangles);
  const Index n = points.rows();
  EdgePathGeodesics plain, dijkstra, landmarks;
  std::string error;
  MOBIUS_CHECK(plain.Build(points, triangles, error));
  MOBIUS_CHECK(dijkstra.Build(points, triangles, error));
  MOBIUS_CHECK(landmarks.Build(points, triangles, error));
  dijkstra.SetUseAStar(false);
  landmarks.BuildLandmarks(SampleScoreLandmarks);
  EdgePathGeodesics::Workspace a, b, c;
  Index settledPlain = 0, settledLandmarks = 0;
  std::mt19937 random(11);
  for (int query = 0; query < 200; ++query)
  {
    // One end near each end of the sheet: long along the surface.
    const Index row = 5 + random() % 31;
    const Index from = row * 121 + random() % 10;
    const Index to = (row + random() % 5) * 121 + 111 + random() % 10;
    const double reference = dijkstra.Distance(from, to, c);
    const double withLandmarks = landmarks.Distance(from, to, b);
    MOBIUS_CHECK_NEAR(plain.Distance(from, to, a), reference, 1e-12 * reference);
    MOBIUS_CHECK_NEAR(withLandmarks, reference, 1e-12 * reference);
    settledPlain += a.GetLastSettledCount();
    settledLandmarks += b.GetLastSettledCount();
  }
  std::cout << "bent sheet, " << n << " vertices, 200 end-to-end queries: A* settled "
            << settledPlain << " vertices, with landmarks " << settledLandmarks << std::endl;
  MOBIUS_CHECK(settledLandmarks < settledPlain / 3);
  // Random pairs anywhere (and points inside triangles) agree too.
  for (int query = 0; query < 200; ++query)
  {
    const Index from = random() % n;
    SurfacePoint to;
    to.Triangle = random() % triangles.rows();
    to.Barycentric = Eigen::Vector3d::Random().cwiseAbs() + Eigen::Vector3d::Constant(0.01);
    to.Barycentric /= to.Barycentric.sum();
    const double reference = dijkstra.Distance(from, to, c);
    MOBIUS_CHECK_NEAR(landmarks.Distance(from, to, b), reference, 1e-12 * reference);
  }

  // Two components: landmarks in both; across them no path.
  Points two(2 * n, 3);
  two << points, points.rowwise() + Eigen::RowVector3d(100, 0, 0);
  Triangles both(2 * triangles.rows(), 3);
  both << triangles, (triangles.array() + n).matrix();
  EdgePathGeodesics separate;
  MOBIUS_CHECK(separate.Build(two, both, error));
  separate.BuildLandmarks(SampleScoreLandmarks);
  MOBIUS_CHECK(std::isinf(separate.Distance(3, n + 3, b)));
  const double inSecond = separate.Distance(n + 10, n + 4000, b);
  MOBIUS_CHECK_NEAR(inSecond, dijkstra.Distance(10, 4000, c), 1e-12 * inSecond);
}

void TestCorridor()
{
  // The sheet of TestLandmarks: bent about the y axis, each column strip stays a flat
  // rectangle (width: the chord of a column), so the surface is intrinsically flat and the
  // exact geodesic between two vertices is their distance in the unrolled sheet.
  const int columns = 120, rows = 40;
  const double h = 0.05, bend = 300.0 * M_PI / 180.0;
  Points points;
  Triangles triangles;
  MakeStrip(columns, rows, h, bend, points, triangles);
  const double chord = (points.row(1) - points.row(0)).norm();
  EdgePathGeodesics edges;
  std::string error;
  MOBIUS_CHECK(edges.Build(points, triangles, error));
  CorridorGeodesics none, corridor;
  none.Build(edges, 0);
  corridor.Build(edges, SampleGeodesics().SteinerPoints);
  CorridorGeodesics::Workspace a, b;
  std::mt19937 random(5);
  double edgeExcess = 0.0, corridorExcess = 0.0;
  const int queries = 300;
  for (int query = 0; query < queries; ++query)
  {
    const int i0 = random() % (columns + 1), j0 = random() % (rows + 1);
    int i1 = random() % (columns + 1), j1 = random() % (rows + 1);
    i1 = i1 == i0 && j1 == j0 ? (i1 + 1) % (columns + 1) : i1;
    const Index from = j0 * (columns + 1) + i0, to = j1 * (columns + 1) + i1;
    const double exact = std::hypot((i1 - i0) * chord, (j1 - j0) * h);
    const double edgePath = none.Distance(from, to, a);
    const double shortened = corridor.Distance(from, to, b);
    MOBIUS_CHECK(shortened >= exact * (1 - 1e-12) && shortened <= edgePath * (1 + 1e-12));
    edgeExcess += edgePath / exact - 1;
    corridorExcess += shortened / exact - 1;
  }
  std::cout << "bent sheet, " << queries << " random vertex pairs: edge paths "
            << 100 * edgeExcess / queries << "% longer than exact, corridor with "
            << SampleGeodesics().SteinerPoints << " Steiner points " << 100 * corridorExcess / queries
            << "%" << std::endl;
  MOBIUS_CHECK(edgeExcess / queries > 0.03);
  MOBIUS_CHECK(corridorExcess / queries < 0.02); // measured 1.3%: the grid is a hard case
  // Zero Steiner points: the edge paths themselves; neighbors: the edge.
  EdgePathGeodesics::Workspace plain;
  MOBIUS_CHECK(none.Distance(0, 5 * (columns + 1) + 7, a) ==
    edges.Distance(0, 5 * (columns + 1) + 7, plain));
  MOBIUS_CHECK(corridor.Distance(0, 1, b) == chord);
  MOBIUS_CHECK(std::isnan(corridor.Distance(0, points.rows(), b)));
}

void TestNearestCorner()
{
  Points points(4, 3);
  points << 0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5;
  MOBIUS_CHECK(NearestCorner(points, { 0, 1, 2 }, Eigen::Vector3d(0.1, 0.6, 0.3)) == 1);
  MOBIUS_CHECK(NearestCorner(points, { 0, 1, 2 }, Eigen::Vector3d(0.6, 0.2, 0.2)) == 0);
  // A corner that is not a vertex drops out; the rest keep their shares.
  MOBIUS_CHECK(NearestCorner(points, { 0, -1, 2 }, Eigen::Vector3d(0.1, 0.6, 0.3)) == 2);
  MOBIUS_CHECK(NearestCorner(points, { -1, -1, 7 }, Eigen::Vector3d(0.2, 0.5, 0.3)) == -1);
}

void TestScoreSamples()
{
  // The unit square, 10 x 10: each sample mapped one vertex to the right is off by 0.1 of
  // sqrt(area) = 1.
  Points points;
  Triangles triangles;
  MakeStrip(10, 10, 0.1, 0.0, points, triangles);
  EdgePathGeodesics geodesics;
  std::string error;
  MOBIUS_CHECK(geodesics.Build(points, triangles, error));
  const std::vector<Index> truth = { 0, 12, 25, 50 };
  std::vector<Index> mapped = { 1, 13, 26, 51 };
  std::vector<double> errors;
  bool shortened = false;
  MOBIUS_CHECK(ScoreSamples(geodesics, mapped, truth, {}, 2, errors, shortened, error));
  MOBIUS_CHECK(errors.size() == 4);
  for (double e : errors)
  {
    MOBIUS_CHECK_NEAR(e, 0.1, 1e-12);
  }
  mapped[2] = -1; // a sample the map does not reach
  MOBIUS_CHECK(ScoreSamples(geodesics, mapped, truth, {}, 1, errors, shortened, error));
  MOBIUS_CHECK(std::isnan(errors[2]) && !std::isnan(errors[3]));
  mapped[2] = points.rows();
  MOBIUS_CHECK(!ScoreSamples(geodesics, mapped, truth, {}, 1, errors, shortened, error));
  MOBIUS_CHECK(error.find("sample 3") != std::string::npos &&
    error.find("out of range") != std::string::npos);
  mapped.pop_back();
  MOBIUS_CHECK(!ScoreSamples(geodesics, mapped, truth, {}, 1, errors, shortened, error));
  MOBIUS_CHECK(error.find("3 samples, the truth 4") != std::string::npos);
}

void TestShortenedPairs()
{
  // The bent sheet (intrinsically flat): samples mapped 7 columns and 3 rows off are
  // measured by shortened paths, close to the exact (unrolled) distance; samples mapped 90
  // columns off make a pair above ShortenPairsUpTo, measured by edge paths alone.
  const int columns = 120, rows = 40;
  Points points;
  Triangles triangles;
  MakeStrip(columns, rows, 0.05, 300.0 * M_PI / 180.0, points, triangles);
  const double chord = (points.row(1) - points.row(0)).norm();
  EdgePathGeodesics geodesics;
  std::string error;
  MOBIUS_CHECK(geodesics.Build(points, triangles, error));
  const double scale = std::sqrt(geodesics.GetSurfaceArea());
  std::vector<Index> truth, near, far;
  for (int j = 0; j + 3 <= rows; j += 4)
  {
    for (int i = 0; i + 97 <= columns; i += 8)
    {
      truth.push_back(j * (columns + 1) + i);
      near.push_back((j + 3) * (columns + 1) + i + 7);
      far.push_back(j * (columns + 1) + i + 90);
    }
  }
  std::vector<double> errors, edgeErrors;
  bool shortened = false;
  SampleGeodesics edgesOnly;
  edgesOnly.SteinerPoints = 0;
  MOBIUS_CHECK(ScoreSamples(geodesics, near, truth, {}, 2, errors, shortened, error) && shortened);
  MOBIUS_CHECK(ScoreSamples(geodesics, near, truth, edgesOnly, 2, edgeErrors, shortened, error) &&
    !shortened);
  const double exact = std::hypot(7 * chord, 3 * 0.05) / scale;
  double mean = 0.0, edgeMean = 0.0;
  for (size_t k = 0; k < truth.size(); ++k)
  {
    MOBIUS_CHECK(errors[k] >= exact * (1 - 1e-12) && errors[k] <= edgeErrors[k] * (1 + 1e-12));
    mean += errors[k] / truth.size();
    edgeMean += edgeErrors[k] / truth.size();
  }
  std::cout << "bent sheet, samples 7 x 3 off: exact " << exact << ", shortened " << mean
            << ", edge paths " << edgeMean << std::endl;
  MOBIUS_CHECK(mean < 1.01 * exact && edgeMean > 1.05 * exact);
  MOBIUS_CHECK(ScoreSamples(geodesics, far, truth, {}, 2, errors, shortened, error) && !shortened);
  MOBIUS_CHECK(ScoreSamples(geodesics, far, truth, edgesOnly, 2, edgeErrors, shortened, error));
  MOBIUS_CHECK(errors == edgeErrors);
}

void TestPairSummary()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const PairErrorSummary summary = SummarizePairErrors({ 1.0, 12.0, 3.0, nan, 20.0 });
  MOBIUS_CHECK(summary.Pairs == 4);
  MOBIUS_CHECK_NEAR(summary.Mean, 9.0, 1e-12);
  MOBIUS_CHECK_NEAR(summary.Median, 7.5, 1e-12);
  MOBIUS_CHECK_NEAR(summary.ShareFailed, 0.5, 1e-12);
  const PairErrorSummary odd = SummarizePairErrors({ 10.0, 2.0, 4.0 });
  MOBIUS_CHECK(odd.Median == 4.0 && odd.ShareFailed == 0.0); // 10 itself is not above 10
  MOBIUS_CHECK(std::isnan(SummarizePairErrors({}).Mean));
}
}

int main()
{
  TestVertexDistances();
  TestLandmarks();
  TestCorridor();
  TestNearestCorner();
  TestScoreSamples();
  TestShortenedPairs();
  TestPairSummary();
  return MOBIUS_TEST_RESULT();
}
