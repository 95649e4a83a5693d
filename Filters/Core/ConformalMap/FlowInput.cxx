#include "FlowInput.h"

#include "MapDistortion.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <sstream>

namespace mobius
{
int ScaleToUnitOrder(Points& points, const Triangles& triangles)
{
  double largestCoordinate = 0.0;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index v = triangles(t, k);
      for (int c = 0; v >= 0 && v < points.rows() && c < 3; ++c)
      {
        const double magnitude = std::abs(points(v, c));
        largestCoordinate = std::isfinite(magnitude) ? std::max(largestCoordinate, magnitude) : largestCoordinate;
      }
    }
  }
  const int scaleExponent = largestCoordinate > 0.0 ? std::ilogb(largestCoordinate) : 0;
  points *= std::ldexp(1.0, -scaleExponent);
  return scaleExponent;
}

bool FaceOutward(const Points& points, Triangles& triangles)
{
  const bool reversed = EnclosedVolume(points, triangles) < 0;
  if (reversed)
  {
    triangles.col(1).swap(triangles.col(2));
  }
  return reversed;
}

bool TriangleAreasAtScale(const Points& points, const Triangles& triangles, int scaleExponent,
  Vector& areas, std::string& problem)
{
  areas.resize(triangles.rows());
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    const Eigen::Vector3d a = points.row(triangles(t, 0)), b = points.row(triangles(t, 1)),
                          c = points.row(triangles(t, 2));
    const double area = 0.5 * (b - a).cross(c - a).norm();
    areas[t] = std::ldexp(area, 2 * scaleExponent);
    // Exactly 0 is three points on a line, which the flow takes; a positive area must stay
    // a normal double at the input's scale.
    if (!std::isfinite(areas[t]) || (area != 0.0 && !(areas[t] >= DBL_MIN)))
    {
      std::ostringstream message;
      message << "its triangles' areas (triangle " << t << ": 2^"
              << std::ilogb(area) + 2 * scaleExponent
              << ") are beyond what double precision represents; rescale the mesh";
      problem = message.str();
      return false;
    }
  }
  return true;
}
}
