// Points held to about 32 significant digits, as unevaluated sums High + Low of two doubles
// (Low below half an ulp of High: "double-double" arithmetic, Dekker 1971).
//
// Why: a conformal map squeezes a tail or finger exponentially; on the unit sphere its tip
// can be 1e-25 across, while a double coordinate near 1 is resolved only to 1e-16. The
// squeezed-region refinement re-solves such regions relative to a point of the region (so
// the solution itself is accurate relative to the region's size), and keeps the result in
// this form, so that a region nested inside it can be re-solved in turn from accurate
// boundary values.
#ifndef mobius_ExtendedPoints_h
#define mobius_ExtendedPoints_h

#include "MeshTypes.h"

namespace mobius
{
struct ExtendedPoint
{
  Eigen::RowVector3d High = Eigen::RowVector3d::Zero();
  Eigen::RowVector3d Low = Eigen::RowVector3d::Zero();
};

class ExtendedPoints
{
public:
  explicit ExtendedPoints(const Points& points)
    : High(points)
    , Low(Points::Zero(points.rows(), 3))
  {
  }

  ExtendedPoint Point(Index v) const { return { this->High.row(v), this->Low.row(v) }; }

  /// Point a minus point b, accurate to about 1e-32 absolutely (the difference of the high
  /// parts of nearby points is exact).
  Eigen::RowVector3d Difference(Index a, Index b) const
  {
    return (this->High.row(a) - this->High.row(b)) + (this->Low.row(a) - this->Low.row(b));
  }
  Eigen::RowVector3d Difference(Index a, const ExtendedPoint& b) const
  {
    return (this->High.row(a) - b.High) + (this->Low.row(a) - b.Low);
  }

  /// Sets point v to origin + offset, keeping the digits the offset adds below the origin's.
  void Set(Index v, const ExtendedPoint& origin, const Eigen::RowVector3d& offset)
  {
    for (int k = 0; k < 3; ++k)
    {
      // Knuth's two-sum: sum + error == origin.High + offset exactly.
      const double sum = origin.High[k] + offset[k];
      const double back = sum - origin.High[k];
      const double error = (origin.High[k] - (sum - back)) + (offset[k] - back);
      const double low = error + origin.Low[k];
      const double high = sum + low; // renormalize: |low| below half an ulp of high
      this->High(v, k) = high;
      this->Low(v, k) = low - (high - sum);
    }
  }

  Points High, Low;
};
}

#endif
