#include "SurfacePolish.h"

#include "CotangentLaplacian.h"
#include "ParallelFor.h"
#include "SparseCholesky.h"
#include "SurfaceWalk.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>

namespace mobius
{
namespace
{
double TotalArea(const Points& points, const Triangles& triangles)
{
  return TriangleAreas(points, triangles).sum();
}

// The rotation R maximizing tr(R^T A), refined from `start` by rotating it about the axis
// sum_c r_c x a_c (r_c, a_c: columns) until that torque vanishes (Müller, Bender, Chentanez &
// Macklin, "A robust method to extract the rotational part of deformations", 2016). Warm
// started from the previous iteration's rotation it needs a few steps, where an SVD per
// vertex and iteration was most of the polish's time. The first iteration, whose start may
// be any rotation (the copy's), takes the SVD.
constexpr int kRotationSteps = 4;
Eigen::Matrix3d NearestRotation(const Eigen::Matrix3d& a, const Eigen::Matrix3d& start)
{
  Eigen::Quaterniond q(start);
  for (int step = 0; step < kRotationSteps; ++step)
  {
    const Eigen::Matrix3d r = q.toRotationMatrix();
    const Eigen::Vector3d torque =
      r.col(0).cross(a.col(0)) + r.col(1).cross(a.col(1)) + r.col(2).cross(a.col(2));
    const double scale =
      std::abs(r.col(0).dot(a.col(0)) + r.col(1).dot(a.col(1)) + r.col(2).dot(a.col(2))) +
      1e-9 * a.norm() + 1e-300;
    const Eigen::Vector3d omega = torque / scale;
    const double angle = omega.norm();
    if (angle < 1e-6)
    {
      break;
    }
    q = Eigen::Quaterniond(Eigen::AngleAxisd(angle, omega / angle)) * q;
    q.normalize();
  }
  return q.toRotationMatrix();
}

// ARAP edges with their weights, per vertex, from the stiffness matrix's off-diagonal entries
// (the intrinsic Delaunay edges: non-negative weights; a non-mesh edge's vector is the chord
// between its ends, as rigid as any other).
struct WeightedNeighbors
{
  std::vector<Index> Offsets;
  std::vector<Index> Items;
  std::vector<double> Weights;
};

WeightedNeighbors NeighborsOf(const SparseMatrix& stiffness)
{
  WeightedNeighbors neighbors;
  neighbors.Offsets.assign(static_cast<size_t>(stiffness.cols()) + 1, 0);
  for (Index j = 0; j < stiffness.outerSize(); ++j)
  {
    for (SparseMatrix::InnerIterator it(stiffness, j); it; ++it)
    {
      if (it.row() != j && it.value() != 0)
      {
        neighbors.Items.push_back(it.row());
        neighbors.Weights.push_back(std::max(0.0, -it.value()));
      }
    }
    neighbors.Offsets[j + 1] = static_cast<Index>(neighbors.Items.size());
  }
  return neighbors;
}
}

bool PolishSurfaceMap(const Points& sourcePoints, const Triangles& sourceTriangles,
  const Points& targetPoints, const Triangles& targetTriangles,
  const VertexLists& targetVertexTriangles, std::vector<Index>& triangle,
  std::vector<Eigen::Vector3d>& barycentric, const SurfacePolishParameters& parameters,
  SurfacePolishInfo& info)
{
  const Index n = sourcePoints.rows();
  info = SurfacePolishInfo();
  const double sourceArea = TotalArea(sourcePoints, sourceTriangles);
  const double targetArea = TotalArea(targetPoints, targetTriangles);
  if (n == 0 || !(sourceArea > 0) || !(targetArea > 0))
  {
    info.Error = "a surface has no area";
    return false;
  }
  // The source at the target's scale: an isometric copy is then rigid, not just similar.
  Points x = sourcePoints * std::sqrt(targetArea / sourceArea);
  if (parameters.ReverseOrientation)
  {
    // A map that reverses orientation (a mirror self-map) is a rotation of the mirrored
    // source; ARAP's rotations could not follow it otherwise.
    x.col(0) *= -1;
  }
  SparseMatrix system;
  CotangentStiffnessInfo stiffnessInfo;
  if (!BuildCotangentStiffness(x, sourceTriangles, true, system, stiffnessInfo))
  {
    info.Error = stiffnessInfo.Error;
    return false;
  }
  const WeightedNeighbors neighbors = NeighborsOf(system);
  Vector area = LumpedMass(x, sourceTriangles);
  area *= static_cast<double>(n) / area.sum();
  const double pull = parameters.Fit + parameters.Anchor;
  for (Index i = 0; i < n; ++i)
  {
    system.coeffRef(i, i) += pull * area[i];
  }
  for (const auto& pin : parameters.Pinned)
  {
    system.coeffRef(pin.first, pin.first) += parameters.PinWeight * parameters.Fit * area[pin.first];
  }
  SparseCholesky cholesky;
  if (!cholesky.Analyze(system) || !cholesky.Factorize(system))
  {
    info.Error = "the polish's system could not be factored";
    return false;
  }

  const SurfaceWalker target{ targetPoints, targetTriangles, targetVertexTriangles };
  // Outward normals: mirroring the points turned the triangles' normals inwards.
  Points sourceNormals = AreaWeightedVertexNormals(x, sourceTriangles);
  if (parameters.ReverseOrientation)
  {
    sourceNormals *= -1;
  }
  const double reject = parameters.RejectDistance * MeanEdgeLength(targetPoints, targetTriangles);
  const double reject2 = reject * reject;
  // Row-major with 3 fixed columns, like Points: the per-edge products stay fixed-size.
  Points spectral(n, 3);
  for (Index i = 0; i < n; ++i)
  {
    spectral.row(i) = target.Point(triangle[i], barycentric[i]).transpose();
  }
  Points y = spectral, lastSolved = spectral;
  std::vector<Index> current = triangle;
  std::vector<Eigen::Matrix3d> rotations(static_cast<size_t>(n), Eigen::Matrix3d::Identity());
  std::vector<char> trusted(static_cast<size_t>(n), 1);
  const int threads = ResolveThreadCount(parameters.NumberOfThreads);

  for (int iteration = 0; iteration < parameters.Iterations; ++iteration)
  {
    Eigen::MatrixXd rhs(n, 3); // column-major, as the solver takes it
    ParallelForChunks<Index>(n, 512, threads, [&](Index begin, Index end) {
      for (Index i = begin; i < end; ++i)
      {
        // ARAP local step: the rotation taking the source's edge vectors around i closest
        // to the current ones, i.e. maximizing tr(R^T A), A = sum_j w_ij y_ij x_ij^T.
        Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
        for (Index k = neighbors.Offsets[i]; k < neighbors.Offsets[i + 1]; ++k)
        {
          const Index j = neighbors.Items[k];
          covariance += neighbors.Weights[k] * (y.row(j) - y.row(i)).transpose() * (x.row(j) - x.row(i));
        }
        Eigen::Matrix3d r;
        if (iteration == 0)
        {
          const Eigen::JacobiSVD<Eigen::Matrix3d> svd(
            covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
          Eigen::Matrix3d u = svd.matrixU();
          if ((u * svd.matrixV().transpose()).determinant() < 0)
          {
            u.col(2) *= -1;
          }
          r = u * svd.matrixV().transpose();
        }
        else
        {
          r = NearestRotation(covariance, rotations[i]);
        }
        rotations[i] = r;

        // The closest target point, if it can be trusted; else y_i itself.
        const Eigen::Vector3d q = y.row(i).transpose();
        Eigen::Vector3d weights;
        const double d2 = target.Walk(q, current[i], weights, true);
        const Index t = current[i];
        const Eigen::Vector3d a = targetPoints.row(targetTriangles(t, 0)).transpose(),
                              b = targetPoints.row(targetTriangles(t, 1)).transpose(),
                              c = targetPoints.row(targetTriangles(t, 2)).transpose();
        const Eigen::Vector3d faceNormal = (b - a).cross(c - a).normalized();
        const double facing = faceNormal.dot(r * sourceNormals.row(i).transpose());
        trusted[i] = d2 <= reject2 && facing >= parameters.MinimumNormalCosine ? 1 : 0;
        const Eigen::Vector3d closest = trusted[i] ? target.Point(t, weights) : q;
        rhs.row(i) = area[i] *
          (parameters.Fit * closest + parameters.Anchor * spectral.row(i).transpose()).transpose();
      }
    });
    for (const auto& pin : parameters.Pinned)
    {
      rhs.row(pin.first) += parameters.PinWeight * parameters.Fit * area[pin.first] *
        targetPoints.row(pin.second);
    }
    // ARAP global step's right-hand side: sum_j w_ij (R_i + R_j) / 2 (x_i - x_j).
    ParallelForChunks<Index>(n, 512, threads, [&](Index begin, Index end) {
      for (Index i = begin; i < end; ++i)
      {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for (Index k = neighbors.Offsets[i]; k < neighbors.Offsets[i + 1]; ++k)
        {
          const Index j = neighbors.Items[k];
          sum += 0.5 * neighbors.Weights[k] * (rotations[i] + rotations[j]) *
            (x.row(i) - x.row(j)).transpose();
        }
        rhs.row(i) += sum.transpose();
      }
    });
    const Points solved = cholesky.Solve(rhs);
    y = iteration > 0 ? Points(solved + parameters.Momentum * (solved - lastSolved)) : solved;
    lastSolved = solved;
  }

  // The last solution itself, not its extrapolation, onto the target.
  std::vector<char> kept(static_cast<size_t>(n), 0);
  ParallelForChunks<Index>(n, 512, threads, [&](Index begin, Index end) {
    for (Index i = begin; i < end; ++i)
    {
      Index t = current[i];
      Eigen::Vector3d weights;
      if (lastSolved.row(i).allFinite() &&
        target.Walk(lastSolved.row(i).transpose(), t, weights) <= reject2)
      {
        triangle[i] = t;
        barycentric[i] = weights;
      }
      else
      {
        kept[i] = 1; // far from the target: its spectral point stays
      }
    }
  });
  // A landmark ends on its target vertex itself, a corner of a triangle around it.
  for (const auto& pin : parameters.Pinned)
  {
    PlaceAtVertex(targetTriangles, targetVertexTriangles, pin.second, triangle[pin.first],
      barycentric[pin.first]);
  }
  const Index rejected = std::count(trusted.begin(), trusted.end(), 0);
  const Index keptSpectral = std::count(kept.begin(), kept.end(), 1);
  info.Rejected = rejected;
  info.KeptSpectral = keptSpectral;
  return true;
}
}
