#include "MeanCurvature.h"

#include "CotangentLaplacian.h"

#include <Eigen/IterativeLinearSolvers>

#include <algorithm>
#include <cmath>

namespace mobius
{
namespace
{
// Mean curvature of one vertex is |L x| / (2 area); a few needle or folded vertices can give
// values far beyond any real feature: they are clamped to this (a sphere of radius 1/50 of
// sqrt(area)) before the diffusion spreads them.
constexpr double kCurvatureBound = 50.0;
}

Vector SmoothedMeanCurvature(const Points& points, const Triangles& triangles, double smoothingTime)
{
  const Vector areas = TriangleAreas(points, triangles);
  const double area = areas.sum();
  if (!(area > 0) || !std::isfinite(area))
  {
    return Vector();
  }
  const Points unit = points / std::sqrt(area);
  SparseMatrix stiffness;
  CotangentStiffnessInfo info;
  if (!BuildCotangentStiffness(unit, triangles, true, stiffness, info))
  {
    return Vector();
  }
  const Vector mass = LumpedMass(unit, triangles);
  const Points normals = AreaWeightedVertexNormals(unit, triangles);
  // L x = 2 H M n (L positive semi-definite, M the vertex areas, n outward).
  const Points curvatureNormal = stiffness * unit;
  Vector curvature(points.rows());
  for (Index i = 0; i < points.rows(); ++i)
  {
    const double h = mass[i] > 0 ? curvatureNormal.row(i).dot(normals.row(i)) / (2 * mass[i]) : 0;
    curvature[i] = std::clamp(std::isfinite(h) ? h : 0.0, -kCurvatureBound, kCurvatureBound);
  }
  // One implicit heat step: (M + t L) h = M H. Well conditioned for the small times used
  // here, so conjugate gradients converge in a few dozen iterations on any mesh size.
  SparseMatrix system = smoothingTime * stiffness;
  for (Index i = 0; i < points.rows(); ++i)
  {
    system.coeffRef(i, i) += mass[i];
  }
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper> solver;
  solver.setTolerance(1e-8);
  solver.compute(system);
  const Vector smoothed = solver.solve(mass.cwiseProduct(curvature));
  return smoothed.allFinite() ? smoothed : Vector();
}
}
