// NearestRowsByClusters returns exactly the nearest row, as an exhaustive search in double
// precision does, whatever the clusters: the cells of a surface-like point set (tight
// clusters, what the refinement gives it), clusters of random members (wide: few can be
// skipped), points in no cluster (-1), a single cluster, and queries far from every point.
// A search that skipped clusters by the centre distance alone, or by a bound not loosened for
// single precision, would return farther rows here.
#include "CoreTest.h"
#include "SpectralSearch.h"

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace mobius;

namespace
{
std::vector<Index> Exhaustive(const RowMatrix& queries, const RowMatrix& points)
{
  std::vector<Index> nearest(static_cast<size_t>(queries.rows()));
  for (Index q = 0; q < queries.rows(); ++q)
  {
    (points.rowwise() - queries.row(q)).rowwise().squaredNorm().minCoeff(&nearest[q]);
  }
  return nearest;
}

// Points on a closed 2-parameter sheet in `dimension` dimensions (smooth functions of two
// angles at growing frequencies, like the eigenfunctions of a torus), and the grid cell of
// each as its cluster.
RowMatrix SheetPoints(int side, int dimension, std::vector<Index>& cells)
{
  RowMatrix points(side * side, dimension);
  cells.resize(static_cast<size_t>(side * side));
  for (int i = 0; i < side; ++i)
  {
    for (int j = 0; j < side; ++j)
    {
      const double u = 2 * M_PI * i / side, v = 2 * M_PI * j / side;
      const Index row = i * side + j;
      for (int d = 0; d < dimension; ++d)
      {
        const double frequency = 1 + d / 4;
        points(row, d) = (d % 2 ? std::sin(frequency * u + d) : std::cos(frequency * v - d)) +
          0.3 * std::sin(u + v + d);
      }
      cells[static_cast<size_t>(row)] = (i / 5) * (side / 5) + j / 5;
    }
  }
  return points;
}

void CheckExact(const RowMatrix& queries, const RowMatrix& points,
  const std::vector<Index>& cluster, int threads)
{
  const std::vector<Index> expected = Exhaustive(queries, points);
  const std::vector<Index> found = NearestRowsByClusters(queries, points, cluster, threads);
  MOBIUS_CHECK(found.size() == expected.size());
  int wrong = 0;
  for (size_t q = 0; q < expected.size(); ++q)
  {
    wrong += found[q] != expected[q] ? 1 : 0;
  }
  MOBIUS_CHECK(wrong == 0);
}

void ExactForEveryClustering()
{
  std::vector<Index> cells;
  const RowMatrix points = SheetPoints(60, 40, cells);
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  // Queries near the sheet (a map's rows: near some point, none exactly on one) and far off.
  RowMatrix queries(700, points.cols());
  std::uniform_int_distribution<Index> anyPoint(0, points.rows() - 1);
  for (Index q = 0; q < queries.rows(); ++q)
  {
    const double spread = q < 600 ? 0.05 : 3.0;
    for (Index d = 0; d < points.cols(); ++d)
    {
      queries(q, d) = points(anyPoint(random), d) * (q < 600 ? 1.0 : 0.0) + spread * noise(random);
    }
  }
  CheckExact(queries, points, cells, 1);
  CheckExact(queries, points, cells, 3);

  std::vector<Index> scattered(cells.size());
  std::uniform_int_distribution<Index> anyCluster(0, 49);
  for (Index& c : scattered)
  {
    c = anyCluster(random);
  }
  CheckExact(queries, points, scattered, 2);

  std::vector<Index> some = cells;
  for (size_t p = 0; p < some.size(); p += 3)
  {
    some[p] = -1;
  }
  CheckExact(queries, points, some, 2);
  CheckExact(queries, points, std::vector<Index>(cells.size(), 0), 1);
}
}

int main()
{
  ExactForEveryClustering();
  return MOBIUS_TEST_RESULT();
}
