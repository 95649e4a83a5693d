// Meshes the conformal map must handle as a user would bring them: CGAL's CC0 meshes
// decimated or subdivided-then-decimated to 3K-10K vertices (other triangulations of the
// same shapes, with the needles and uneven sizes that decimation leaves), and generated
// shapes with long thin limbs, tails and fingers (the parts a conformal map squeezes
// exponentially). Built in code from build/data/meshes, deterministic.
#ifndef ConformalMapCorpus_h
#define ConformalMapCorpus_h

#include "vtkCleanPolyData.h"
#include "vtkLoopSubdivisionFilter.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkQuadricDecimation.h"
#include "vtkSmartPointer.h"
#include "vtkSurfaceMeshReader.h"
#include "vtkTriangleFilter.h"

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace mobius_corpus
{
/// A corpus entry: its name and how to make it (made on demand: some take a while).
struct CorpusMesh
{
  std::string Name;
  std::function<vtkSmartPointer<vtkPolyData>()> Make;
};

inline vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path)
{
  vtkNew<vtkSurfaceMeshReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(reader->GetOutputPort());
  triangles->Update();
  return triangles->GetOutput();
}

inline vtkSmartPointer<vtkPolyData> LoopSubdivided(vtkPolyData* mesh, int levels)
{
  vtkNew<vtkLoopSubdivisionFilter> loop;
  loop->SetInputData(mesh);
  loop->SetNumberOfSubdivisions(levels);
  loop->Update();
  return loop->GetOutput();
}

/// Quadric decimation to about `vertices` vertices (a closed triangle mesh has about twice as
/// many triangles as vertices).
inline vtkSmartPointer<vtkPolyData> Decimated(vtkPolyData* mesh, vtkIdType vertices)
{
  const double keep = static_cast<double>(vertices) / mesh->GetNumberOfPoints();
  if (keep >= 1.0)
  {
    return mesh;
  }
  vtkNew<vtkQuadricDecimation> decimate;
  decimate->SetInputData(mesh);
  decimate->SetTargetReduction(1.0 - keep);
  decimate->VolumePreservationOn();
  vtkNew<vtkCleanPolyData> clean; // decimation leaves unused points
  clean->SetInputConnection(decimate->GetOutputPort());
  clean->PointMergingOff();
  clean->Update();
  return clean->GetOutput();
}

/// A closed quad mesh grown by extrusion, the way shapes are modelled for subdivision: a box,
/// then limbs, necks and tails pulled out of its faces ring by ring. Every extrusion keeps the
/// surface closed, manifold, genus 0 and outward-facing.
class QuadModel
{
public:
  using Quad = std::array<int, 4>;

  /// A box [-size/2, size/2] divided into n[0] x n[1] x n[2] quads along its axes.
  QuadModel(const Eigen::Vector3d& size, const std::array<int, 3>& n)
  {
    std::map<std::array<int, 3>, int> ids; // grid coordinates -> vertex
    auto vertex = [&](std::array<int, 3> g) {
      auto found = ids.find(g);
      if (found != ids.end())
      {
        return found->second;
      }
      Eigen::Vector3d p;
      for (int k = 0; k < 3; ++k)
      {
        p[k] = size[k] * (static_cast<double>(g[k]) / n[k] - 0.5);
      }
      this->Points.push_back(p);
      ids.emplace(g, static_cast<int>(this->Points.size()) - 1);
      return static_cast<int>(this->Points.size()) - 1;
    };
    for (int axis = 0; axis < 3; ++axis)
    {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3; // (u, v, axis) right-handed
      for (int side = 0; side < 2; ++side)
      {
        for (int i = 0; i < n[u]; ++i)
        {
          for (int j = 0; j < n[v]; ++j)
          {
            std::array<int, 3> g00{}, g10{}, g11{}, g01{};
            for (auto* g : { &g00, &g10, &g11, &g01 })
            {
              (*g)[axis] = side * n[axis];
            }
            g00[u] = i, g00[v] = j;
            g10[u] = i + 1, g10[v] = j;
            g11[u] = i + 1, g11[v] = j + 1;
            g01[u] = i, g01[v] = j + 1;
            const Quad q{ vertex(g00), vertex(g10), vertex(g11), vertex(g01) }; // faces +axis
            this->Quads.push_back(side ? q : Quad{ q[0], q[3], q[2], q[1] });
          }
        }
      }
    }
  }

