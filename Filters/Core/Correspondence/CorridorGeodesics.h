// Geodesic distances between vertices closer to the exact polyhedral ones than edge paths,
// for the cost of an edge-path search plus a small one: the edge path between the two
// vertices (EdgePathGeodesics) is shortened through Steiner points, `SteinerPoints` evenly
// spaced points on every edge of the triangles around the path's vertices (its corridor),
// joined by straight segments across each triangle (Lanthier, Maheshwari & Sack 1997, on
// the corridor only). Every such path lies on the surface, so the result is never shorter
// than the exact geodesic, and never longer than the edge path (which is one of those
// paths). The exact geodesic may leave the corridor (an edge path can run an edge or more
// beside it): the corridor around the shortened path is searched again, up to
// MaximumRounds times, while the length drops.
#ifndef mobius_CorridorGeodesics_h
#define mobius_CorridorGeodesics_h

#include "CorrespondenceScore.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace mobius
{
class CorridorGeodesics
{
public:
  /// Per-thread buffers, reused from query to query.
  class Workspace
  {
  private:
    friend class CorridorGeodesics;
    EdgePathGeodesics::Workspace Edges;
    std::vector<Index> Path;
    std::vector<std::int32_t> CorridorTriangles;
    std::vector<char> InCorridor;             // per mesh triangle
    std::vector<std::int32_t> LocalVertex;    // per mesh vertex: its node, or -1
    std::unordered_map<std::uint64_t, std::int32_t> LocalEdge; // first Steiner node of an edge
    std::vector<Eigen::Vector3d> Position;    // per node
    std::vector<std::int32_t> TriangleNodes;  // per corridor triangle, NodesPerTriangle nodes
    std::vector<std::int32_t> FirstNodeTriangle, NodeTriangle; // per node, its triangles
    std::vector<double> Distance;
    std::vector<std::int32_t> ParentNode, ParentTriangle; // ParentTriangle: corridor index
    std::vector<std::pair<double, std::int32_t>> Heap;
  };

  /// `geodesics` must be built, and outlive this object. Steiner points per edge: 0 gives
  /// the edge-path distances back.
  void Build(const EdgePathGeodesics& geodesics, int steinerPoints);

  /// The shortened distance between two vertices; +infinity if no path joins them, NaN for
  /// an index out of range. The cost grows with the path: its corridor does.
  double Distance(Index fromVertex, Index toVertex, Workspace& workspace) const;

private:
  /// The shortest path from node `from` to node `to` of the corridor's graph.
  double Shortest(std::int32_t from, std::int32_t to, Workspace& workspace) const;
  /// The triangles around workspace.Path's vertices, their nodes and node-triangle lists.
  void BuildCorridor(Workspace& workspace) const;
  void ClearCorridor(Workspace& workspace) const;
  /// Corridors searched at most per query (the first around the edge path), and the gain a
  /// round must bring for another. On FAUST_r pairs a second round changed the mean error
  /// by under 0.01%; the rounds matter on regular grids, whose many edge paths of one length
  /// can run far from the straight line (a bent sheet: 3.9% long after one round, 1.2% after
  /// eight, against 14% for the edge paths).
  static constexpr int MaximumRounds = 8;
  static constexpr double RoundGain = 1e-3;

  const EdgePathGeodesics* Geodesics = nullptr;
  int SteinerPoints = 0;
  std::vector<std::int32_t> FirstVertexTriangle, VertexTriangle; // per vertex, its triangles
};
}

#endif
