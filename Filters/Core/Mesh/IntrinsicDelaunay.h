// Intrinsic Delaunay triangulation by edge flips (Fisher, Springborn, Schröder & Bobenko
// 2007; Bobenko & Springborn 2007).
//
// Why: cotangent weights of needle triangles are huge or negative, which makes the
// Laplacian indefinite-looking and its Cholesky factorization inaccurate, and lets a
// conformal flow fold triangles. Flipping edges on the surface's *intrinsic* metric (the
// edge lengths; no vertex moves, the surface geometry is unchanged) until every edge is
// locally Delaunay gives a Laplacian with non-negative weights (a maximum principle) that
// still discretizes the same smooth operator.
//
// The intrinsic triangulation may contain several edges between the same two vertices and
// even triangles with a repeated vertex; a Laplacian built from it by summing per-corner
// weights is still correct.
#ifndef mobius_IntrinsicDelaunay_h
#define mobius_IntrinsicDelaunay_h

#include "MeshTypes.h"

#include <vector>

namespace mobius
{
/// A triangulation described only by connectivity and edge lengths. Half-edge 3 t + k runs
/// from corner k to corner k+1 of triangle t; Length[3 t + k] is its length and Twin the
/// opposite half-edge in the neighbouring triangle (-1 on a boundary).
struct IntrinsicTriangulation
{
  Triangles Corners;
  std::vector<double> Length;
  std::vector<Index> Twin;
};

/// The triangulation of an embedded mesh with its Euclidean edge lengths. Needs
/// manifold edges (at most two triangles each) with consistent orientation; returns false
/// otherwise.
bool MakeIntrinsicTriangulation(
  const Points& points, const Triangles& triangles, IntrinsicTriangulation& intrinsic);

/// Flips edges until every interior edge is locally Delaunay (the angles opposite it sum to
/// at most pi). Returns the number of flips. Terminates in theory; `maximumFlips` is a guard
/// against rounding-induced cycles (0: 100 times the number of half-edges).
Index FlipToDelaunay(IntrinsicTriangulation& intrinsic, Index maximumFlips = 0);

/// Cotangent of the angle opposite each half-edge (3 per triangle), from edge lengths.
/// Degenerate triangles give non-finite values, which callers must check.
std::vector<double> OppositeCotangents(const IntrinsicTriangulation& intrinsic);
}

#endif
