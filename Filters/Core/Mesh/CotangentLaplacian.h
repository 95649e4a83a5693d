// The finite-element Laplacian of a triangle mesh: the cotangent stiffness matrix and the
// lumped mass matrix, plus the per-triangle areas both are built from (and the vertex
// normals they give).
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

/// Unit vertex normals: the sum of the normals of the triangles around each vertex, each
/// weighted by its area.
Points AreaWeightedVertexNormals(const Points& points, const Triangles& triangles);

/// Lumped (barycentric) mass: each vertex gets a third of the area of its triangles.
Vector LumpedMass(const Points& points, const Triangles& triangles);

/// The finite-element mass matrix of piecewise-linear functions, blended with the lumped one:
/// consistentShare x consistent (M_ii = sum A_t / 6, M_ij = sum A_t / 12 over the triangles t
/// around vertex i / edge ij) + (1 - consistentShare) x lumped (diagonal, A_t / 3). With
/// `intrinsicDelaunay`, the triangles (and their areas, from edge lengths) are those of the
/// intrinsic Delaunay triangulation, the one BuildCotangentStiffness uses, so that the mass
/// and the stiffness discretize the same function space. Every diagonal entry is stored;
/// off-diagonal ones only when consistentShare is not 0.
/// False if the mesh has non-manifold or inconsistently oriented edges.
bool BuildMassMatrix(const Points& points, const Triangles& triangles, bool intrinsicDelaunay,
  double consistentShare, SparseMatrix& mass);

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
