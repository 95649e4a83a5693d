// An exactly mirror-symmetric closed surface with known mirror pairs, for the symmetry
// tests: a four-legged "creature" (body, head, tail, legs as smooth bumps) grown from an
// icosphere, whose connectivity is symmetric under z -> -z; the positions are made exactly
// symmetric (one of each pair is the other with z negated, vertices on the plane get z = 0).
//
// (Gluing a clipped half of a real mesh to its mirror image was tried first: CGAL's cow has
// its tail in the mirror plane, so the clipped half has a ribbon for a tail and the conformal
// map folds; the camel's midplane section makes a genus-1 surface.)
#ifndef MirrorSymmetricMesh_h
#define MirrorSymmetricMesh_h

#include "Icosphere.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace mobius_test
{
struct MirrorSymmetricMesh
{
  vtkSmartPointer<vtkPolyData> Mesh;
  /// Partner[v]: the vertex at the mirror position of v (v itself on the plane z = 0).
  std::vector<vtkIdType> Partner;
  /// Largest distance between a mirrored icosphere vertex and its partner before the
  /// positions were symmetrized: the icosphere's own symmetry (tests check it is tiny).
  double IcosphereAsymmetry = 0;
};

inline MirrorSymmetricMesh MakeMirrorSymmetricCreature(int levels = 4)
{
  mobius::Points sphere;
  mobius::Triangles triangles;
  mobius::MakeIcosphere(levels, sphere, triangles);
  const Eigen::Index n = sphere.rows();
  MirrorSymmetricMesh result;
  result.Partner.resize(n);
  for (Eigen::Index v = 0; v < n; ++v)
  {
    Eigen::RowVector3d mirrored = sphere.row(v);
    mirrored.z() = -mirrored.z();
    Eigen::Index nearest = 0;
    const double distance =
      std::sqrt((sphere.rowwise() - mirrored).rowwise().squaredNorm().minCoeff(&nearest));
    result.Partner[v] = nearest;
    result.IcosphereAsymmetry = std::max(result.IcosphereAsymmetry, distance);
  }

  // Smooth bumps on the unit sphere, in mirror pairs or on the plane: four legs, a head, a
  // tail; then the body is stretched along x. Front and back differ (a big head, a thin
  // tail, front and hind legs of different sizes) so that the only mirror symmetry is z.
  struct Bump
  {
    Eigen::Vector3d Center;
    double Height, Width;
  };
  std::vector<Bump> bumps = {
    { Eigen::Vector3d(0.9, 0.45, 0.0), 0.7, 0.3 },   // head
    { Eigen::Vector3d(-1.0, 0.3, 0.0), 0.3, 0.12 },  // tail
  };
  for (double side : { 1.0, -1.0 })
  {
    bumps.push_back({ Eigen::Vector3d(0.6, -0.75, 0.4 * side), 0.65, 0.18 });  // front leg
    bumps.push_back({ Eigen::Vector3d(-0.4, -0.75, 0.4 * side), 0.45, 0.25 }); // hind leg
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  for (Eigen::Index v = 0; v < n; ++v)
  {
    const Eigen::Index p = result.Partner[v];
    if (p < v)
    {
      continue; // placed as the mirror image of its partner
    }
    const Eigen::Vector3d u = sphere.row(v).transpose();
    double radius = 1.0;
    for (const Bump& bump : bumps)
    {
      radius += bump.Height * std::exp(-(u - bump.Center.normalized()).squaredNorm() /
                  (bump.Width * bump.Width));
    }
    Eigen::Vector3d position = radius * u;
    position.x() *= 1.8;
    position.z() *= 0.8;
    if (p == v)
    {
      position.z() = 0;
    }
    points->SetPoint(v, position.data());
    position.z() = -position.z();
    points->SetPoint(p, position.data());
  }
  vtkNew<vtkCellArray> polys;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    const vtkIdType ids[3] = { triangles(t, 0), triangles(t, 1), triangles(t, 2) };
    polys->InsertNextCell(3, ids);
  }
  result.Mesh = vtkSmartPointer<vtkPolyData>::New();
  result.Mesh->SetPoints(points);
  result.Mesh->SetPolys(polys);
  return result;
}
}

#endif
