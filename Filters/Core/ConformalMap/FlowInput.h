// What the conformal flow needs of a repaired mesh besides its topology: coordinates of
// order 1, triangles facing outward, and areas that double precision represents.
#ifndef mobius_FlowInput_h
#define mobius_FlowInput_h

#include "MeshTypes.h"

#include <string>

namespace mobius
{
/// Scales `points` by the power of two that brings the largest finite coordinate of the
/// points the triangles use to [1, 2) and returns its exponent e (the input is the result
/// times 2^e; 0 for all-zero points). Points no triangle uses do not count: one stray point
/// at 1e100 (which the repair drops) would otherwise squeeze the surface to 1e-100, where
/// its areas underflow.
///
/// The geometry squares lengths twice (areas as norms of cross products, cotangent
/// weights): coordinates beyond about 1e75 or below 1e-75 overflow or underflow double
/// precision (a mesh at 1e-100 had "320 zero-area triangles", one at 1e100 "no area").
/// Scaling by a power of two is exact, so everything runs on coordinates of order 1 and
/// the outputs are scaled back exactly.
int ScaleToUnitOrder(Points& points, const Triangles& triangles);

/// The coordinates of the points the triangles use span more than double precision can
/// compute areas over (the farthest point more than 1e100 times the median edge length from
/// the origin): after ScaleToUnitOrder the rest of the surface would underflow and read as
/// "every triangle has zero area". The problem, naming the point; empty if none.
std::string CheckCoordinateRange(const Points& points, const Triangles& triangles);

/// Reverses every triangle if the surface encloses a negative volume, and says whether it
/// did. The flow keeps the orientation of the triangles: facing outward, the map comes out
/// orientation-preserving and outward-facing on the sphere.
bool FaceOutward(const Points& points, Triangles& triangles);

/// The triangles' areas at the input's scale (`points` times 2^scaleExponent). False, with
/// `problem` naming the first triangle, when one is neither 0 (three points on a line) nor
/// a positive normal double.
bool TriangleAreasAtScale(const Points& points, const Triangles& triangles, int scaleExponent,
  Vector& areas, std::string& problem);
}

#endif
