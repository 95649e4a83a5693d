#include "SurfacePolish.h"

#include "CotangentLaplacian.h"
#include "ParallelFor.h"
#include "SparseCholesky.h"
#include "SurfaceWalk.h"

#include <Eigen/Cholesky>
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

// The rotation R maximizing f(R) = tr(R^T A), one Newton step on from the unit quaternion
// q (which it updates; r is its matrix, as the last step returned it) over rotations
// R <- exp([w]x) R. To second order f changes by w.t - w^T H w / 2 with the torque
// t = sum_c r_c x a_c (r_c, a_c: columns) and H = tr(P) I - (P + P^T) / 2, P = A R^T; the
// step is w = H^-1 t. Near the optimum P is
// A's symmetric polar factor and H's eigenvalues are sums of two of A's singular values:
// the steps converge quadratically, so one per iteration of the polish, warm started from
// the last, keeps up with its slowly moving A. (Müller, Bender, Chentanez & Macklin, "A
// robust method to extract the rotational part of deformations", 2016, take H = tr(P) I:
// on a flat fan of edges, one singular value near 0, that overestimates the curvature about
// two axes and converges only linearly. The polish took 4 such steps per iteration; with 2,
// its FAUST_r maps came out about 1% worse; one Newton step costs about as much as 2 of
// them.) Where H is not positive definite, far from the optimum, that scaled step is taken
// instead. The first iteration, whose start may be any rotation, takes an SVD.
Eigen::Matrix3d NearestRotation(
  const Eigen::Matrix3d& a, const Eigen::Matrix3d& r, Eigen::Quaterniond& q)
{
  const Eigen::Vector3d torque =
    r.col(0).cross(a.col(0)) + r.col(1).cross(a.col(1)) + r.col(2).cross(a.col(2));
  const Eigen::Matrix3d p = a * r.transpose();
  const double trace = p.trace();
  Eigen::Matrix3d hessian = -0.5 * (p + p.transpose());
  hessian.diagonal().array() += trace;
  const Eigen::LLT<Eigen::Matrix3d> newton(hessian);
  const Eigen::Vector3d omega = newton.info() == Eigen::Success
    ? Eigen::Vector3d(newton.solve(torque))
    : Eigen::Vector3d(torque / (std::abs(trace) + 1e-9 * a.norm() + 1e-300));
  if (!(omega.squaredNorm() >= 1e-18)) // converged (or A is 0, or not finite)
  {
    return r;
  }
  // exp(w / 2) to first order, normalized: the same fixed point, no trigonometry.
  q = Eigen::Quaterniond(1.0, 0.5 * omega.x(), 0.5 * omega.y(), 0.5 * omega.z()) * q;
  q.normalize();
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

// Per ARAP edge (as in WeightedNeighbors) its weighted source vector e_ij = w_ij (x_j - x_i),
// and per vertex their sum: both steps read them every iteration. Per vertex also
// sum_j w_ij |x_j - x_i|^2, the scale of its ARAP residual.
struct WeightedEdges
{
  std::vector<Eigen::Vector3d> Vectors;
  std::vector<Eigen::Vector3d> Sums;
  std::vector<double> SquaredLengths;
};

WeightedEdges WeightedEdgesOf(const WeightedNeighbors& neighbors, const Points& x)
{
  const Index n = x.rows();
  WeightedEdges edges;
  edges.Vectors.resize(neighbors.Items.size());
  edges.Sums.assign(static_cast<size_t>(n), Eigen::Vector3d::Zero());
  edges.SquaredLengths.assign(static_cast<size_t>(n), 0.0);
  for (Index i = 0; i < n; ++i)
  {
    for (Index k = neighbors.Offsets[i]; k < neighbors.Offsets[i + 1]; ++k)
    {
      const Eigen::Vector3d edge = (x.row(neighbors.Items[k]) - x.row(i)).transpose();
      edges.Vectors[k] = neighbors.Weights[k] * edge;
      edges.Sums[i] += edges.Vectors[k];
      edges.SquaredLengths[i] += edges.Vectors[k].dot(edge);
    }
  }
  return edges;
}

// Vertex i's ARAP residual relative to its edges' size, sum_j w_ij |y_ij - R x_ij|^2 over
// sum_j w_ij |x_ij|^2 (y_ij = y_j - y_i, likewise x_ij), given A = sum_j w_ij y_ij x_ij^T:
// expanded, sum_j w_ij |y_ij|^2 - 2 tr(R^T A) + sum_j w_ij |x_ij|^2.
double RelativeResidual(const WeightedNeighbors& neighbors, const WeightedEdges& edges,
  const Points& y, Index i, const Eigen::Matrix3d& r, const Eigen::Matrix3d& covariance)
{
  const double scale = edges.SquaredLengths[i];
  if (!(scale > 0))
  {
    return 0;
  }
  double deformed = 0;
  for (Index k = neighbors.Offsets[i]; k < neighbors.Offsets[i + 1]; ++k)
  {
    deformed += neighbors.Weights[k] * (y.row(neighbors.Items[k]) - y.row(i)).squaredNorm();
  }
  return std::max(0.0, deformed - 2 * (r.transpose() * covariance).trace() + scale) / scale;
}

// The polish's system matrix L + (fit + Anchor) D, landmarks held PinWeight times as hard.
SparseMatrix PolishSystem(const SparseMatrix& stiffness, const Vector& area, double fit,
  const SurfacePolishParameters& parameters)
{
  SparseMatrix system = stiffness;
  for (Index i = 0; i < system.rows(); ++i)
  {
    system.coeffRef(i, i) += (fit + parameters.Anchor) * area[i];
  }
  for (const auto& pin : parameters.Pinned)
  {
    system.coeffRef(pin.first, pin.first) += parameters.PinWeight * fit * area[pin.first];
  }
  return system;
}

// The Fit gain for the rest of the polish from its map's relative ARAP residuals (see
// SurfacePolish.h): their area-weighted mean over RigidResidual, between 1 and the maximum.
double FitGain(const std::vector<double>& residuals, const Vector& area,
  const SurfacePolishParameters& parameters, double& meanResidual)
{
  double sum = 0;
  for (size_t i = 0; i < residuals.size(); ++i)
  {
    sum += area[static_cast<Index>(i)] * residuals[i];
  }
  meanResidual = sum / area.sum();
  if (!(parameters.RigidResidual > 0) || !std::isfinite(meanResidual))
  {
    return 1.0;
  }
  return std::clamp(meanResidual / parameters.RigidResidual, 1.0,
    std::max(1.0, parameters.MaximumFitGain));
}

// A curvature the closest points are moved to match: both surfaces' values per vertex and
// the weight (in units of the target's lengths).
struct CurvatureTerm
{
  const Vector* Source;
  const Vector* Target;
  double Weight;
  size_t Curvature; ///< its entry of kPolishCurvatures
};

// Where the fit gained, each curvature's weight over the second half: its CurvatureWeights
// times the first of its GainedCurvatureScales to times the second, linearly in `progress`
// (0 to 1).
void ScheduleCurvatureWeights(const SurfacePolishParameters& parameters, double progress,
  double length, std::vector<CurvatureTerm>& terms)
{
  for (CurvatureTerm& term : terms)
  {
    const auto& [first, last] = parameters.GainedCurvatureScales[term.Curvature];
    term.Weight =
      parameters.CurvatureWeights[term.Curvature] * (first + (last - first) * progress) * length;
  }
}

constexpr int kCurvatureTerms = static_cast<int>(kPolishCurvatures.size());

// The step from the closest point c (in target triangle t, at barycentrics `weights`) that
// matches the curvatures h_k of source vertex i: minimizing
// |s|^2 + sum_k (r_k - a_k . s)^2 over steps s in the triangle's plane, with a_k = w_k g_k
// (g_k the gradient of h_k, linear there) and r_k = w_k (h_k,i - h_k(c)), gives
// (I + sum_k a_k a_k^T) s = sum_k r_k a_k. The solution lies in the span of the a_k: s = A x
// with (I + A^T A) x = r, a system of one row per curvature instead of 3. At most an edge
// long: beyond that the h_k are not linear any more.
Eigen::Vector3d CurvatureStep(const Points& targetPoints, const Triangles& targetTriangles,
  const std::vector<CurvatureTerm>& terms, Index i, Index t, const Eigen::Vector3d& weights,
  double maximumStep)
{
  const Eigen::Vector3d a = targetPoints.row(targetTriangles(t, 0)).transpose(),
                        b = targetPoints.row(targetTriangles(t, 1)).transpose(),
                        c = targetPoints.row(targetTriangles(t, 2)).transpose();
  const Eigen::Vector3d normal = (b - a).cross(c - a);
  const double doubleArea = normal.norm();
  if (!(doubleArea > 0))
  {
    return Eigen::Vector3d::Zero();
  }
  // The gradient of a linear interpolant: sum over corners of h_v (n x e_v) / 2A, e_v the
  // edge opposite v, counterclockwise.
  const Eigen::Vector3d unit = normal / doubleArea;
  const Eigen::Vector3d ea = unit.cross(c - b) / doubleArea, eb = unit.cross(a - c) / doubleArea,
                        ec = unit.cross(b - a) / doubleArea;
  using Gradients = Eigen::Matrix<double, 3, kCurvatureTerms>;
  using Mismatches = Eigen::Matrix<double, kCurvatureTerms, 1>;
  Gradients scaled = Gradients::Zero();
  Mismatches mismatch = Mismatches::Zero();
  for (size_t k = 0; k < terms.size(); ++k)
  {
    const Vector& h = *terms[k].Target;
    const double ha = h[targetTriangles(t, 0)], hb = h[targetTriangles(t, 1)],
                 hc = h[targetTriangles(t, 2)];
    scaled.col(k) = terms[k].Weight * (ha * ea + hb * eb + hc * ec);
    const double here = weights[0] * ha + weights[1] * hb + weights[2] * hc;
    mismatch[k] = terms[k].Weight * ((*terms[k].Source)[i] - here);
  }
  Eigen::Matrix<double, kCurvatureTerms, kCurvatureTerms> gram = scaled.transpose() * scaled;
  gram.diagonal().array() += 1.0; // positive definite
  Eigen::Vector3d step = scaled * gram.llt().solve(mismatch);
  const double length = step.norm();
  return length > maximumStep ? Eigen::Vector3d(step * (maximumStep / length)) : step;
}
}

