#include "SqueezedRegionRefinement.h"

#include "NestedFrames.h"
#include "SqueezedTipSpreading.h"

#ifdef MOBIUS_HAVE_CHOLMOD
#include <Eigen/UmfPackSupport>
#else
#include <Eigen/SparseLU>
#endif

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace mobius
{
namespace
{
#ifdef MOBIUS_HAVE_CHOLMOD
// SuiteSparse's UMFPACK, told that the matrix is nearly symmetric: it orders the pattern of
// A + A^T by AMD and takes the diagonal pivots, which a diagonally dominant system like this
// one allows. The regions can be large (a Loop-subdivided CGAL man of 1.1M vertices has
// 383K squeezed vertices in its limbs, re-solved at three levels): that took 10.2 s with
// Eigen's SparseLU (COLAMD), as long with UMFPACK's default (unsymmetric) strategy, and
// 5.7 s with this one, with the same map to the digits checked.
class RegionSolver
{
public:
  bool Compute(const SparseMatrix& system)
  {
    this->Solver.umfpackControl()(UMFPACK_STRATEGY) = UMFPACK_STRATEGY_SYMMETRIC;
    this->Solver.compute(system);
    return this->Solver.info() == Eigen::Success;
  }
  Eigen::MatrixXd Solve(const Eigen::MatrixXd& rightHandSides) const
  {
    return this->Solver.solve(rightHandSides);
  }

private:
  Eigen::UmfPackLU<SparseMatrix> Solver;
};
#else
class RegionSolver
{
public:
  bool Compute(const SparseMatrix& system)
  {
    this->Solver.compute(system);
    return this->Solver.info() == Eigen::Success;
  }
  Eigen::MatrixXd Solve(const Eigen::MatrixXd& rightHandSides) const
  {
    return this->Solver.solve(rightHandSides);
  }

private:
  Eigen::SparseLU<SparseMatrix> Solver;
};
#endif

// Floater's mean-value weights of the original surface, row i: w_ij = (tan(a/2) + tan(b/2)) /
// |p_i - p_j| with a, b the angles at p_i next to edge ij. Positive for every triangulation,
// which is what makes the re-solved region fold-free (Floater 2003); not symmetric.
SparseMatrix MeanValueWeights(const Points& p, const Triangles& triangles)
{
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(6 * static_cast<size_t>(triangles.rows()));
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index i = triangles(t, k), j = triangles(t, (k + 1) % 3),
                  l = triangles(t, (k + 2) % 3);
      const Eigen::RowVector3d eij = p.row(j) - p.row(i), eil = p.row(l) - p.row(i);
      const double lij = eij.norm(), lil = eil.norm();
      const double cosine = std::max(-1.0, std::min(1.0, eij.dot(eil) / (lij * lil)));
      const double halfTangent = std::tan(0.5 * std::acos(cosine));
      entries.emplace_back(i, j, halfTangent / lij);
      entries.emplace_back(i, l, halfTangent / lil);
    }
  }
  SparseMatrix w(p.rows(), p.rows());
  w.setFromTriplets(entries.begin(), entries.end());
  return SparseMatrix(w.transpose()); // column i holds row i's weights
}

