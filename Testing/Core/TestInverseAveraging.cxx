// A map averaged with the inverse of the map the other way: on the unit sphere, a map
// turned one way and a reverse map turned the same way (whose inverse is turned back) meet
// at the identity; landmarks stay where the map put them; where the other direction's map
// is nowhere near (collapsed onto one point), the map keeps its own points.
#include "CoreTest.h"
#include "Icosphere.h"
#include "InverseAveraging.h"
#include "MeshAdjacency.h"
#include "SurfaceWalk.h"

#include <Eigen/Geometry>

#include <iostream>
#include <vector>

using namespace mobius;

namespace
{
struct Map
{
  std::vector<Index> Triangle;
  std::vector<Eigen::Vector3d> Barycentric;
};

struct Sphere
{
  Points Positions;
  Triangles Faces;
  VertexLists Corners;
};

Sphere MakeSphere()
{
  Sphere sphere;
  MakeIcosphere(4, sphere.Positions, sphere.Faces);
  sphere.Corners = VertexTriangles(sphere.Positions.rows(), sphere.Faces);
  return sphere;
}

// Each vertex of the sphere mesh sent to the mesh point closest to its position turned by
// `turn`.
Map TurnedMap(const Sphere& sphere, const Eigen::Matrix3d& turn)
{
  const SurfaceWalker walker{ sphere.Positions, sphere.Faces, sphere.Corners };
  Map map;
  for (Index i = 0; i < sphere.Positions.rows(); ++i)
  {
    Index t = sphere.Corners.Items[sphere.Corners.Begin(i)];
    Eigen::Vector3d weights;
    walker.Walk(turn * sphere.Positions.row(i).transpose(), t, weights);
    map.Triangle.push_back(t);
    map.Barycentric.push_back(weights);
  }
  return map;
}

// Mean distance of each vertex's mapped point from the vertex itself.
double MeanOffset(const Sphere& sphere, const Map& map)
{
  const SurfaceWalker walker{ sphere.Positions, sphere.Faces, sphere.Corners };
  double sum = 0;
  for (Index i = 0; i < sphere.Positions.rows(); ++i)
  {
    sum += (walker.Point(map.Triangle[i], map.Barycentric[i]) -
      sphere.Positions.row(i).transpose()).norm();
  }
  return sum / sphere.Positions.rows();
}

void TestTurnsCancel()
{
  const Sphere sphere = MakeSphere();
  // About a third of an edge (the mesh's edges are about 0.08 long).
  const Eigen::Matrix3d turn =
    Eigen::AngleAxisd(0.03, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Map forward = TurnedMap(sphere, turn);
  const Map reverse = TurnedMap(sphere, turn);
  Map averaged = forward;
  const std::vector<std::pair<Index, Index>> pinned = { { 7, 7 } };
  AverageWithInverse(sphere.Positions, sphere.Faces, sphere.Positions, sphere.Faces,
    sphere.Corners, reverse.Triangle, reverse.Barycentric, kInverseWeight, pinned, 2,
    averaged.Triangle, averaged.Barycentric);
  const double before = MeanOffset(sphere, forward), after = MeanOffset(sphere, averaged);
  std::cout << "turned both ways: offset " << before << " -> " << after << "\n";
  MOBIUS_CHECK(before > 0.02);
  MOBIUS_CHECK(after < 0.05 * before);
  MOBIUS_CHECK(averaged.Triangle[7] == forward.Triangle[7]);
  MOBIUS_CHECK(averaged.Barycentric[7] == forward.Barycentric[7]);

  // The same on one thread.
  Map one = forward;
  AverageWithInverse(sphere.Positions, sphere.Faces, sphere.Positions, sphere.Faces,
    sphere.Corners, reverse.Triangle, reverse.Barycentric, kInverseWeight, pinned, 1,
    one.Triangle, one.Barycentric);
  MOBIUS_CHECK(one.Triangle == averaged.Triangle && one.Barycentric == averaged.Barycentric);
}

void TestFarInverseIgnored()
{
  const Sphere sphere = MakeSphere();
  const Eigen::Matrix3d turn =
    Eigen::AngleAxisd(0.03, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Map forward = TurnedMap(sphere, turn);
  // Every target vertex onto source vertex 0: no inverse anywhere but near vertex 0.
  Map collapsed;
  const Index t = sphere.Corners.Items[sphere.Corners.Begin(0)];
  for (Index v = 0; v < sphere.Positions.rows(); ++v)
  {
    collapsed.Triangle.push_back(t);
    Eigen::Vector3d weights = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
    {
      weights[k] = sphere.Faces(t, k) == 0 ? 1.0 : 0.0;
    }
    collapsed.Barycentric.push_back(weights);
  }
  Map averaged = forward;
  AverageWithInverse(sphere.Positions, sphere.Faces, sphere.Positions, sphere.Faces,
    sphere.Corners, collapsed.Triangle, collapsed.Barycentric, kInverseWeight, {}, 2,
    averaged.Triangle, averaged.Barycentric);
  const double reach = kInverseReach * MeanEdgeLength(sphere.Positions, sphere.Faces);
  Index unchanged = 0, far = 0;
  for (Index i = 0; i < sphere.Positions.rows(); ++i)
  {
    if ((sphere.Positions.row(i) - sphere.Positions.row(0)).norm() > reach)
    {
      ++far;
      unchanged += averaged.Triangle[i] == forward.Triangle[i] &&
        averaged.Barycentric[i] == forward.Barycentric[i];
    }
  }
  std::cout << "collapsed inverse: " << unchanged << " of " << far << " far vertices unchanged\n";
  MOBIUS_CHECK(far > sphere.Positions.rows() / 2);
  MOBIUS_CHECK(unchanged == far);
}
}

int main()
{
  TestTurnsCancel();
  TestFarInverseIgnored();
  return MOBIUS_TEST_RESULT();
}