namespace
{
// The curvatures the closest points match: those given for both surfaces.
std::vector<CurvatureTerm> CurvatureTermsOf(
  const SurfacePolishParameters& parameters, Index n, Index targetSize, double targetArea)
{
  std::vector<CurvatureTerm> terms;
  for (size_t k = 0; k < parameters.CurvatureWeights.size(); ++k)
  {
    if (parameters.CurvatureWeights[k] > 0 && k < parameters.SourceCurvatures.size() &&
      k < parameters.TargetCurvatures.size() && parameters.SourceCurvatures[k].size() == n &&
      parameters.TargetCurvatures[k].size() == targetSize)
    {
      terms.push_back({ &parameters.SourceCurvatures[k], &parameters.TargetCurvatures[k],
        parameters.CurvatureWeights[k] * std::sqrt(targetArea), k });
    }
  }
  return terms;
}

// The rotation of the first iteration, whose start may be any rotation: from an SVD.
Eigen::Matrix3d FirstRotation(const Eigen::Matrix3d& covariance, Eigen::Quaterniond& q)
{
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(
    covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d u = svd.matrixU();
  if ((u * svd.matrixV().transpose()).determinant() < 0)
  {
    u.col(2) *= -1;
  }
  const Eigen::Matrix3d r = u * svd.matrixV().transpose();
  q = Eigen::Quaterniond(r);
  return r;
}
}

// Everything the polish keeps from one iteration to the next.
struct SurfacePolisher::State
{
  State(const Points& targetPoints, const Triangles& targetTriangles,
    const VertexLists& targetVertexTriangles, const SurfacePolishParameters& parameters)
    : Parameters(parameters)
    , Target{ targetPoints, targetTriangles, targetVertexTriangles }
    , Cholesky(SparseCholesky::Use::ManySolves)
  {
  }

