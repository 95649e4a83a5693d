// An asymmetric test surface given by its conformal map: the unit sphere stretched, with a
// bulge toward +x+y, so that its centered map is not the identity and has no symmetry. For
// the core tests of the centering and the rotational alignment, without data files.
#ifndef mobius_BumpySurface_h
#define mobius_BumpySurface_h

#include "MeshTypes.h"

#include <functional>

namespace mobius
{
/// Per triangle of the sphere mesh, the area of its image under `embed` (a smooth map of
/// R^3): the areas a spherical map of the embedded surface on this mesh carries.
Vector EmbeddedTriangleAreas(const Points& sphere, const Triangles& triangles,
  const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& embed);

/// The surface's point over the unit vector `x`.
Eigen::Vector3d BumpySurfacePoint(const Eigen::Vector3d& x);

/// EmbeddedTriangleAreas through BumpySurfacePoint.
Vector BumpySurfaceAreas(const Points& sphere, const Triangles& triangles);
}

#endif
