// The first eigenfunctions of a surface's Laplace-Beltrami operator: the basis in which the
// refinement stage compares two surfaces (functional maps).
#ifndef mobius_LaplaceBeltramiBasis_h
#define mobius_LaplaceBeltramiBasis_h

#include "MeshTypes.h"

#include <string>

namespace mobius
{
struct LaplaceBeltramiBasis
{
  /// n x k, column j the j-th eigenfunction (ascending eigenvalue), orthonormal in the
  /// lumped mass of the surface scaled to unit area: Functions^T diag(Mass) Functions = I.
  Eigen::MatrixXd Functions;
  /// The k eigenvalues, ascending, for the surface scaled to unit area (the first is ~0).
  Vector Eigenvalues;
  /// Lumped mass of each vertex, the surface scaled to unit area (sums to 1).
  Vector Mass;
};

/// Computes the `count` eigenpairs of smallest eigenvalue of L phi = lambda M phi, with L the
/// cotangent stiffness of the intrinsic Delaunay triangulation (well-defined weights on
/// needle triangles) and M the lumped mass, by shift-invert Lanczos (Spectra) on a sparse
/// Cholesky factorization, with single-precision Lanczos vectors and a double-precision
/// Rayleigh-Ritz step (eigenfunctions mass-orthonormal to double precision; eigenvalues the
/// Rayleigh quotients). Needs a closed, manifold, oriented mesh. Returns false with `error`
/// set if the Laplacian cannot be built or the eigensolver does not converge.
bool ComputeLaplaceBeltramiBasis(const Points& points, const Triangles& triangles, int count,
  LaplaceBeltramiBasis& basis, std::string& error);
}

#endif