  const SurfacePolishParameters& Parameters;
  const SurfaceWalker Target;
  Index N = 0;
  double TargetArea = 0;
  double TargetEdge = 0;
  double Reject2 = 0; ///< squared distance beyond which a closest point is not trusted
  Points X;           ///< the source at the target's scale (mirrored for ReverseOrientation)
  Points SourceNormals;
  SparseMatrix Stiffness;
  WeightedNeighbors Neighbors;
  WeightedEdges Edges;
  Vector Area; ///< vertex area over mean vertex area
  double Fit = 0;
  SparseCholesky Cholesky;
  std::vector<CurvatureTerm> CurvatureTerms;
  std::vector<Index> SpectralTriangle; ///< the map at the start
  std::vector<Eigen::Vector3d> SpectralBarycentric;
  Points Spectral; ///< its points, which the anchor holds
  Points Y;        ///< the current iterate (the last solution pushed on by momentum)
  Points LastSolved;
  std::vector<Index> Current; ///< each vertex's last closest triangle
  std::vector<Eigen::Matrix3d> Rotations;
  std::vector<Eigen::Quaterniond> Quaternions;
  std::vector<char> Trusted;
  std::vector<double> Residuals;
  int Threads = 1;
  int Iteration = 0;
  SurfacePolishInfo Info;

