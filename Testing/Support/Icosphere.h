// Subdivided icosahedra: well-shaped triangulations of the unit sphere, for the tests that
// must not depend on data files.
#ifndef mobius_Icosphere_h
#define mobius_Icosphere_h

#include "MeshTypes.h"

namespace mobius
{
/// A unit-sphere triangulation: the icosahedron with each triangle split into four
/// `levels` times, new vertices projected onto the sphere. 10*4^levels + 2 vertices,
/// 20*4^levels triangles, outward (counter-clockwise seen from outside) orientation.
/// The vertex set is mirror-symmetric about each coordinate plane.
void MakeIcosphere(int levels, Points& points, Triangles& triangles);

/// A sliver without area closing a T-junction: a new last point m at `where` on the edge
/// (a, b) of triangle 0 (a, b, c), that triangle split into (a, m, c) and (m, b, c), and
/// (a, b, m) closing the other side of the edge. Triangle 0 goes last: the split and the
/// sliver are the last three rows.
void InsertSliver(const Points& points, const Triangles& triangles, const Eigen::RowVector3d& where,
  Points& withSliver, Triangles& split);
}

#endif
