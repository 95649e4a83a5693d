// The finite-element Laplacian of a triangle mesh: the cotangent stiffness matrix and the
// lumped mass matrix, plus the per-triangle areas both are built from.
#ifndef mobius_CotangentLaplacian_h
#define mobius_CotangentLaplacian_h

#include "MeshTypes.h"

#include <Eigen/SparseCore>

#include <string>

namespace mobius
{
using SparseMatrix = Eigen::SparseMatrix<double>;

/// Area of each triangle.
Vector TriangleAreas(const Points& points, const Triangles& triangles);

/// Lumped (barycentric) mass: each vertex gets a third of the area of its triangles.
Vector LumpedMass(const Points& points, const Triangles& triangles);

struct CotangentStiffnessInfo
{
  /// Edge flips made to reach the intrinsic Delaunay triangulation.
  Index IntrinsicFlips = 0;
  /// Edges whose weight (cot alpha + cot beta) / 2 is negative (never after intrinsic
  /// Delaunay flips, except for rounding).
  Index NegativeWeights = 0;
  /// Why the matrix could not be built (empty on success).
  std::string Error;
};

/// The stiffness matrix L of the piecewise-linear Dirichlet energy, x^T L x = 1/2 sum over
/// edges of (cot alpha + cot beta) |x_i - x_j|^2: L_ij = -(cot alpha_ij + cot beta_ij) / 2,
/// L_ii = -sum_j L_ij; symmetric, rows sum to zero, positive semi-definite when all weights
/// are non-negative, invariant under scaling of the mesh. Every diagonal entry is stored
/// (explicitly, even if zero) so callers can add a mass matrix into the same pattern.
///
/// With `intrinsicDelaunay`, the weights come from the intrinsic Delaunay triangulation of
/// the mesh's edge lengths (see IntrinsicDelaunay.h): the same surface, but well-shaped
/// weights on meshes with needle triangles. Needs manifold, consistently oriented edges.
/// Returns false with info.Error set when a weight is not finite (e.g. a zero-length edge).
bool BuildCotangentStiffness(const Points& points, const Triangles& triangles,
  bool intrinsicDelaunay, SparseMatrix& stiffness, CotangentStiffnessInfo& info);
}

#endif