  void LocalStep(int iteration, Eigen::MatrixXd& rhs);
  void AddRotatedEdges(Eigen::MatrixXd& rhs) const;
  bool MeasureRigidity();
};

// Per vertex: the ARAP rotation, and the right-hand side's pull towards the closest target
// point (moved to match the curvatures, if it can be trusted; else towards y_i itself) and
// the spectral point.
void SurfacePolisher::State::LocalStep(int iteration, Eigen::MatrixXd& rhs)
{
  const Points& targetPoints = this->Target.Positions;
  const Triangles& targetTriangles = this->Target.Faces;
  const bool measure = iteration == this->Parameters.Iterations / 2;
  ParallelForChunks<Index>(this->N, 512, this->Threads, [&](Index begin, Index end) {
    for (Index i = begin; i < end; ++i)
    {
      // ARAP local step: the rotation taking the source's edge vectors around i closest
      // to the current ones, i.e. maximizing tr(R^T A), A = sum_j w_ij y_ij x_ij^T.
      Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
      for (Index k = this->Neighbors.Offsets[i]; k < this->Neighbors.Offsets[i + 1]; ++k)
      {
        covariance += (this->Y.row(this->Neighbors.Items[k]) - this->Y.row(i)).transpose() *
          this->Edges.Vectors[k].transpose();
      }
      const Eigen::Matrix3d r = iteration == 0
        ? FirstRotation(covariance, this->Quaternions[i])
        : NearestRotation(covariance, this->Rotations[i], this->Quaternions[i]);
      this->Rotations[i] = r;
      if (measure)
      {
        this->Residuals[i] = RelativeResidual(this->Neighbors, this->Edges, this->Y, i, r, covariance);
      }

      const Eigen::Vector3d q = this->Y.row(i).transpose();
      Eigen::Vector3d weights;
      const double d2 = this->Target.Walk(q, this->Current[i], weights, true);
      const Index t = this->Current[i];
      const Eigen::Vector3d a = targetPoints.row(targetTriangles(t, 0)).transpose(),
                            b = targetPoints.row(targetTriangles(t, 1)).transpose(),
                            c = targetPoints.row(targetTriangles(t, 2)).transpose();
      const Eigen::Vector3d faceNormal = (b - a).cross(c - a).normalized();
      const double facing = faceNormal.dot(r * this->SourceNormals.row(i).transpose());
      this->Trusted[i] =
        d2 <= this->Reject2 && facing >= this->Parameters.MinimumNormalCosine ? 1 : 0;
      Eigen::Vector3d closest = this->Trusted[i] ? this->Target.Point(t, weights) : q;
      if (this->Trusted[i] && !this->CurvatureTerms.empty())
      {
        // Into the product of space and curvature: a step in the triangle's plane, at
        // most an edge long, so within a second-order distance of the surface.
        closest += CurvatureStep(
          targetPoints, targetTriangles, this->CurvatureTerms, i, t, weights, this->TargetEdge);
      }
      rhs.row(i) = this->Area[i] *
        (this->Fit * closest + this->Parameters.Anchor * this->Spectral.row(i).transpose())
          .transpose();
    }
  });
  for (const auto& pin : this->Parameters.Pinned)
  {
    rhs.row(pin.first) += this->Parameters.PinWeight * this->Fit * this->Area[pin.first] *
      targetPoints.row(pin.second);
  }
}

// ARAP global step's right-hand side: sum_j w_ij (R_i + R_j) / 2 (x_i - x_j)
// = -(R_i sum_j e_ij + sum_j R_j e_ij) / 2 with e_ij = w_ij (x_j - x_i).
void SurfacePolisher::State::AddRotatedEdges(Eigen::MatrixXd& rhs) const
{
  ParallelForChunks<Index>(this->N, 512, this->Threads, [&](Index begin, Index end) {
    for (Index i = begin; i < end; ++i)
    {
      Eigen::Vector3d sum = this->Rotations[i] * this->Edges.Sums[i];
      for (Index k = this->Neighbors.Offsets[i]; k < this->Neighbors.Offsets[i + 1]; ++k)
      {
        sum.noalias() += this->Rotations[this->Neighbors.Items[k]] * this->Edges.Vectors[k];
      }
      rhs.row(i) -= 0.5 * sum.transpose();
    }
  });
}

// Halfway: the Fit gain for the rest from the map's ARAP residuals, the system refactored
// if it gained. False if it could not be.
bool SurfacePolisher::State::MeasureRigidity()
{
  this->Info.FitGain = FitGain(this->Residuals, this->Area, this->Parameters, this->Info.RigidResidual);
  if (!(this->Info.FitGain > 1.0))
  {
    return true;
  }
  this->Fit = this->Parameters.Fit * this->Info.FitGain;
  return this->Cholesky.Factorize(
    PolishSystem(this->Stiffness, this->Area, this->Fit, this->Parameters));
}

namespace
{
const char* const kFactorError = "the polish's system could not be factored";
}

SurfacePolisher::SurfacePolisher() = default;
SurfacePolisher::~SurfacePolisher() = default;

bool SurfacePolisher::Start(const Points& sourcePoints, const Triangles& sourceTriangles,
  const Points& targetPoints, const Triangles& targetTriangles,
  const VertexLists& targetVertexTriangles, const std::vector<Index>& triangle,
  const std::vector<Eigen::Vector3d>& barycentric, const SurfacePolishParameters& parameters)
{
  this->Polish =
    std::make_unique<State>(targetPoints, targetTriangles, targetVertexTriangles, parameters);
  State& p = *this->Polish;
  const Index n = p.N = sourcePoints.rows();
  const double sourceArea = TotalArea(sourcePoints, sourceTriangles);
  p.TargetArea = TotalArea(targetPoints, targetTriangles);
  if (n == 0 || !(sourceArea > 0) || !(p.TargetArea > 0))
  {
    p.Info.Error = "a surface has no area";
    return false;
  }
  // The source at the target's scale: an isometric copy is then rigid, not just similar.
  p.X = sourcePoints * std::sqrt(p.TargetArea / sourceArea);
  if (parameters.ReverseOrientation)
  {
    // A map that reverses orientation (a mirror self-map) is a rotation of the mirrored
    // source; ARAP's rotations could not follow it otherwise.
    p.X.col(0) *= -1;
  }
  CotangentStiffnessInfo stiffnessInfo;
  if (!BuildCotangentStiffness(p.X, sourceTriangles, true, p.Stiffness, stiffnessInfo))
  {
    p.Info.Error = stiffnessInfo.Error;
    return false;
  }
  p.Neighbors = NeighborsOf(p.Stiffness);
  p.Area = LumpedMass(p.X, sourceTriangles);
  p.Area *= static_cast<double>(n) / p.Area.sum();
  p.Fit = parameters.Fit;
  const SparseMatrix system = PolishSystem(p.Stiffness, p.Area, p.Fit, parameters);
  if (!p.Cholesky.Analyze(system) || !p.Cholesky.Factorize(system))
  {
    p.Info.Error = kFactorError;
    return false;
  }
  // Outward normals: mirroring the points turned the triangles' normals inwards.
  p.SourceNormals = AreaWeightedVertexNormals(p.X, sourceTriangles);
  if (parameters.ReverseOrientation)
  {
    p.SourceNormals *= -1;
  }
  p.TargetEdge = MeanEdgeLength(targetPoints, targetTriangles);
  p.Reject2 = std::pow(parameters.RejectDistance * p.TargetEdge, 2);
  // Row-major with 3 fixed columns, like Points: the per-edge products stay fixed-size.
  p.Spectral.resize(n, 3);
  for (Index i = 0; i < n; ++i)
  {
    p.Spectral.row(i) = p.Target.Point(triangle[i], barycentric[i]).transpose();
  }
  p.SpectralTriangle = triangle;
  p.SpectralBarycentric = barycentric;
  p.Y = p.LastSolved = p.Spectral;
  p.Current = triangle;
  p.Rotations.assign(static_cast<size_t>(n), Eigen::Matrix3d::Identity());
  p.Quaternions.resize(static_cast<size_t>(n));
  p.Edges = WeightedEdgesOf(p.Neighbors, p.X);
  p.Trusted.assign(static_cast<size_t>(n), 1);
  p.Residuals.assign(static_cast<size_t>(n), 0.0);
  p.Threads = ResolveThreadCount(parameters.NumberOfThreads);
  p.CurvatureTerms = CurvatureTermsOf(parameters, n, targetPoints.rows(), p.TargetArea);
  return true;
}

bool SurfacePolisher::Iterate(int count)
{
  State& p = *this->Polish;
  if (!p.Info.Error.empty())
  {
    return false;
  }
  // Halfway, the map's ARAP residuals set how far the rigid prior is trusted after.
  const int measured = p.Parameters.Iterations / 2;
  const int last = std::min(p.Parameters.Iterations, p.Iteration + std::max(0, count));
  for (; p.Iteration < last; ++p.Iteration)
  {
    const int iteration = p.Iteration;
    if (iteration > measured && p.Info.FitGain > 1.0)
    {
      const double progress = static_cast<double>(iteration - measured) /
        std::max(1, p.Parameters.Iterations - 1 - measured);
      ScheduleCurvatureWeights(p.Parameters, progress, std::sqrt(p.TargetArea), p.CurvatureTerms);
    }
    Eigen::MatrixXd rhs(p.N, 3); // column-major, as the solver takes it
    p.LocalStep(iteration, rhs);
    p.AddRotatedEdges(rhs);
    const Points solved = p.Cholesky.Solve(rhs);
    p.Y = iteration > 0 ? Points(solved + p.Parameters.Momentum * (solved - p.LastSolved)) : solved;
    p.LastSolved = solved;
    if (iteration == measured && !p.MeasureRigidity())
    {
      p.Info.Error = kFactorError;
      return false;
    }
  }
  return true;
}

int SurfacePolisher::Iterations() const
{
  return this->Polish ? this->Polish->Iteration : 0;
}

void SurfacePolisher::CurrentMap(
  std::vector<Index>& triangle, std::vector<Eigen::Vector3d>& barycentric)
{
  State& p = *this->Polish;
  triangle.resize(static_cast<size_t>(p.N));
  barycentric.resize(static_cast<size_t>(p.N));
  std::vector<char> kept(static_cast<size_t>(p.N), 0);
  // The last solution itself, not its extrapolation, onto the target.
  ParallelForChunks<Index>(p.N, 512, p.Threads, [&](Index begin, Index end) {
    for (Index i = begin; i < end; ++i)
    {
      Index t = p.Current[i];
      Eigen::Vector3d weights;
      if (p.LastSolved.row(i).allFinite() &&
        p.Target.Walk(p.LastSolved.row(i).transpose(), t, weights) <= p.Reject2)
      {
        triangle[i] = t;
        barycentric[i] = weights;
      }
      else
      {
        kept[i] = 1; // far from the target: its spectral point stays
        triangle[i] = p.SpectralTriangle[i];
        barycentric[i] = p.SpectralBarycentric[i];
      }
    }
  });
  // A landmark ends on its target vertex itself, a corner of a triangle around it.
  for (const auto& pin : p.Parameters.Pinned)
  {
    PlaceAtVertex(p.Target.Faces, p.Target.VertexFaces, pin.second, triangle[pin.first],
      barycentric[pin.first]);
  }
  p.Info.Rejected = std::count(p.Trusted.begin(), p.Trusted.end(), 0);
  p.Info.KeptSpectral = std::count(kept.begin(), kept.end(), 1);
}

void SurfacePolisher::MoveTo(
  const std::vector<Index>& triangle, const std::vector<Eigen::Vector3d>& barycentric)
{
  State& p = *this->Polish;
  ParallelForChunks<Index>(p.N, 512, p.Threads, [&](Index begin, Index end) {
    for (Index i = begin; i < end; ++i)
    {
      const Eigen::Vector3d point = p.Target.Point(triangle[i], barycentric[i]);
      // The iterate is the last solution plus momentum: both move, the step stays.
      p.Y.row(i) += point.transpose() - p.LastSolved.row(i);
      p.LastSolved.row(i) = point.transpose();
      p.Current[i] = triangle[i];
    }
  });
}

const SurfacePolishInfo& SurfacePolisher::Info() const
{
  return this->Polish->Info;
}

bool PolishSurfaceMap(const Points& sourcePoints, const Triangles& sourceTriangles,
  const Points& targetPoints, const Triangles& targetTriangles,
  const VertexLists& targetVertexTriangles, std::vector<Index>& triangle,
  std::vector<Eigen::Vector3d>& barycentric, const SurfacePolishParameters& parameters,
  SurfacePolishInfo& info)
{
  SurfacePolisher polisher;
  const bool polished = polisher.Start(sourcePoints, sourceTriangles, targetPoints,
                          targetTriangles, targetVertexTriangles, triangle, barycentric, parameters) &&
    polisher.Iterate(parameters.Iterations);
  if (polished)
  {
    polisher.CurrentMap(triangle, barycentric);
  }
  info = polisher.Info();
  return polished;
}
}
