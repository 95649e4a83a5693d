// Spherical orbifold maps with cyclic symmetry (Baden, Crane & Kazhdan 2018, §7.2).
//
// A map of the surface onto the sphere's quotient by the rotations through 2 pi k / n about
// an axis: one sector of the sphere, 1/n of it, with its two straight sides glued and two
// cone points of angle 2 pi / n at the poles. Compared with a plain spherical map, the
// surface's two cone vertices get n times the angle on the sphere, which spreads elongated
// shapes (limbs, ends) over more of it: less area distortion.
//
// The steps: choose two cone vertices (given, or two far-apart ones), cut the mesh along
// the shortest edge path between them, glue n copies into the cyclic covering
// (CyclicCovering.h), map the covering onto the sphere with the conformal flow
// (ConformalMap.h) started from the mesh's own map lifted to the covering (CoveringLift.h),
// and center it (MobiusCentering.h, the covering's areas). The symmetry comes from the
// start: the lift places the copies n-fold symmetrically about the axis through the two
// cones (the deck transformation, which shifts every copy by one, acts as a rotation by
// 2 pi / n), and every later step keeps it up to rounding: the flow's linear solves and
// rescaling treat the copies alike (the covering's copies have the same geometry), and a
// symmetric map's center of mass lies on the axis, so centering moves it along the axis.
// The centering makes the result canonical: the centered map of the covering is unique up
// to rotation, so any other conformal map of the covering, centered, is this one turned
// (and symmetric too). The map is finally rotated so that the cones' axis is z (cone 1 at
// the north pole).
#ifndef mobius_SphericalOrbifoldMap_h
#define mobius_SphericalOrbifoldMap_h

#include "ConformalMap.h"
#include "CyclicCovering.h"
#include "MobiusCentering.h"
#include "OrbifoldMeasures.h"

#include <string>
#include <vector>

namespace mobius
{
constexpr int MinimumOrbifoldCopies = 2;
constexpr int MaximumOrbifoldCopies = 8;

struct SphericalOrbifoldMapParameters
{
  /// n, the order of the symmetry: the number of copies in the covering (2 to 8).
  int Copies = 2;
  /// The two cone vertices; both -1 to choose two far-apart vertices (FarApartVertices).
  Index Cones[2] = { -1, -1 };
  /// The conformal flow on the covering, and on the mesh itself when no map of it is given.
  ConformalMapParameters Flow;
  MobiusCenteringParameters Centering;
  ProgressCallback Progress;
};

struct SphericalOrbifoldMapResult
{
  bool Success = false;
  /// Why it failed (naming the bad parameter or the step), or a summary.
  std::string Message;
  /// The cone vertices used and the cut path between them (input vertex numbers).
  Index Cones[2] = { -1, -1 };
  CyclicCovering Covering;
  /// The map of the covering: centered, cone 1's image on +z.
  Points CoveringMap;
  /// The mesh's own (plain) spherical map, centered.
  Points PlainMap;
  /// The flow on the covering and the final centering.
  ConformalMapResult CoveringFlow;
  MobiusCenteringResult CoveringCentering;
  /// How far the map is from n-fold symmetry about z (CoveringMap vs. its deck shift).
  CyclicSymmetryError Symmetry;
  /// |x(cone 0) + x(cone 1)|: 0 when the cones are antipodal, as centering makes them.
  double ConeAntipodality = 0.0;
  /// Flipped triangles of the covering's map.
  Index FlippedTriangles = 0;
  /// Area distortion of the plain map and of the orbifold map (over the covering's
  /// triangles, i.e. of any one copy since the copies are alike).
  AreaDistortionStatistics PlainAreaDistortion;
  AreaDistortionStatistics OrbifoldAreaDistortion;
};

/// Computes the orbifold map of the closed genus-0 mesh (points, triangles). `plainMap` is
/// the mesh's own spherical conformal map (one unit vector per point) or empty to compute it
/// here. Never throws; on failure Success is false and Message names the problem (cones out
/// of range or equal or neighbours, Copies out of [2, 8], a failed flow).
SphericalOrbifoldMapResult ComputeSphericalOrbifoldMap(const Points& points,
  const Triangles& triangles, const Points& plainMap,
  const SphericalOrbifoldMapParameters& parameters);

/// Checks the cones and the number of copies for a mesh of `numberOfPoints` vertices; an
/// empty string when they are valid, the problem otherwise (both cones -1 means automatic).
std::string CheckOrbifoldParameters(Index numberOfPoints, int copies, Index cone0, Index cone1);

/// The mesh vertices of the two cones named by their input point ids (`inputIds[v]` is mesh
/// vertex v's; the last vertex carrying the id when several do), into `cones`. Both ids -1
/// leave `cones` at -1 (automatic cones). An empty string, or the problem: a cone that is not
/// a vertex of the mapped (repaired) surface.
std::string FindConeVertices(
  const std::vector<Index>& inputIds, const Index coneIds[2], Index cones[2]);

/// What an orbifold map puts out: one copy of the covering (copy 0's triangles: its own
/// vertices and the next copy's along the cut's left side) or the whole covering, the
/// covering's vertices renumbered in order of first use by the triangles.
struct OrbifoldOutputMesh
{
  Points SpherePoints;              ///< the map of each output vertex
  Points SurfacePoints;             ///< the surface point of the mesh vertex it copies
  std::vector<Index> SourceVertex;  ///< the mesh vertex it copies
  std::vector<int> VertexCopy;      ///< its copy (-1 for the cones)
  Triangles OutputTriangles;
  std::vector<int> TriangleCopy;    ///< the copy each triangle belongs to
  Vector TriangleAreas;             ///< the surface area of the mesh triangle it copies
};

/// The output mesh of a successful `result` for the mesh (surface, triangles).
OrbifoldOutputMesh SelectOrbifoldOutput(const SphericalOrbifoldMapResult& result,
  const Points& surface, const Triangles& triangles, bool wholeCovering);
}

#endif
