// Exactness of a self-map where the spherical map is exactly symmetric. The conformal map of
// an exactly mirror-symmetric mesh is itself symmetric, so its reflection sends each vertex
// exactly onto its mirror partner on the sphere; a refined map, interpolated in a truncated
// eigenbasis, only comes near it. Where the reflected sphere point of a vertex coincides with
// a vertex (to a small fraction of the local vertex spacing on the sphere), that vertex is
// the image. On a mesh without exact symmetry a reflected point almost never falls that close
// to a vertex, and moving it there changes the map by less than the tolerance.
#ifndef mobius_VertexSnapping_h
#define mobius_VertexSnapping_h

#include "MeshTypes.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace mobius
{
/// For every vertex v whose reflected sphere point `reflectedSphere.row(v)` lies within
/// `relativeTolerance` x (the shortest sphere edge at w) of a vertex w of (`sphere`,
/// `triangles`), sets `triangle[v]` to a triangle with corner w and `barycentric[v]` to that
/// corner's unit vector. Returns how many vertices were snapped, or -1 with `error` set if
/// the sphere cannot be searched.
Index SnapToCoincidentVertices(const Points& reflectedSphere, const Points& sphere,
  const Triangles& triangles, double relativeTolerance, std::vector<Index>& triangle,
  std::vector<Eigen::Vector3d>& barycentric, std::string& error);
}

#endif