  Eigen::Vector3d Center(int face) const
  {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int v : this->Quads[face])
    {
      c += this->Points[v] / 4;
    }
    return c;
  }

  Eigen::Vector3d Normal(int face) const
  {
    const Quad& q = this->Quads[face];
    return (this->Points[q[2]] - this->Points[q[0]])
      .cross(this->Points[q[3]] - this->Points[q[1]])
      .normalized();
  }

  /// The face whose center is nearest to `point`.
  int FaceNear(const Eigen::Vector3d& point) const
  {
    int best = 0;
    for (int f = 1; f < static_cast<int>(this->Quads.size()); ++f)
    {
      if ((this->Center(f) - point).squaredNorm() < (this->Center(best) - point).squaredNorm())
      {
        best = f;
      }
    }
    return best;
  }

  /// Pulls `face` out by `offset`, scaling it by `scale` about its center; the face keeps its
  /// index (now the moved copy) and four side quads join it to where it was.
  void Extrude(int face, const Eigen::Vector3d& offset, double scale)
  {
    const Quad old = this->Quads[face];
    const Eigen::Vector3d center = this->Center(face);
    Quad moved;
    for (int k = 0; k < 4; ++k)
    {
      this->Points.push_back(center + scale * (this->Points[old[k]] - center) + offset);
      moved[k] = static_cast<int>(this->Points.size()) - 1;
    }
    this->Quads[face] = moved;
    for (int k = 0; k < 4; ++k)
    {
      const int next = (k + 1) % 4;
      this->Quads.push_back({ old[k], old[next], moved[next], moved[k] });
    }
  }

  /// A limb of `rings` extrusions from `face`: each ring moves `step` along `direction`
  /// (which may turn: it is called with the ring's index) and scales the cross-section by
  /// `taper`.
  void Limb(int face, int rings, double step, double taper,
    const std::function<Eigen::Vector3d(int)>& direction)
  {
    for (int r = 0; r < rings; ++r)
    {
      this->Extrude(face, step * direction(r).normalized(), taper);
    }
  }

  /// Triangles (each quad split along a diagonal), Loop-subdivided `levels` times.
  vtkSmartPointer<vtkPolyData> Subdivided(int levels) const
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (const auto& p : this->Points)
    {
      points->InsertNextPoint(p.data());
    }
    vtkNew<vtkCellArray> triangles;
    for (const Quad& q : this->Quads)
    {
      const vtkIdType a[3] = { q[0], q[1], q[2] }, b[3] = { q[0], q[2], q[3] };
      triangles->InsertNextCell(3, a);
      triangles->InsertNextCell(3, b);
    }
    vtkNew<vtkPolyData> mesh;
    mesh->SetPoints(points);
    mesh->SetPolys(triangles);
    return levels > 0 ? LoopSubdivided(mesh, levels) : vtkSmartPointer<vtkPolyData>(mesh.Get());
  }

  std::vector<Eigen::Vector3d> Points;
  std::vector<Quad> Quads;
};

/// A four-legged animal: a body 3 x 1 x 1, four legs of width 0.2 and `legRings` rings of
/// 0.2 (length / width about legRings), a neck with a head, and a tail of width 0.2 and
/// `tailRings` rings of 0.2 that taper by `tailTaper` per ring.
inline vtkSmartPointer<vtkPolyData> Quadruped(int legRings, int tailRings, double tailTaper, int levels)
{
  QuadModel model(Eigen::Vector3d(3.0, 1.0, 1.0), { 6, 2, 2 });
  for (double x : { -1.25, 1.25 })
  {
    for (double y : { -0.25, 0.25 })
    {
      const int face = model.FaceNear({ x, y, -0.5 });
      model.Extrude(face, { 0, 0, -0.1 }, 0.4);
      model.Limb(face, legRings, 0.2, 1.0,
        [&](int r) { return Eigen::Vector3d(r > legRings / 2 ? 0.3 : 0.0, 0, -1); });
    }
  }
  // Neck up and forward, then the head forward.
  const int neck = model.FaceNear({ 1.5, 0.25, 0.25 });
  model.Extrude(neck, { 0.1, 0, 0 }, 0.8);
  model.Limb(neck, 4, 0.25, 1.0, [](int) { return Eigen::Vector3d(1, 0, 1); });
  model.Limb(neck, 3, 0.25, 1.15, [](int) { return Eigen::Vector3d(1, 0, -0.3); });
  model.Limb(neck, 1, 0.15, 0.6, [](int) { return Eigen::Vector3d(1, 0, -0.5); });
  // The tail: back, drooping.
  const int tail = model.FaceNear({ -1.5, 0.25, 0.25 });
  model.Extrude(tail, { -0.1, 0, 0 }, 0.4);
  model.Limb(tail, tailRings, 0.2, tailTaper,
    [&](int r) { return Eigen::Vector3d(-1, 0, -0.05 * r); });
  return model.Subdivided(levels);
}

