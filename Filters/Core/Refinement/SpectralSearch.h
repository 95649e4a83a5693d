// Nearest neighbours in a spectral embedding (each vertex a row of k eigenfunction values):
// the pointwise map is read off a functional map by these searches.
#ifndef mobius_SpectralSearch_h
#define mobius_SpectralSearch_h

#include "MeshAdjacency.h"
#include "MeshTypes.h"

#include <vector>

namespace mobius
{
using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// For every row of `queries`, the index of the nearest row of `points` (Euclidean, both
/// with the same number of columns). Exhaustive, in blocks of matrix products (faster than a
/// k-d tree at the 20-100 dimensions used here), with numberOfThreads threads.
std::vector<Index> NearestRows(const RowMatrix& queries, const RowMatrix& points,
  int numberOfThreads);

/// The same, exact, when the points fall into clusters of nearby rows (`cluster`: a cluster
/// number per point, e.g. its nearest sample on a mesh; -1: a cluster of its own): each
/// query compares its distances to the clusters' centres and scans only the clusters that can
/// hold a point nearer than the best found so far (centre distance minus cluster radius),
/// and of a large cluster only the parts (at most 12 nearby rows) that can. On a spectral
/// embedding, where the rows of neighbouring vertices are near one another, a query scans
/// about 4 of 1000 clusters: a fraction of the exhaustive search's cost.
std::vector<Index> NearestRowsByClusters(const RowMatrix& queries, const RowMatrix& points,
  const std::vector<Index>& cluster, int numberOfThreads);

/// Greedy descent on the mesh: from `start`, moves to the neighbour whose embedding row is
/// nearest to `query` while that improves, and returns the vertex where it stops (a local
/// minimum of the distance over the vertex graph).
Index DescendToNearestVertex(const Eigen::Ref<const Eigen::RowVectorXd>& query,
  const RowMatrix& embedding, const VertexLists& neighbors, Index start);

/// The point nearest to `query` on the triangles around `vertex`, the embedding extended
/// linearly over each triangle: the triangle and barycentric coordinates (non-negative, sum 1)
/// of the point. This places a mapped point inside a target triangle rather than on a vertex.
void ProjectOntoIncidentTriangles(const Eigen::Ref<const Eigen::RowVectorXd>& query,
  const RowMatrix& embedding, const Triangles& triangles, const VertexLists& vertexTriangles,
  Index vertex, Index& triangle, Eigen::Vector3d& barycentric);
}

#endif
