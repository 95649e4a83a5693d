// A triangulated torus, the simplest closed surface of genus 1: tests use it to check that
// higher-genus input is recognized and rejected.
#ifndef mobius_Torus_h
#define mobius_Torus_h

#include "MeshTypes.h"

namespace mobius
{
/// An n x m grid on the torus with radii `major` and `minor` about the z axis, wrapped in
/// both directions, each grid quad split into two triangles: n*m points, 2*n*m triangles.
void MakeTorus(int n, int m, double major, double minor, Points& points, Triangles& triangles);
}

#endif
