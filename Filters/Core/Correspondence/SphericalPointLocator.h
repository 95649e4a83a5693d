// Point location in a spherical triangulation, for the dense correspondence: which triangle of a
// spherical map contains a point of the sphere, and with which barycentric coordinates.
//
// A spherical map may be extremely non-uniform (a conformal map squeezes whole limbs into regions
// 1e-12 wide) and may keep a few folded or degenerate triangles. The locator therefore uses a
// bounding-volume hierarchy of spherical caps rather than a latitude-longitude or cube-map grid:
// - every triangle is stored exactly once, so memory is O(n) and the depth is O(log n) whatever
//   the spread of triangle sizes (a uniform grid is either far too coarse in the squeezed regions
//   or duplicates the large triangles into a huge number of cells);
// - it works on unit vectors in R^3, so poles and the phi = 0/2 pi seam are not special;
// - the same tree answers "nearest triangle" by branch and bound, which is how a point that lies
//   in no triangle (a hole, or round-off) is still located: Locate never says "not found".
//
// Containment uses signed volumes written as det(p, b, c) = p . ((b - p) x (c - p)): the
// differences are small and exact-ish for tiny triangles (relative accuracy ~1e-16 instead of
// 1e-16 / size), a point equal to a vertex gives exact zeros, and the two triangles sharing an
// edge compute exactly opposite values for it, so points on edges and vertices are always found.
#ifndef mobius_SphericalPointLocator_h
#define mobius_SphericalPointLocator_h

#include "MeshTypes.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace mobius
{
struct SphericalLocation
{
  /// Row of the located triangle in the triangle array given to Build(). -1 only when the query
  /// itself is unusable (zero, infinite or NaN) or the locator was not built.
  Index Triangle = -1;
  /// Projective barycentric coordinates (alpha, beta, gamma): each in [0, 1], sum 1, and the
  /// located point is (alpha a + beta b + gamma c) normalized. For a point inside the triangle
  /// this is the solution of [a b c] w = p normalized to sum 1.
  Eigen::Vector3d Barycentric = Eigen::Vector3d::Zero();
  /// True when p lay in no triangle (a hole in the mesh, or round-off at a vertex of a
  /// degenerate star): the nearest point of the nearest triangle was returned instead.
  bool Clamped = false;
  /// Angular distance (radians) from p to the located point; 0 unless Clamped.
  double AngularDistance = 0.0;
};

class SphericalPointLocator
{
public:
  /// Builds the cap hierarchy (O(n log n)). spherePoints must lie on the unit sphere within
  /// 1e-6; they are kept as given (a copy), so the barycentric coordinates are exactly those of
  /// the caller's triangles, even 1e-11-wide ones. Triangles are vertex indices, outward oriented,
  /// though folded (det(a, b, c) < 0) and degenerate triangles are tolerated. Returns false
  /// with a message naming the problem for an empty mesh, an index out of range, a point off
  /// the sphere, or a non-finite coordinate; the locator is then empty.
  bool Build(const Points& spherePoints, const Triangles& triangles, std::string& error);

  /// Locates p, which need not be exactly on the sphere (its direction counts; a p already unit
  /// to 1e-14 is used as given, so vertices and edge points stay exact). Thread-safe.
  /// A point inside several triangles (on an edge, at a vertex, or in a fold) gets one of them.
  SphericalLocation Locate(const Eigen::Vector3d& p) const;

  /// Locates every row of `queries` with numberOfThreads threads (0: one per core).
  /// `progress` is called from the calling thread only; returning false aborts.
  /// Returns false if aborted or if the locator was not built.
  bool LocateAll(const Points& queries, std::vector<SphericalLocation>& locations,
    int numberOfThreads = 0, const ProgressCallback& progress = {}) const;

  bool IsBuilt() const { return !this->Nodes.empty(); }
  Index GetNumberOfTriangles() const { return static_cast<Index>(this->LeafTriangles.size()); }
  /// Depth of the hierarchy (the root alone has depth 1), for diagnostics.
  int GetDepth() const { return this->Depth; }

private:
  /// A node's bounding cap is the set of unit vectors x with |x - Center| <= ChordRadius.
  /// Inner nodes have their two children at FirstChild and FirstChild + 1; leaves own the
  /// LeafTriangles [FirstTriangle, FirstTriangle + TriangleCount).
  struct Node
  {
    Eigen::Vector3d Center;
    double ChordRadius = 0.0;
    std::int32_t First = 0;         // first child, or first leaf triangle
    std::int32_t TriangleCount = 0; // 0 for inner nodes
  };

  /// A triangle in hierarchy order, with what containment needs at hand. 32-bit indices halve
  /// the memory; Build() refuses meshes too large for them.
  struct LeafTriangle
  {
    std::array<std::int32_t, 3> Vertices;
    std::int32_t Id;          // row in the input triangle array
    std::int32_t Orientation; // sign of det(a, b, c): +1 outward, -1 folded, 0 degenerate
  };

  struct Primitive;
  int BuildNode(std::int32_t node, std::vector<Primitive>& primitives, const Triangles& triangles,
    const Points& unitPoints, std::int32_t begin, std::int32_t end);
  bool Contains(
    const LeafTriangle& triangle, const Eigen::Vector3d& p, Eigen::Vector3d& barycentric) const;
  SphericalLocation LocateNearest(const Eigen::Vector3d& p) const;

  Points SpherePoints; // the input points, as given
  std::vector<Node> Nodes;
  std::vector<LeafTriangle> LeafTriangles;
  int Depth = 0;
};
}

#endif
