#include "Curvature.h"

#include "CotangentLaplacian.h"
#include "PortableMath.h"

#include <Eigen/Geometry>
#include <Eigen/IterativeLinearSolvers>

#include <algorithm>
#include <cmath>

namespace mobius
{
namespace
{
// Per vertex, the mean curvature H of the unit-area surface: L x = 2 H M n (L positive
// semi-definite, M the vertex areas, n outward).
Vector VertexMeanCurvature(const Points& unit, const Triangles& triangles,
  const SparseMatrix& stiffness, const Vector& mass)
{
  const Points normals = AreaWeightedVertexNormals(unit, triangles);
  const Points curvatureNormal = stiffness * unit;
  Vector curvature(unit.rows());
  for (Index i = 0; i < unit.rows(); ++i)
  {
    const double h = mass[i] > 0 ? curvatureNormal.row(i).dot(normals.row(i)) / (2 * mass[i]) : 0;
    curvature[i] = std::isfinite(h) ? h : 0.0;
  }
  return curvature;
}

// Per vertex, the Gaussian curvature K of the unit-area surface: its angle defect, 2 pi less
// the angles of its triangles there, over its area. The angles come from PortableAtan2, the
// same bits on every CPU: the polish matches this curvature, and std::atan2's last bit,
// which depends on the CPU, moved polished maps by up to 0.1 sqrt(area).
Vector VertexGaussianCurvature(const Points& unit, const Triangles& triangles, const Vector& mass)
{
  Vector defect = Vector::Constant(unit.rows(), 2 * M_PI);
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      const Eigen::Vector3d corner = unit.row(triangles(t, c)).transpose();
      const Eigen::Vector3d u = unit.row(triangles(t, (c + 1) % 3)).transpose() - corner;
      const Eigen::Vector3d v = unit.row(triangles(t, (c + 2) % 3)).transpose() - corner;
      defect[triangles(t, c)] -= PortableAtan2(u.cross(v).norm(), u.dot(v));
    }
  }
  Vector curvature(unit.rows());
  for (Index i = 0; i < unit.rows(); ++i)
  {
    const double k = mass[i] > 0 ? defect[i] / mass[i] : 0.0;
    curvature[i] = std::isfinite(k) ? k : 0.0;
  }
  return curvature;
}

Vector SignedRoot(const Vector& values)
{
  return values.unaryExpr([](double v) { return std::copysign(std::sqrt(std::abs(v)), v); });
}
}

Vector SmoothedMeanCurvature(const Points& points, const Triangles& triangles, double smoothingTime)
{
  return SmoothedCurvatures(points, triangles,
    { { smoothingTime, kCandidateCurvature.Bound, kCandidateCurvature.Range } }).front();
}

std::vector<Vector> SmoothedCurvatures(
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
  Vector mean, gaussian; // each computed when a scale first asks for it
  // Implicit heat steps: (M + (t / steps) L) h' = M h, from h = H. Well conditioned for the
  // small times used here, so conjugate gradients converge in a few dozen iterations on any
  // mesh size.
  for (size_t k = 0; k < scales.size(); ++k)
  {
    const bool isMean = scales[k].Kind == CurvatureKind::Mean;
    Vector& curvature = isMean ? mean : gaussian;
    if (curvature.size() == 0)
    {
      curvature = isMean ? VertexMeanCurvature(unit, triangles, stiffness, mass)
                         : VertexGaussianCurvature(unit, triangles, mass);
    }
    const Vector weighted =
      mass.cwiseProduct(curvature.cwiseMax(-scales[k].Bound).cwiseMin(scales[k].Bound));
    const int steps = std::max(1, scales[k].Steps);
    SparseMatrix system = (scales[k].SmoothingTime / steps) * stiffness;
    for (Index i = 0; i < points.rows(); ++i)
    {
      system.coeffRef(i, i) += mass[i];
    }
    Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper> solver;
    solver.setTolerance(1e-8);
    solver.compute(system);
    Vector solution = solver.solve(weighted);
    for (int step = 1; step < steps; ++step)
    {
      // From the last step's solution, which each step changes less.
      solution = solver.solveWithGuess(Vector(mass.cwiseProduct(solution)), solution);
    }
    if (!isMean)
    {
      solution = SignedRoot(solution);
    }
    if (solution.allFinite())
    {
      smoothed[k] = solution.cwiseMax(-scales[k].Range).cwiseMin(scales[k].Range);
    }
  }
  return smoothed;
}
}
