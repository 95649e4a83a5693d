// A starting map for the conformal flow on a cyclic covering, lifted from the spherical
// conformal map of the mesh itself.
//
// Why the flow needs one: every copy of the covering starts at the same place in space, so
// the flow started from the covering's own points would keep all copies on top of each
// other (it treats the copies alike) and end at an n-fold wrapped sphere, not a map.
//
// The lift: the n-fold cyclic covering branched at two points of the sphere is
// w -> w^n in a stereographic coordinate that puts the two points at 0 and infinity. So,
// with z the stereographic coordinate of the mesh's spherical map (cone 1 at infinity, cone
// 0 moved to 0), copy i of the covering starts at w = |z|^(1/n) exp(i (arg z + 2 pi i s)/n),
// with arg z continued across the cut surface (copy 0) and s = +-1 the turn direction of
// the gluing. This is a flip-free map of the covering when the mesh's map is flip-free, and
// already n-fold symmetric about the axis through the cones; the flow then makes it
// discretely conformal on the covering's own triangles (the cone angles, n times the
// original, enter through its Laplacian).
#ifndef mobius_CoveringLift_h
#define mobius_CoveringLift_h

#include "CyclicCovering.h"

#include <string>

namespace mobius
{
/// Lifts `sphereMap` (a spherical map of the mesh the covering was built from, one unit
/// vector per input vertex) to the covering; cone 0 goes to (0, 0, -1), cone 1 to (0, 0, 1).
/// Returns false with `error` set if the map cannot be lifted (a vertex on a cone's image,
/// a cut side that does not wrap once around the cone).
bool LiftSphericalMapToCovering(const Points& sphereMap, const Triangles& triangles,
  const CyclicCovering& covering, Points& lifted, std::string& error);
}

#endif
