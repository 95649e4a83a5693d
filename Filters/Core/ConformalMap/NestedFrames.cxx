#include "NestedFrames.h"

#include <algorithm>

namespace mobius
{
NestedFrames::NestedFrames(const Points& sphere)
  : Positions(sphere)
  , Deepest(static_cast<size_t>(sphere.rows()), -1)
  , DeepestRow(static_cast<size_t>(sphere.rows()), -1)
{
}

Index NestedFrames::Find(const Level& level, Index v)
{
  const auto found = std::lower_bound(level.Members.begin(), level.Members.end(), v);
  return found != level.Members.end() && *found == v ? found - level.Members.begin() : -1;
}

Eigen::RowVector3d NestedFrames::LevelDifference(Index a, Index b) const
{
  const int deepest = this->Deepest[a];
  if (deepest >= 0 && deepest == this->Deepest[b])
  {
    // The usual case, two neighbours of one squeezed region: no search.
    const Level& level = this->Levels[deepest];
    const Index ra = this->DeepestRow[a], rb = this->DeepestRow[b];
    if (level.Region[ra] == level.Region[rb])
    {
      return level.Local.row(ra) - level.Local.row(rb);
    }
  }
  for (int j = std::min(this->Deepest[a], this->Deepest[b]); j >= 0; --j)
  {
    const Level& level = this->Levels[j];
    const Index ra = Find(level, a), rb = Find(level, b);
    if (ra >= 0 && rb >= 0 && level.Region[ra] == level.Region[rb])
    {
      return level.Local.row(ra) - level.Local.row(rb);
    }
  }
  return this->Positions.Difference(a, b);
}

Vector NestedFrames::LongestEdges(const Triangles& triangles) const
{
  Vector longest = Vector::Zero(this->Positions.High.rows());
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index a = triangles(t, k), b = triangles(t, (k + 1) % 3);
      const double length = this->Difference(a, b).norm();
      longest[a] = std::max(longest[a], length);
      longest[b] = std::max(longest[b], length);
    }
  }
  return longest;
}

void NestedFrames::AddLevel(const std::vector<Index>& members, const std::vector<Index>& region,
  const std::vector<Index>& origins, const Eigen::MatrixXd& offsets)
{
  // Each member's new position in each shallower level that holds it: the origin's old
  // position there plus the offset (accurate relative to that level's scale, all that level
  // is asked for). Read the origins' old coordinates before any member changes.
  const int depth = static_cast<int>(this->Levels.size());
  for (int j = 0; j < depth; ++j)
  {
    Level& level = this->Levels[j];
    std::vector<Eigen::RowVector3d> originLocal(origins.size());
    std::vector<char> originFound(origins.size(), 0);
    for (size_t r = 0; r < origins.size(); ++r)
    {
      const Index row = Find(level, origins[r]);
      if (row >= 0)
      {
        originLocal[r] = level.Local.row(row);
        originFound[r] = 1;
      }
    }
    for (size_t m = 0; m < members.size(); ++m)
    {
      const Index row = Find(level, members[m]);
      if (row >= 0 && originFound[region[m]])
      {
        level.Local.row(row) = originLocal[region[m]] + offsets.row(static_cast<Index>(m));
      }
    }
  }
  std::vector<ExtendedPoint> originPoints(origins.size());
  for (size_t r = 0; r < origins.size(); ++r)
  {
    originPoints[r] = this->Positions.Point(origins[r]);
  }
  for (size_t m = 0; m < members.size(); ++m)
  {
    this->Positions.Set(members[m], originPoints[region[m]], offsets.row(static_cast<Index>(m)));
    this->Deepest[members[m]] = depth;
    this->DeepestRow[members[m]] = static_cast<Index>(m);
  }
  this->Levels.push_back({ members, region, offsets });
}

void NestedFrames::MoveAbsolute(Index v, const ExtendedPoint& center, const Eigen::RowVector3d& offset)
{
  this->Positions.Set(v, center, offset);
  this->Deepest[v] = -1;
}
}
