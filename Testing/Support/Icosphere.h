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
}

#endif
