// The dense correspondence of two spherical maps (vtkDenseCorrespondence's work, the paper's
// §7.4): every point of the query map located in the other map's spherical triangulation
// (its triangle and barycentric coordinates), each landmark put on its partner's vertex
// itself, and how far the points that fell in no triangle had to be moved. Every message of
// the location is made here (the filter adds only its own: an input it cannot read).
#ifndef mobius_DenseCorrespondence_h
#define mobius_DenseCorrespondence_h

#include "MeshTypes.h"

#include <string>
#include <utility>
#include <vector>

namespace mobius
{
/// One spherical map as the filter read it.
struct CorrespondenceMap
{
  Points Sphere; ///< unit vectors
  mobius::Triangles Triangles;
  std::string Name; ///< what messages call it, e.g. "Target (port 1)"
};

struct DenseCorrespondenceParameters
{
  /// Locate the target's points in the source (the inverse map) instead of the source's in
  /// the target.
  bool TargetToSource = false;
  /// Point ids of the source and of the target map: the query's landmark is put on the
  /// located map's landmark vertex.
  std::vector<std::pair<Index, Index>> Landmarks;
  /// Threads of the point location (already resolved: at least 1).
  int NumberOfThreads = 1;
  /// The fraction of the whole correspondence done; returning false stops it.
  ProgressCallback Progress;
};

struct DenseCorrespondence
{
  /// The message of the reason the maps cannot be put in correspondence; empty on success.
  std::string Error;
  /// Progress asked to stop: no result and no error.
  bool Stopped = false;
  /// Per query point, the triangle of the located map it is in and its barycentric
  /// coordinates there (normalized, the combination of the corners is the point).
  std::vector<Index> Triangle;
  std::vector<Eigen::Vector3d> Barycentric;
  /// Points that floating point put in no triangle (or that fell in a hole), moved to the
  /// nearest point of the nearest triangle; the largest angle (radians) one was moved.
  Index ClampedPoints = 0;
  double MaximumClampDistance = 0;
};

/// Locates the query map's points (the source's, or the target's with TargetToSource) in
/// the other map; `maps` are the source and the target, the located one with triangles.
DenseCorrespondence CorrespondSphericalMaps(
  const CorrespondenceMap maps[2], const DenseCorrespondenceParameters& parameters);
}

#endif
