#include "InverseAveraging.h"

#include "ParallelFor.h"
#include "SurfaceWalk.h"

namespace mobius
{
namespace
{
// Per target vertex, its point on the source.
Points ReversePoints(const Points& sourcePoints, const Triangles& sourceTriangles,
  const std::vector<Index>& triangle, const std::vector<Eigen::Vector3d>& barycentric)
{
  Points points(static_cast<Index>(triangle.size()), 3);
  for (size_t v = 0; v < triangle.size(); ++v)
  {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
    {
      point += barycentric[v][k] * sourcePoints.row(sourceTriangles(triangle[v], k)).transpose();
    }
    points.row(static_cast<Index>(v)) = point.transpose();
  }
  return points;
}
}

void AverageWithInverse(const Points& sourcePoints, const Triangles& sourceTriangles,
  const Points& targetPoints, const Triangles& targetTriangles,
  const VertexLists& targetVertexTriangles, const std::vector<Index>& reverseTriangle,
  const std::vector<Eigen::Vector3d>& reverseBarycentric, double weight,
  const std::vector<std::pair<Index, Index>>& pinned, int numberOfThreads,
  std::vector<Index>& forwardTriangle, std::vector<Eigen::Vector3d>& forwardBarycentric)
{
  const Points carried =
    ReversePoints(sourcePoints, sourceTriangles, reverseTriangle, reverseBarycentric);
  const SurfaceWalker onSource{ carried, targetTriangles, targetVertexTriangles };
  const SurfaceWalker onTarget{ targetPoints, targetTriangles, targetVertexTriangles };
  const double reach = kInverseReach * MeanEdgeLength(sourcePoints, sourceTriangles);
  std::vector<char> held(sourcePoints.rows(), 0);
  for (const auto& pin : pinned)
  {
    held[static_cast<size_t>(pin.first)] = 1;
  }
  ParallelForChunks<Index>(sourcePoints.rows(), 512, numberOfThreads, [&](Index begin, Index end) {
    for (Index i = begin; i < end; ++i)
    {
      if (held[static_cast<size_t>(i)])
      {
        continue;
      }
      const Index start = forwardTriangle[static_cast<size_t>(i)];
      Index inverseTriangle = start;
      Eigen::Vector3d inverseWeights;
      if (!(onSource.Walk(sourcePoints.row(i).transpose(), inverseTriangle, inverseWeights) <=
            reach * reach))
      {
        continue;
      }
      const Eigen::Vector3d average =
        (1 - weight) * onTarget.Point(start, forwardBarycentric[static_cast<size_t>(i)]) +
        weight * onTarget.Point(inverseTriangle, inverseWeights);
      Index triangle = start;
      Eigen::Vector3d weights;
      onTarget.Walk(average, triangle, weights);
      forwardTriangle[static_cast<size_t>(i)] = triangle;
      forwardBarycentric[static_cast<size_t>(i)] = weights;
    }
  });
}
}
