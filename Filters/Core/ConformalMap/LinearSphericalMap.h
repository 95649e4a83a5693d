// A spherical conformal map from one sparse linear solve (Angenent, Haker, Tannenbaum &
// Kikinis 1999; Haker et al. 2000), used as the starting shape of the conformal flow.
//
// Why: the flow started from the surface itself needs 8-13 steps (one Cholesky
// factorization each) to become round. A conformal map of the sphere is (up to
// discretization) a fixed point of the flow, so the flow started from one only polishes it.
//
// The map: puncture the surface at a point p inside one triangle. A conformal map z of the
// punctured sphere onto the plane has a simple pole at p and solves
//   Laplace z = 2 pi (d/du - i d/dv) delta_p
// with (u, v) an oriented orthonormal frame at p (1/w is 2 d/dw of log|w|, whose Laplacian is
// 2 pi delta). Its finite-element form against the hat functions phi_j is L z = b with the
// stiffness L and b_j = (d/du - i d/dv) phi_j (p): non-zero only at the three corners of the
// triangle, constant in it (2 pi is dropped; scale does not matter). The inverse
// stereographic projection of z, scaled so that half the area lands in each hemisphere,
// is the map.
//
// L is singular (constants); we factor L + eps M, which is positive definite and has the
// flow's sparsity pattern, so the flow's symbolic analysis is reused. The shift adds a
// constant to z (a translation of the plane: a Möbius transformation, removed by the
// centering) and a relative error of order eps / lambda_1 elsewhere, which one step of
// iterative refinement reduces to its square.
#ifndef mobius_LinearSphericalMap_h
#define mobius_LinearSphericalMap_h

#include "CotangentLaplacian.h"
#include "MeshTypes.h"
#include "SparseCholesky.h"

#include <string>

namespace mobius
{
/// The triangle to puncture: the pole region is where the piecewise-linear z (which must
/// follow 1/w) is least accurate, so we take a well-shaped triangle (shape quality
/// 4 sqrt(3) area / sum of squared edge lengths, 1 for equilateral) in a flat region (its
/// normal agrees with its three neighbours') among the larger half of the triangles.
/// -1 if there is no triangle with positive area.
Index ChoosePoleTriangle(const Points& points, const Triangles& triangles);

struct LinearSphericalMapResult
{
  bool Success = false;
  std::string Error;
  /// The triangle that contains the pole (the north pole of the map).
  Index PoleTriangle = -1;
  /// The solver was asked to factorize (L + eps M): it no longer holds what it held.
  bool Factorized = false;
  /// One point per vertex on the unit sphere (not yet Möbius-centered).
  Points SpherePoints;
};

/// The map of a closed genus-0 surface (`points` scaled to unit area) whose stiffness and
/// lumped mass are given. `solver` must have analyzed the pattern of `stiffness` (every
/// diagonal entry stored); it is left holding the factorization of L + eps M.
LinearSphericalMapResult ComputeLinearSphericalMap(const Points& points,
  const Triangles& triangles, const SparseMatrix& stiffness, const Vector& mass,
  SparseCholesky& solver);
}

#endif