// Re-solves the squeezed regions of one threshold: `local` numbers the members (-1 for the
// rest). False if the factorization or the solution failed.
bool ResolveRegions(NestedFrames& frames, const SparseMatrix& weights,
  const std::vector<Index>& members, const std::vector<Index>& local)
{
  const Index m = static_cast<Index>(members.size());
  // Regions (connected components of the members) and each one's local origin: its first
  // member's position. Rows of different regions never couple, so one factorization serves
  // them all.
  std::vector<Index> region(static_cast<size_t>(m), -1), stack, origins;
  for (Index s = 0; s < m; ++s)
  {
    if (region[s] >= 0)
    {
      continue;
    }
    const Index id = static_cast<Index>(origins.size());
    origins.push_back(members[s]);
    region[s] = id;
    stack.assign(1, s);
    while (!stack.empty())
    {
      const Index r = stack.back();
      stack.pop_back();
      for (SparseMatrix::InnerIterator it(weights, members[r]); it; ++it)
      {
        const Index j = local[it.row()];
        if (j >= 0 && region[j] < 0)
        {
          region[j] = id;
          stack.push_back(j);
        }
      }
    }
  }
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(m, 3);
  for (Index r = 0; r < m; ++r)
  {
    const Index i = members[r];
    const Index origin = origins[region[r]];
    // Row r: sum_j w_ij (x_i - x_j) = 0, i.e. x_i is the weighted average of its
    // neighbours.
    double total = 0.0;
    for (SparseMatrix::InnerIterator it(weights, i); it; ++it)
    {
      total += it.value();
      const Index j = local[it.row()];
      if (j >= 0)
      {
        entries.emplace_back(r, j, -it.value());
      }
      else
      {
        // Boundary values move right, relative to the origin (from the deepest level that
        // holds both: accurate relative to their distance).
        rhs.row(r) += it.value() * frames.Difference(it.row(), origin);
      }
    }
    entries.emplace_back(r, r, total);
  }
  SparseMatrix system(m, m);
  system.setFromTriplets(entries.begin(), entries.end());
  system.makeCompressed();
  RegionSolver solver;
  if (!solver.Compute(system))
  {
    return false;
  }
  const Eigen::MatrixXd y = solver.Solve(rhs);
  if (!y.allFinite())
  {
    return false;
  }
  frames.AddLevel(members, region, origins, y);
  return true;
}

double ShortestEdge(const NestedFrames& frames, const Triangles& triangles)
{
  double shortest = std::numeric_limits<double>::infinity();
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      shortest =
        std::min(shortest, frames.Difference(triangles(t, k), triangles(t, (k + 1) % 3)).norm());
    }
  }
  return shortest;
}

// Back to doubles on the unit sphere (every edge the spreading reached is resolved by now);
// untouched points keep their bits.
void WriteBack(const NestedFrames& frames, Points& sphere)
{
  const ExtendedPoints& x = frames.Absolute();
  for (Index i = 0; i < sphere.rows(); ++i)
  {
    if (x.High.row(i) != sphere.row(i) || !x.Low.row(i).isZero(0.0))
    {
      const Eigen::RowVector3d p = x.High.row(i) + x.Low.row(i);
      sphere.row(i) = p / p.norm();
    }
  }
}
}

SqueezedRegionRefinementResult RefineSqueezedRegions(
  Points& sphere, const Triangles& triangles, const Points& original, double largestThreshold)
{
  SqueezedRegionRefinementResult result;
  const Index n = sphere.rows();
  NestedFrames frames(sphere);
  SparseMatrix weights; // built when the first squeezed region is found
  std::vector<char> refined(static_cast<size_t>(n), 0);
  Vector longest = frames.LongestEdges(triangles);
  for (double tau = largestThreshold; tau > SmallestSqueezedRegionThreshold; tau *= 1e-2)
  {
    std::vector<Index> local(static_cast<size_t>(n), -1), members;
    for (Index i = 0; i < n; ++i)
    {
      if (longest[i] < tau)
      {
        local[i] = static_cast<Index>(members.size());
        members.push_back(i);
      }
    }
    if (members.empty())
    {
      break;
    }
    if (weights.nonZeros() == 0)
    {
      weights = MeanValueWeights(original, triangles);
      if (!Eigen::Map<const Vector>(weights.valuePtr(), weights.nonZeros()).allFinite())
      {
        result.Success = false;
        break;
      }
    }
    if (!ResolveRegions(frames, weights, members, local))
    {
      result.Success = false;
      break;
    }
    for (Index i : members)
    {
      refined[i] = 1;
    }
    ++result.Levels;
    longest = frames.LongestEdges(triangles);
  }
  result.SmallestEdge = ShortestEdge(frames, triangles);
  for (char r : refined)
  {
    result.RefinedVertices += r;
  }
  if (n > 0 && longest.minCoeff() < ResolvableEdgeLength)
  {
    result.Spreading = SpreadUnresolvedTips(frames, triangles);
  }
  WriteBack(frames, sphere);
  return result;
}
}
