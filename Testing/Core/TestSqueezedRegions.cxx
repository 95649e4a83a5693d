// The conformal map's thin parts: nested frames that keep offsets far below double
// precision on the unit sphere, the spreading of tips no double can hold, the robust
// distortion figures, and the rule that refuses or warns about a map.
#include "ConformalMap.h"
#include "CoreTest.h"
#include "MapDistortion.h"
#include "MapVerdict.h"
#include "NestedFrames.h"

#include <cmath>
#include <string>
#include <vector>

using namespace mobius;

namespace
{
// A closed tube of radius `radius` and length `length` along z, `around` vertices per ring,
// rings about as far apart as the vertices around, each end closed by a fan around a vertex.
void CappedTube(double radius, double length, int around, Points& p, Triangles& t)
{
  const double spacing = 2.0 * M_PI * radius / around;
  const int rings = static_cast<int>(std::ceil(length / spacing)) + 1;
  p.resize(rings * around + 2, 3);
  for (int r = 0; r < rings; ++r)
  {
    for (int k = 0; k < around; ++k)
    {
      const double angle = 2.0 * M_PI * (k + 0.5 * (r % 2)) / around; // staggered rings
      p.row(r * around + k) << radius * std::cos(angle), radius * std::sin(angle), length * r / (rings - 1);
    }
  }
  const Index bottom = rings * around, top = bottom + 1;
  p.row(bottom) << 0.0, 0.0, -0.5 * spacing;
  p.row(top) << 0.0, 0.0, length + 0.5 * spacing;
  std::vector<Eigen::Vector3i> faces;
  for (int r = 0; r + 1 < rings; ++r)
  {
    for (int k = 0; k < around; ++k)
    {
      const int a = r * around + k, b = r * around + (k + 1) % around;
      const int c = (r + 1) * around + k, d = (r + 1) * around + (k + 1) % around;
      if (r % 2 == 0)
      {
        faces.emplace_back(a, b, c);
        faces.emplace_back(b, d, c);
      }
      else
      {
        faces.emplace_back(a, b, d);
        faces.emplace_back(a, d, c);
      }
    }
  }
  for (int k = 0; k < around; ++k)
  {
    faces.emplace_back(static_cast<int>(bottom), (k + 1) % around, k);
    const int last = (rings - 1) * around;
    faces.emplace_back(static_cast<int>(top), last + k, last + (k + 1) % around);
  }
  t.resize(static_cast<Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f)
  {
    t.row(static_cast<Index>(f)) = faces[f].cast<Index>().transpose();
  }
}

// Two vertices 3e-40 apart inside a region that moved by 1e-20, at a point of the sphere
// with no coordinate near 0: double-double positions lose that (their low part holds 1e-20 to
// 1e-36), the nested levels keep it exactly.
void TestNestedFrames()
{
  Points sphere(4, 3);
  sphere << 0.6, 0.8, 0, 0.6, 0.8, 0, 0, 0, 1, -1, 0, 0;
  NestedFrames frames(sphere);
  Eigen::MatrixXd offsets(2, 3);
  offsets << 1e-20, 1e-20, 0, 1e-20, 1e-20, 0; // both move by (1e-20, 1e-20, 0)
  frames.AddLevel({ 0, 1 }, { 0, 0 }, { 0 }, offsets);
  offsets << 0, 0, 0, 0, 3e-40, 0; // relative to vertex 0 as it now is
  frames.AddLevel({ 0, 1 }, { 0, 0 }, { 0 }, offsets);
  const Eigen::RowVector3d d = frames.Difference(1, 0);
  MOBIUS_CHECK(d[0] == 0.0 && d[1] == 3e-40 && d[2] == 0.0);
  MOBIUS_CHECK(frames.Absolute().Difference(1, 0).norm() < 1e-41);
  MOBIUS_CHECK_NEAR(frames.Absolute().Difference(0, 2)[0], 0.6 + 1e-20, 1e-16);
  // A vertex outside the levels: from the absolute positions.
  MOBIUS_CHECK_NEAR(frames.Difference(2, 3).norm(), std::sqrt(2.0), 1e-15);
}

// A tube 160 radii long: the conformal map squeezes each end to about e^-80 (1e-35) of the
// sphere, beyond double-double's 1e-32 and far beyond a double's 1e-16. The map must come out
// with no fold, the tips spread to resolvable size.
void TestThinTube()
{
  Points p;
  Triangles t;
  CappedTube(0.05, 8.0, 12, p, t);
  const ConformalMapResult result = ComputeSphericalConformalMap(p, t);
  MOBIUS_CHECK(result.Success);
  if (!result.Success)
  {
    std::cerr << result.Message << "\n";
    return;
  }
  std::cout << "tube: smallest edge before spreading " << result.Refinement.SmallestEdge
            << ", levels " << result.Refinement.Levels << ", tips spread "
            << result.Refinement.Spreading.SpreadTips << " (exponent "
            << result.Refinement.Spreading.SmallestExponent << "), flips "
            << result.Distortion.FlippedTriangles << ", median QC "
            << result.Distortion.MedianQuasiConformal << "\n";
  MOBIUS_CHECK(result.Refinement.SmallestEdge < 1e-32);
  MOBIUS_CHECK(result.Refinement.Spreading.SpreadTips >= 2);
  MOBIUS_CHECK(result.Refinement.Spreading.UnresolvedEdges == 0);
  MOBIUS_CHECK(result.Distortion.FlippedTriangles == 0);
  MOBIUS_CHECK(result.Distortion.SmallestMappedAreaShare > 1e-32);
  MOBIUS_CHECK(!JudgeConformalMap(result, 1e-4).Degenerate());
}

// Two triangles mapped by known linear maps: a similarity (QC 1) on area 3, a stretch by 20 in
// one direction (QC 20) on area 1.
void TestDistortionFigures()
{
  Points original(6, 3), mapped(6, 3);
  original << 0, 0, 0, 3, 0, 0, 0, 2, 0, 10, 0, 0, 11, 0, 0, 10, 2, 0;
  mapped = original;
  mapped.row(4) << 10 + 20, 0, 0; // the second triangle stretched along x
  Triangles t(2, 3);
  t << 0, 1, 2, 3, 4, 5;
  const MapDistortion d = MeasureMapDistortion(original, mapped, t);
  MOBIUS_CHECK_NEAR(d.MedianQuasiConformal, 1.0, 1e-12);
  MOBIUS_CHECK_NEAR(d.P95QuasiConformal, 20.0, 1e-9);
  MOBIUS_CHECK_NEAR(d.MeanQuasiConformal, (3 * 1.0 + 1 * 20.0) / 4, 1e-9);
  MOBIUS_CHECK_NEAR(d.SquashedAreaShare, 0.25, 1e-12);
}

// The rule: squashed more than half the surface, or folded: refused; squashed more than 1%:
// a warning naming the share; a huge mean alone: nothing.
void TestVerdict()
{
  ConformalMapResult result;
  result.Success = true;
  result.Converged = true;
  result.Distortion.MeanQuasiConformal = 1e7; // a tail squeezed to a speck
  result.Distortion.MedianQuasiConformal = 1.1;
  result.Distortion.SquashedAreaShare = 0.003;
  MapVerdict verdict = JudgeConformalMap(result, 1e-4);
  MOBIUS_CHECK(!verdict.Degenerate() && verdict.Warning.empty());
  result.Distortion.SquashedAreaShare = 0.04;
  verdict = JudgeConformalMap(result, 1e-4);
  MOBIUS_CHECK(!verdict.Degenerate());
  MOBIUS_CHECK(verdict.Warning.find("4% of the surface") != std::string::npos);
  result.Distortion.SquashedAreaShare = 0.6;
  verdict = JudgeConformalMap(result, 1e-4);
  MOBIUS_CHECK(verdict.Degenerate() && verdict.Reason().find("squashed: 60%") != std::string::npos);
  result.Distortion.SquashedAreaShare = 0.0;
  result.Distortion.FlippedTriangles = 3;
  verdict = JudgeConformalMap(result, 1e-4);
  MOBIUS_CHECK(verdict.Degenerate() && verdict.Reason().find("3 triangles are flipped") != std::string::npos);
}
}

int main()
{
  TestNestedFrames();
  TestDistortionFigures();
  TestVerdict();
  TestThinTube();
  return MOBIUS_TEST_RESULT();
}