/// A hand: a palm 1 x 0.25 x 1, four fingers of width 0.2 and `fingerRings` rings of 0.2, and
/// a thumb, each curled by `curl` radians per ring.
inline vtkSmartPointer<vtkPolyData> Hand(int fingerRings, double curl, int levels)
{
  QuadModel model(Eigen::Vector3d(1.0, 0.25, 1.0), { 4, 1, 4 });
  auto finger = [&](const Eigen::Vector3d& at, const Eigen::Vector3d& out, int rings) {
    const int face = model.FaceNear(at);
    model.Extrude(face, 0.05 * out, 0.8);
    const Eigen::Vector3d bend(0, -1, 0);
    model.Limb(face, rings, 0.2, 0.97,
      [&](int r) { return std::cos(curl * r) * out + std::sin(curl * r) * bend; });
  };
  for (int f = 0; f < 4; ++f)
  {
    finger({ -0.375 + 0.25 * f, 0, 0.5 }, { 0, 0, 1 }, fingerRings - (f == 0 || f == 3 ? 2 : 0));
  }
  finger({ 0.5, 0, -0.125 }, Eigen::Vector3d(1, 0, 0.5).normalized(), fingerRings - 3);
  // The wrist: a short stump.
  model.Limb(model.FaceNear({ -0.125, 0, -0.5 }), 2, 0.25, 1.0, [](int) { return Eigen::Vector3d(0, 0, -1); });
  return model.Subdivided(levels);
}

/// A cube with `spikes` straight spikes of width 1/3 x `scale` and `rings` rings of the same
/// length along its face normals (a sea urchin): the same thin part several times.
inline vtkSmartPointer<vtkPolyData> Urchin(int spikes, int rings, double scale, int levels)
{
  QuadModel model(Eigen::Vector3d(1.0, 1.0, 1.0), { 3, 3, 3 });
  const Eigen::Vector3d directions[6] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 },
    { 0, 0, 1 }, { 0, 0, -1 } };
  for (int s = 0; s < spikes && s < 6; ++s)
  {
    const Eigen::Vector3d d = directions[s];
    const int face = model.FaceNear(0.5 * d);
    model.Extrude(face, 0.05 * d, scale);
    model.Limb(face, rings, scale / 3, 1.0, [&](int) { return d; });
  }
  return model.Subdivided(levels);
}

/// A body 1.2 x 1 x 0.8 with six branches of different widths, lengths (about `length` rings
/// times 1.0, 0.8, 0.6, 0.5, 0.7, 0.9) and bends: thin parts without the symmetries of the
/// urchin, so that a map onto a bent copy has one right answer.
inline vtkSmartPointer<vtkPolyData> Branches(int length, int levels)
{
  QuadModel model(Eigen::Vector3d(1.2, 1.0, 0.8), { 3, 3, 3 });
  struct Branch
  {
    Eigen::Vector3d At, Out, Bend;
    double Share, Scale;
  };
  const Branch branches[6] = { { { 0.6, 0.0, 0.0 }, { 1, 0, 0 }, { 0, 0, 1 }, 1.0, 0.6 },
    { { -0.6, 0.33, 0.0 }, { -1, 0, 0 }, { 0, 1, 0 }, 0.8, 0.5 },
    { { 0.0, 0.5, 0.27 }, { 0, 1, 0 }, { 1, 0, 0 }, 0.6, 0.7 },
    { { 0.4, -0.5, -0.27 }, { 0, -1, 0 }, { 0, 0, -1 }, 0.5, 0.6 },
    { { -0.4, 0.0, 0.4 }, { 0, 0, 1 }, { -1, 0, 0 }, 0.7, 0.45 },
    { { 0.0, -0.33, -0.4 }, { 0, 0, -1 }, { 0, 1, 0 }, 0.9, 0.55 } };
  for (int b = 0; b < 6; ++b)
  {
    const Branch& branch = branches[b];
    const int face = model.FaceNear(branch.At);
    model.Extrude(face, 0.05 * branch.Out, branch.Scale);
    const int rings = std::max(1, static_cast<int>(std::lround(branch.Share * length)));
    const double turn = 0.02 * (b + 1);
    model.Limb(face, rings, 0.3 * branch.Scale, 1.0, [&](int r) {
      return Eigen::Vector3d(std::cos(turn * r) * branch.Out + std::sin(turn * r) * branch.Bend);
    });
  }
  return model.Subdivided(levels);
}
}

#endif
