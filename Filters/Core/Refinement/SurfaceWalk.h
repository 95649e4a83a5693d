// Closest points on a triangle mesh, found by walking from a nearby triangle: the local
// search the polish and the averaging of a map with its inverse both need, where the points
// move by a fraction of an edge between queries or start next to their answer.
#ifndef mobius_SurfaceWalk_h
#define mobius_SurfaceWalk_h

#include "MeshAdjacency.h"
#include "MeshTypes.h"

#include <Eigen/Core>

namespace mobius
{
/// The point of triangle abc closest to q, as barycentric coordinates `weights`; returns the
/// squared distance.
double ClosestOnTriangle(const Eigen::Vector3d& q, const Eigen::Vector3d& a,
  const Eigen::Vector3d& b, const Eigen::Vector3d& c, Eigen::Vector3d& weights);

/// Mean length of the triangles' edges (each interior edge counted twice).
double MeanEdgeLength(const Points& points, const Triangles& triangles);

/// A triangle mesh to walk on: its points, triangles and the triangles around each vertex.
struct SurfaceWalker
{
  const Points& Positions;
  const Triangles& Faces;
  const VertexLists& VertexFaces;

  /// Squared distance from q to triangle t; `weights`: the closest point's barycentrics.
  double Closest(const Eigen::Vector3d& q, Index t, Eigen::Vector3d& weights) const;

  /// The closest point to q reached by walking from triangle `t` to whichever triangle
  /// around its corners is closer, as long as one is (at most kMaximumWalkSteps steps); `t`
  /// and `weights` end at it, the squared distance is returned. With `insideIsEnough` the
  /// walk is local: a point that projects inside its triangle stops there (exact on a flat
  /// neighbourhood, off by a second-order amount on a curved one), one that projects onto
  /// an edge or a corner looks only at the triangles around that edge's ends or that corner
  /// (looking across the edge alone left the polish's maps about 1% worse). Good enough
  /// between the polish's iterations, where the points move by a fraction of an edge, at a
  /// fraction of the cost.
  double Walk(const Eigen::Vector3d& q, Index& t, Eigen::Vector3d& weights,
    bool insideIsEnough = false) const;

  /// The point of triangle t at barycentrics `weights`.
  Eigen::Vector3d Point(Index t, const Eigen::Vector3d& weights) const;

private:
  static constexpr int kMaximumWalkSteps = 64;
  /// The triangles around vertex v but t: the closest to q replaces `next`, `best` and
  /// `weights` if it is closer than `best`.
  void CloserAround(const Eigen::Vector3d& q, Index v, Index t, double& best, Index& next,
    Eigen::Vector3d& weights) const;
  /// The local walk of Walk(insideIsEnough), from t whose closest point is `weights` at
  /// squared distance `best`.
  double QuickWalk(const Eigen::Vector3d& q, Index& t, Eigen::Vector3d& weights, double best) const;
};
}

#endif
