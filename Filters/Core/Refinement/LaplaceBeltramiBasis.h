// The first eigenfunctions of a surface's Laplace-Beltrami operator: the basis in which the
// refinement stage compares two surfaces (functional maps).
#ifndef mobius_LaplaceBeltramiBasis_h
#define mobius_LaplaceBeltramiBasis_h

#include "CotangentLaplacian.h"
#include "MeshTypes.h"

#include <string>

namespace mobius
{
struct LaplaceBeltramiBasis
{
  /// n x k, column j the j-th eigenfunction (ascending eigenvalue), orthonormal in the
  /// mass matrix of the surface scaled to unit area: Functions^T Mass Functions = I.
  Eigen::MatrixXd Functions;
  /// The k eigenvalues, ascending, for the surface scaled to unit area (the first is ~0).
  Vector Eigenvalues;
  /// The mass matrix of the eigenproblem, the surface scaled to unit area (its entries sum
  /// to 1; diagonal when the consistent share is 0).
  SparseMatrix Mass;
};

/// Computes the `count` eigenpairs of smallest eigenvalue of L phi = lambda M phi, with L the
/// cotangent stiffness of the intrinsic Delaunay triangulation (well-defined weights on
/// needle triangles) and M the mass matrix: by default (`consistentMassShare` 0) the lumped
/// mass of the original triangles; otherwise that share of the consistent mass blended with
/// the lumped one, both on the intrinsic Delaunay triangulation (see BuildMassMatrix and the
/// README's Accuracy section: 0.5 makes the eigenfunctions of a mesh and of a
/// re-triangulation of it agree better, but maps some bent or twisted pairs worse and takes
/// longer, so it is not the default), by shift-invert Lanczos (Spectra) on sparse
/// Cholesky factorizations, with single-precision Lanczos vectors and a double-precision
/// Rayleigh-Ritz step (eigenfunctions mass-orthonormal to double precision; eigenvalues the
/// Rayleigh quotients). More than 40 eigenpairs are found in slices of the spectrum (one
/// shift per window of about 40; docs/DEVELOPMENT.md, "Refinement cost"), checked complete by
/// the factorization's inertia, with one window as the fallback. Needs a closed, manifold,
/// oriented mesh. Returns false with `error` set if the Laplacian cannot be built or the
/// eigensolver does not converge.
bool ComputeLaplaceBeltramiBasis(const Points& points, const Triangles& triangles, int count,
  LaplaceBeltramiBasis& basis, std::string& error, double consistentMassShare = 0.0);

/// The mass matrix ComputeLaplaceBeltramiBasis solves with (the same `consistentMassShare`),
/// scaled to unit total area. With eigenfunctions and eigenvalues computed earlier (and
/// stored), it completes a LaplaceBeltramiBasis for a fraction of the cost. False with
/// `error` set on non-manifold or inconsistently oriented edges, or a vertex without area.
bool BuildUnitAreaMassMatrix(const Points& points, const Triangles& triangles,
  double consistentMassShare, SparseMatrix& mass, std::string& error);
}

#endif
