// A dense map averaged with the inverse of the map the other way. The refinement is not
// symmetric: the samples' nearest-row searches and the polish (which deforms the source as
// rigidly as it can onto the target) each favour one surface, and where the two bodies do not
// correspond rigidly (a torso that stretches differently in two poses) the map X -> Y and the
// inverse of Y -> X slide apart by similar amounts in different directions. Halfway between
// them is nearer the truth than either (docs/DEVELOPMENT.md, "Both directions").
#ifndef mobius_InverseAveraging_h
#define mobius_InverseAveraging_h

#include "MeshAdjacency.h"
#include "MeshTypes.h"

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace mobius
{
/// The points of the inverse that are farther than this many mean source edge lengths from
/// the source vertex they should reach are not trusted: there the two maps disagree about
/// more than a slide (a fold of one of them), and the map keeps its own point.
constexpr double kInverseReach = 3.0;

/// How far towards the inverse: halfway. On 30 FAUST_r training pairs, 0.35 and 0.65 were
/// both worse than 0.5 (docs/DEVELOPMENT.md, "Both directions").
constexpr double kInverseWeight = 0.5;

/// How many of the polish's iterations run between two meetings of the directions: the
/// polishes of both maps stop, each map moves towards the other's inverse, and both go on
/// from there with their momentum (RefineCorrespondence's PolishBoth), so that the rigid
/// prior of each side works on a map the other side has already moved. On FAUST_r training
/// pairs (5,000 vertices) meetings every 10 of the 60 iterations scored 1.4% better than two
/// whole polishes of 60 with one meeting between them, at about the same cost (every 6:
/// 1.6%, every 15: 0.7%; docs/DEVELOPMENT.md, "Meeting while polishing").
constexpr int kMeetingInterval = 10;

/// Pairs with a surface of more vertices than this are polished without meetings (and
/// averaged once, at the end): on 20,000-vertex bodies the meetings gained little (8 FAUST_r
/// pairs subdivided once: 1.458 -> 1.446) and cost 0.25 s, over the 3 s a pair may take.
constexpr Index kMeetingMaximumVertices = 10000;

/// Moves each source vertex's point on the target (`forward`, in place) by `weight` of the
/// way towards the inverse of `reverse` (per target vertex, its point on the source), and
/// projects it onto the target. The inverse at source vertex x is found in the target's
/// triangles carried onto the source by `reverse`: the one nearest x, searched from the
/// triangle `forward` puts x in, gives x's barycentrics, which are read on the target.
/// `pinned` (source vertex, target vertex): landmarks, left where they are.
void AverageWithInverse(const Points& sourcePoints, const Triangles& sourceTriangles,
  const Points& targetPoints, const Triangles& targetTriangles,
  const VertexLists& targetVertexTriangles, const std::vector<Index>& reverseTriangle,
  const std::vector<Eigen::Vector3d>& reverseBarycentric, double weight,
  const std::vector<std::pair<Index, Index>>& pinned, int numberOfThreads,
  std::vector<Index>& forwardTriangle, std::vector<Eigen::Vector3d>& forwardBarycentric);
}

#endif
