#include "MeanCurvature.h"

#include "CotangentLaplacian.h"

#include <Eigen/IterativeLinearSolvers>

#include <cmath>

namespace mobius
{
Vector SmoothedMeanCurvature(const Points& points, const Triangles& triangles, double smoothingTime)
{
  return SmoothedMeanCurvatures(points, triangles,
    { { smoothingTime, kCandidateCurvature.Bound, kCandidateCurvature.Range } }).front();
}

std::vector<Vector> SmoothedMeanCurvatures(
  const Points& points, const Triangles& triangles, const std::vector<CurvatureScale>& scales)
{
  std::vector<Vector> smoothed(scales.size());
  const Vector areas = TriangleAreas(points, triangles);
  const double area = areas.sum();
  if (!(area > 0) || !std::isfinite(area))
  {
    return smoothed;
  }
  const Points unit = points / std::sqrt(area);
  SparseMatrix stiffness;
  CotangentStiffnessInfo info;
  if (!BuildCotangentStiffness(unit, triangles, true, stiffness, info))
  {
    return smoothed;
  }
  const Vector mass = LumpedMass(unit, triangles);
  const Points normals = AreaWeightedVertexNormals(unit, triangles);
  // L x = 2 H M n (L positive semi-definite, M the vertex areas, n outward).
  const Points curvatureNormal = stiffness * unit;
  Vector curvature(points.rows());
  for (Index i = 0; i < points.rows(); ++i)
  {
    const double h = mass[i] > 0 ? curvatureNormal.row(i).dot(normals.row(i)) / (2 * mass[i]) : 0;
    curvature[i] = std::isfinite(h) ? h : 0.0;
  }
  // One implicit heat step per time: (M + t L) h = M H. Well conditioned for the small
  // times used here, so conjugate gradients converge in a few dozen iterations on any mesh
  // size.
  for (size_t k = 0; k < scales.size(); ++k)
  {
    const Vector weighted =
      mass.cwiseProduct(curvature.cwiseMax(-scales[k].Bound).cwiseMin(scales[k].Bound));
    SparseMatrix system = scales[k].SmoothingTime * stiffness;
    for (Index i = 0; i < points.rows(); ++i)
    {
      system.coeffRef(i, i) += mass[i];
    }
    Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper> solver;
    solver.setTolerance(1e-8);
    solver.compute(system);
    const Vector solution = solver.solve(weighted);
    if (solution.allFinite())
    {
      smoothed[k] = solution.cwiseMax(-scales[k].Range).cwiseMin(scales[k].Range);
    }
  }
  return smoothed;
}
}
