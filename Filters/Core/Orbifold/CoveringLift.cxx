#include "CoveringLift.h"

#include "MeshAdjacency.h"
#include "MapDistortion.h"

#include <Eigen/Geometry>

#include <cmath>
#include <complex>
#include <vector>

namespace mobius
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

double WrapAngle(double angle)
{
  return std::remainder(angle, 2.0 * Pi); // in [-pi, pi]
}
}

bool LiftSphericalMapToCovering(const Points& sphereMap, const Triangles& triangles,
  const CyclicCovering& covering, Points& lifted, std::string& error)
{
  const Index V = covering.NumberOfInputVertices;
  const Index F = triangles.rows();
  const int n = covering.Copies;
  if (sphereMap.rows() != V || !sphereMap.allFinite())
  {
    error = "the spherical map to lift has the wrong number of points or non-finite ones";
    return false;
  }
  const Index cone0 = covering.CutPath.front(), cone1 = covering.CutPath.back();

  // Stereographic coordinate from cone 1's image, cone 0's image moved to 0.
  const Eigen::Vector3d north = sphereMap.row(cone1).normalized();
  Eigen::Vector3d e1 = north.unitOrthogonal();
  const Eigen::Vector3d e2 = north.cross(e1);
  std::vector<std::complex<double>> z(static_cast<size_t>(V));
  for (Index v = 0; v < V; ++v)
  {
    if (v == cone1)
    {
      continue;
    }
    const Eigen::Vector3d x = sphereMap.row(v).normalized();
    // 1 - x.n, computed as |x - n|^2 / 2: exact for the points a squeezed limb puts 1e-8
    // from the cone's image, where 1 - x.n cancels to nothing.
    const double denominator = 0.5 * (x - north).squaredNorm();
    if (!(denominator > 0.0))
    {
      error = "a vertex lies on the image of cone 1 in the spherical map; cannot lift it";
      return false;
    }
    z[v] = std::complex<double>(x.dot(e1), x.dot(e2)) / denominator;
  }
  const std::complex<double> z0 = z[cone0];
  double logScale = 0.0;
  for (Index v = 0; v < V; ++v)
  {
    if (v == cone0 || v == cone1)
    {
      continue;
    }
    z[v] -= z0;
    if (!(std::abs(z[v]) > 0.0))
    {
      error = "a vertex lies on the image of cone 0 in the spherical map; cannot lift it";
      return false;
    }
    logScale += std::log(std::abs(z[v]));
  }
  const double scale = std::exp(logScale / static_cast<double>(V - 2)); // geometric mean

  // arg z continued over copy 0 (the cut surface), walking its edges away from the cones.
  const Index total = static_cast<Index>(covering.SourceVertex.size());
  const Triangles copy0 = covering.CoveringTriangles.topRows(F);
  const VertexLists neighbors = VertexNeighbors(total, copy0);
  std::vector<double> angle(static_cast<size_t>(total), 0.0);
  std::vector<char> reached(static_cast<size_t>(total), 0);
  const Index start = copy0(0, 0) < total - 2 ? copy0(0, 0)
                                               : (copy0(0, 1) < total - 2 ? copy0(0, 1) : copy0(0, 2));
  auto zOf = [&](Index w) { return z[covering.SourceVertex[w]]; };
  angle[start] = std::arg(zOf(start));
  reached[start] = 1;
  std::vector<Index> queue{ start };
  for (size_t q = 0; q < queue.size(); ++q)
  {
    const Index w = queue[q];
    for (Index k = neighbors.Begin(w); k < neighbors.End(w); ++k)
    {
      const Index u = neighbors.Items[k];
      if (u >= total - 2 || reached[u])
      {
        continue; // a cone, or done
      }
      angle[u] = angle[w] + WrapAngle(std::arg(zOf(u)) - std::arg(zOf(w)));
      reached[u] = 1;
      queue.push_back(u);
    }
  }

  // The turn direction: the left side of the cut (copy 1's vertices in copy 0) is one full
  // turn from the right side (copy 0's own).
  int turn = 0;
  for (size_t j = 1; j + 1 < covering.CutPath.size(); ++j)
  {
    const Index p = covering.CutPath[j];
    const Index right = covering.Vertex(0, p), left = covering.Vertex(1 % n, p);
    if (!reached[right] || !reached[left])
    {
      error = "the cut surface minus the cones is not connected; cannot lift the map";
      return false;
    }
    const double turns = (angle[left] - angle[right]) / (2.0 * Pi);
    const int s = static_cast<int>(std::lround(turns));
    if ((s != 1 && s != -1) || std::abs(turns - s) > 1e-6 || (turn != 0 && s != turn))
    {
      error = "the spherical map does not wrap once around the cone along the cut (it folds "
              "near the cut); cannot lift it";
      return false;
    }
    turn = s;
  }

  lifted.resize(total, 3);
  for (Index w = 0; w < total - 2; ++w)
  {
    const int copy = covering.VertexCopy[w];
    const Index v = covering.SourceVertex[w];
    const Index base = covering.Vertex(0, v);
    if (!reached[base])
    {
      error = "the cut surface minus the cones is not connected; cannot lift the map";
      return false;
    }
    const double theta = (angle[base] + 2.0 * Pi * turn * copy) / n;
    const double radius = std::pow(std::abs(z[v]) / scale, 1.0 / n);
    const std::complex<double> lift = std::polar(radius, theta);
    const double r2 = std::norm(lift);
    lifted.row(w) << 2.0 * lift.real() / (r2 + 1.0), 2.0 * lift.imag() / (r2 + 1.0),
      (r2 - 1.0) / (r2 + 1.0);
  }
  lifted.row(covering.ConeVertices[0]) << 0.0, 0.0, -1.0;
  lifted.row(covering.ConeVertices[1]) << 0.0, 0.0, 1.0;

  // Keep the triangles facing outward (the stereographic frame may have mirrored them):
  // mirroring across the xz-plane keeps the cones in place.
  double volume = 0.0;
  for (Index t = 0; t < covering.CoveringTriangles.rows(); ++t)
  {
    volume += SignedVolume(lifted.row(covering.CoveringTriangles(t, 0)),
      lifted.row(covering.CoveringTriangles(t, 1)), lifted.row(covering.CoveringTriangles(t, 2)));
  }
  if (volume < 0.0)
  {
    lifted.col(1) *= -1.0;
  }
  return lifted.allFinite();
}
}
