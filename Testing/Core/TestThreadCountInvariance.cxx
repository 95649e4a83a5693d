// Results do not depend on the thread count: the parallel stages split their work the same
// way on any number of threads and add partial results up in a fixed order, so 1, 2, 3 and 7
// threads give the same bits (not merely close values). Checked on the rasterizer (several
// parts of triangles), the whole scale-factor signal, the SO(3) correlation (grid search over
// split slices, peaks refined in batches, both determinant classes) and point location.
#include "CoreTest.h"
#include "Icosphere.h"
#include "SO3Correlation.h"
#include "ScaleFactorSignal.h"
#include "SphericalAreaGrid.h"
#include "SphericalPointLocator.h"

#include <cstring>
#include <random>
#include <vector>

using namespace mobius;

namespace
{
const int ThreadCounts[] = { 1, 2, 3, 7 };

bool SameBits(const double* a, const double* b, std::size_t count)
{
  return std::memcmp(a, b, count * sizeof(double)) == 0;
}

// An icosphere of 20480 triangles (more than one rasterizer part) with uneven areas, its
// vertices pulled toward a pole so that the scale factors vary.
struct TestMap
{
  Points Sphere;
  Triangles Faces;
  Vector Areas;
};

TestMap MakeMap()
{
  TestMap map;
  MakeIcosphere(5, map.Sphere, map.Faces);
  for (Eigen::Index v = 0; v < map.Sphere.rows(); ++v)
  {
    Eigen::Vector3d p = map.Sphere.row(v).transpose();
    p.z() += 0.4 * (1.0 + p.z()) * p.x() * p.x();
    map.Sphere.row(v) = p.normalized().transpose();
  }
  std::mt19937 random(14);
  std::uniform_real_distribution<double> area(0.5, 2.0);
  map.Areas.resize(map.Faces.rows());
  for (Eigen::Index t = 0; t < map.Faces.rows(); ++t)
  {
    map.Areas[t] = area(random) * (1.0 + map.Sphere(map.Faces(t, 0), 0));
  }
  return map;
}

void RasterizerAndSignal(const TestMap& map)
{
  MOBIUS_CHECK(map.Faces.rows() > 2 * 4096);
  SphericalAreaGridResult reference;
  ScaleFactorSignal referenceSignal;
  for (int threads : ThreadCounts)
  {
    SphericalAreaGridResult grid;
    std::string error;
    MOBIUS_CHECK(RasterizeSphericalAreas(map.Sphere, map.Faces, map.Areas, 64,
      ScaleFactorValue::SquareRootAreaRatio, grid, error, {}, threads));
    ScaleFactorSignalParameters parameters;
    parameters.Resolution = 64;
    parameters.NumberOfThreads = threads;
    ScaleFactorSignal signal;
    MOBIUS_CHECK(ComputeScaleFactorSignal(
      map.Sphere, map.Faces, map.Areas, parameters, true, signal, error));
    if (threads == 1)
    {
      reference = grid;
      referenceSignal = signal;
      continue;
    }
    MOBIUS_CHECK(grid.Values.size() == reference.Values.size() &&
      SameBits(grid.Values.data(), reference.Values.data(), grid.Values.size()));
    const auto& c = signal.Coefficients.Values;
    const auto& r = referenceSignal.Coefficients.Values;
    MOBIUS_CHECK(c.size() == r.size() &&
      SameBits(reinterpret_cast<const double*>(c.data()), reinterpret_cast<const double*>(r.data()),
        2 * c.size()));
    MOBIUS_CHECK(SameBits(signal.SmoothedValues.data(), referenceSignal.SmoothedValues.data(),
      signal.SmoothedValues.size()));
  }
}

SphericalHarmonicCoefficients RandomSignal(int bandwidth, std::mt19937& random)
{
  std::normal_distribution<double> normal;
  SphericalHarmonicCoefficients c;
  c.Resize(bandwidth);
  for (int l = 0; l < bandwidth; ++l)
  {
    const double size = 1.0 / (1 + l);
    c(l, 0) = size * normal(random);
    for (int m = 1; m <= l; ++m)
    {
      c(l, m) = size * std::complex<double>(normal(random), normal(random));
      c(l, -m) = ((m & 1) ? -1.0 : 1.0) * std::conj(c(l, m));
    }
  }
  return c;
}

// Random signals have many peaks of similar height: the batches of refined peaks and the
// slices' best-peak lists are exercised.
void Correlation()
{
  std::mt19937 random(2018);
  const SphericalHarmonicCoefficients f = RandomSignal(32, random);
  const SphericalHarmonicCoefficients g = RandomSignal(32, random);
  SO3CorrelationResult reference;
  for (int threads : ThreadCounts)
  {
    SO3CorrelationOptions options;
    options.NumberOfCandidates = 8;
    options.Reflections = SO3ReflectionMode::Both;
    options.NumberOfThreads = threads;
    const SO3CorrelationResult result = CorrelateOverRotations(f, g, options);
    MOBIUS_CHECK(result.Candidates.size() == 8);
    if (threads == 1)
    {
      reference = result;
      continue;
    }
    MOBIUS_CHECK(result.Candidates.size() == reference.Candidates.size());
    for (std::size_t k = 0; k < result.Candidates.size() && k < reference.Candidates.size(); ++k)
    {
      const SO3Candidate& a = result.Candidates[k];
      const SO3Candidate& b = reference.Candidates[k];
      MOBIUS_CHECK(SameBits(a.Transform.data(), b.Transform.data(), 9));
      MOBIUS_CHECK(SameBits(&a.Score, &b.Score, 1));
      MOBIUS_CHECK(SameBits(&a.CorrelationCoefficient, &b.CorrelationCoefficient, 1));
    }
  }
}

void PointLocation(const TestMap& map)
{
  SphericalPointLocator locator;
  std::string error;
  MOBIUS_CHECK(locator.Build(map.Sphere, map.Faces, error));
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  Points queries(20000, 3);
  for (Eigen::Index i = 0; i < queries.rows(); ++i)
  {
    queries.row(i) = Eigen::RowVector3d(normal(random), normal(random), normal(random)).normalized();
  }
  std::vector<SphericalLocation> reference;
  MOBIUS_CHECK(locator.LocateAll(queries, reference, 1));
  for (int threads : { 2, 3, 7 })
  {
    std::vector<SphericalLocation> locations;
    MOBIUS_CHECK(locator.LocateAll(queries, locations, threads));
    bool same = locations.size() == reference.size();
    for (std::size_t i = 0; same && i < locations.size(); ++i)
    {
      same = locations[i].Triangle == reference[i].Triangle &&
        SameBits(locations[i].Barycentric.data(), reference[i].Barycentric.data(), 3);
    }
    MOBIUS_CHECK(same);
  }
}
}

int main()
{
  const TestMap map = MakeMap();
  RasterizerAndSignal(map);
  Correlation();
  PointLocation(map);
  return MOBIUS_TEST_RESULT();
}
