// Conformal scale factors of a spherical map, rasterized exactly onto the cell-centered N x N
// equirectangular grid used by the spherical harmonic transform (see SphericalHarmonics.h for
// the grid layout: values[j*N + i], row j = latitude band from the north pole).
//
// A cell's value is the original-surface area whose spherical image falls in the cell,
// divided by the cell's spherical area (2 pi/N)(cos theta_j - cos theta_{j+1}). The spherical
// image of a triangle is the geodesic triangle on its three mapped vertices (equivalently, the
// central projection of the flat chord triangle). Each triangle's original area is split among
// the cells in proportion to the exact spherical area of geodesic triangle intersect cell, so
// point sampling's aliasing (a conformal map squeezes whole limbs into tiny regions) cannot occur
// and the grid integrates to the total area to round-off.
#ifndef mobius_SphericalAreaGrid_h
#define mobius_SphericalAreaGrid_h

#include "MeshTypes.h"

#include <string>
#include <vector>

namespace mobius
{
/// The smallest grid size N: the grid has N x N cells, N even.
inline constexpr int MinimumGridResolution = 4;

/// What a cell stores: the area ratio lambda, or sqrt(lambda) (the authors' choice, so that
/// the integral of f^2 over the sphere is the total area).
enum class ScaleFactorValue
{
  AreaRatio,
  SquareRootAreaRatio
};

struct SphericalAreaGridResult
{
  int Resolution = 0;         // N
  std::vector<double> Values; // N*N, values[j*N + i]
  double TotalArea = 0.0;     // sum of the triangle areas (= sum over cells of lambda * cell area)
};

/// Spherical area of grid cell row j (all cells of a row have the same area).
double SphericalGridCellArea(int resolution, int row);

/// Rasterizes the areas of a spherical map. spherePoints: points on the unit sphere (within
/// 1e-6; they are normalized internally); triangles: vertex indices; triangleAreas: one finite,
/// non-negative original-surface area per triangle. resolution N: even, >= 4.
/// Triangles whose spherical image has (numerically) zero area put all their area into the
/// cell of their centroid. Returns false with a message naming the problem for bad input, or
/// when `progress` returns false (aborted). numberOfThreads = 0: automatic (ResolveThreadCount);
/// the grid is the same bit for bit on any number of threads.
bool RasterizeSphericalAreas(const Points& spherePoints, const Triangles& triangles,
  const Vector& triangleAreas, int resolution, ScaleFactorValue value,
  SphericalAreaGridResult& result, std::string& error, const ProgressCallback& progress = {},
  int numberOfThreads = 0);
}

#endif
