#include "FlowInput.h"

#include "MapDistortion.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <sstream>
#include <vector>

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

std::string CheckCoordinateRange(const Points& points, const Triangles& triangles)
{
  std::vector<double> edges;
  double largest = 0;
  Index farthest = -1;
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index a = triangles(t, k), b = triangles(t, (k + 1) % 3);
      if (a < 0 || b < 0 || a >= points.rows() || b >= points.rows() || !points.row(a).allFinite())
      {
        continue;
      }
      const double magnitude = points.row(a).cwiseAbs().maxCoeff();
      if (magnitude > largest)
      {
        largest = magnitude;
        farthest = a;
      }
      const double length = (points.row(a) - points.row(b)).cwiseAbs().maxCoeff();
      if (length > 0 && std::isfinite(length))
      {
        edges.push_back(length);
      }
    }
  }
  if (edges.empty())
  {
    return {};
  }
  std::nth_element(edges.begin(), edges.begin() + static_cast<long>(edges.size() / 2), edges.end());
  const double median = edges[edges.size() / 2];
  if (!(largest > 1e100 * median))
  {
    return {};
  }
  std::ostringstream message;
  message << "point " << farthest << " is " << largest << " from the origin while the median edge is "
          << median << " long: double precision cannot compute the surface's areas over that "
          << "range (a stray point? remove it or rescale)";
  return message.str();
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
