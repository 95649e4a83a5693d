// Evenly spread vertex samples of a surface and the sample each vertex is closest to: the
// refinement stage iterates on the samples and extends to every vertex at the end.
#ifndef mobius_SurfaceSampling_h
#define mobius_SurfaceSampling_h

#include "MeshAdjacency.h"
#include "MeshTypes.h"

#include <vector>

namespace mobius
{
/// Farthest-point sampling in Euclidean distance: starts at the vertex farthest from the
/// centroid (deterministic), then repeatedly adds the vertex farthest from every sample so
/// far. Returns min(count, number of points) distinct vertex indices. O(points x count).
std::vector<Index> FarthestPointSamples(const Points& points, Index count);

/// For every vertex, the position in `samples` of the sample nearest to it along the edges
/// of the mesh (a graph Voronoi partition, by multi-source Dijkstra). Vertices no sample
/// reaches (another component) get -1.
std::vector<Index> NearestSampleLabels(
  const Points& points, const VertexLists& neighbors, const std::vector<Index>& samples);
}

#endif
