// The positions of a spherical map whose squeezed regions are re-solved level by level, each
// level in coordinates relative to a point of its own region.
//
// Why: a conformal map squeezes a tail or finger exponentially, to 1e-30 across and far
// beyond; absolute coordinates, even in double-double (ExtendedPoints.h, 1e-32), cannot
// hold such a tip. Each level's solution is accurate relative to its own region's size, so
// we keep it: the difference of two vertices is taken in the deepest level whose region
// holds both, where it is accurate relative to their distance, however small. The squeezed
// regions can then be resolved to any depth double's exponent allows (1e-300), and the
// spreading of tips (SqueezedTipSpreading.h) works from exact offsets.
#ifndef mobius_NestedFrames_h
#define mobius_NestedFrames_h

#include "ExtendedPoints.h"
#include "MeshTypes.h"

#include <vector>

namespace mobius
{
class NestedFrames
{
public:
  explicit NestedFrames(const Points& sphere);

  /// Point a minus point b, from the deepest level whose region holds both (or from the
  /// absolute positions if none does).
  Eigen::RowVector3d Difference(Index a, Index b) const
  {
    return this->Deepest[a] < 0 || this->Deepest[b] < 0 ? this->Positions.Difference(a, b)
                                                        : this->LevelDifference(a, b);
  }

  /// The longest edge at each vertex.
  Vector LongestEdges(const Triangles& triangles) const;

  /// Adds a level: `members` (ascending vertex numbers), the region of each, and their
  /// positions relative to the position `origins[region]` (a vertex) had before. The
  /// members' coordinates in the shallower levels and the absolute positions follow.
  void AddLevel(const std::vector<Index>& members, const std::vector<Index>& region,
    const std::vector<Index>& origins, const Eigen::MatrixXd& offsets);

  /// Moves vertex v to `center` + `offset` (absolute), leaving the levels (its coordinates
  /// there are no longer kept: its differences come from the absolute positions).
  void MoveAbsolute(Index v, const ExtendedPoint& center, const Eigen::RowVector3d& offset);

  const ExtendedPoints& Absolute() const { return this->Positions; }

private:
  struct Level
  {
    std::vector<Index> Members; ///< ascending
    std::vector<Index> Region;
    Eigen::MatrixXd Local;      ///< one row per member
  };
  /// Difference of two vertices that are both in some level.
  Eigen::RowVector3d LevelDifference(Index a, Index b) const;
  /// Row of vertex v in `level`, -1 if it is not a member.
  static Index Find(const Level& level, Index v);

  ExtendedPoints Positions;
  std::vector<Level> Levels;
  std::vector<int> Deepest; ///< per vertex: the deepest level holding it, -1 for none
  std::vector<Index> DeepestRow; ///< per vertex: its row in that level
};
}

#endif
