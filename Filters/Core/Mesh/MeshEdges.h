// The edge machinery of the topology analysis and the repairs: half-edges sorted so that the
// sides of an edge are adjacent, the valid triangles, boundary loops, disjoint sets. Internal
// to the Mesh stage (its .cxx files share it), not an interface of the core.
#ifndef mobius_MeshEdges_h
#define mobius_MeshEdges_h

#include "MeshTypes.h"
#include "StableSortRun.h"

#include <numeric>
#include <vector>

namespace mobius
{
// Disjoint sets with path halving; used for components and for vertex fans.
class UnionFind
{
public:
  explicit UnionFind(Index size)
    : Parent(static_cast<size_t>(size))
  {
    std::iota(this->Parent.begin(), this->Parent.end(), Index(0));
  }
  Index Find(Index i)
  {
    while (this->Parent[i] != i)
    {
      this->Parent[i] = this->Parent[this->Parent[i]];
      i = this->Parent[i];
    }
    return i;
  }
  void Union(Index a, Index b) { this->Parent[this->Find(a)] = this->Find(b); }

private:
  std::vector<Index> Parent;
};

/// A triangle takes part in edge topology only if its indices are in range and distinct.
std::vector<char> ValidTriangles(const Triangles& triangles, Index numberOfPoints);

// One directed side of an edge: triangle t goes from From to To (its corners k and k+1).
struct HalfEdge
{
  Index Low, High; // the edge's endpoints, sorted: the key that groups the sides of an edge
  Index From;
  Index Triangle;
};

// The items that produce(emit) emits, sorted by (key(item), then less) where key is an
// integer in [0, keys): produce runs twice, once to count each key's items and once to put
// them in place (stable), then each key's run is sorted by less. The runs here are a
// vertex's few edges or triangles, so this is linear where a comparison sort of the whole
// array was the topology analysis' largest cost, and it writes the items once, straight to
// their place.
template <typename Item, typename Produce, typename Key, typename Less>
std::vector<Item> BucketSorted(Index keys, Produce produce, Key key, Less less)
{
  std::vector<Index> start(static_cast<size_t>(keys) + 1, 0);
  produce([&](const Item& item) { ++start[static_cast<size_t>(key(item)) + 1]; });
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<Item> sorted(static_cast<size_t>(start.back()));
  {
    std::vector<Index> fill(start.begin(), start.end() - 1);
    produce([&](const Item& item) {
      sorted[static_cast<size_t>(fill[static_cast<size_t>(key(item))]++)] = item;
    });
  }
  for (Index k = 0; k < keys; ++k)
  {
    StableSortRun(sorted.begin() + start[k], sorted.begin() + start[k + 1], less);
  }
  return sorted;
}

/// All half-edges of the valid triangles (whose points are below numberOfPoints), sorted by
/// (Low, High) so that the sides of an edge are adjacent (in triangle order within an edge).
std::vector<HalfEdge> SortedHalfEdges(
  const Triangles& triangles, const std::vector<char>& valid, Index numberOfPoints);

// Calls visit(begin, end) for each group of half-edges sharing an edge.
template <typename Visitor>
void ForEachEdge(const std::vector<HalfEdge>& halfEdges, Visitor visit)
{
  size_t begin = 0;
  while (begin < halfEdges.size())
  {
    size_t end = begin + 1;
    while (end < halfEdges.size() && halfEdges[end].Low == halfEdges[begin].Low &&
      halfEdges[end].High == halfEdges[begin].High)
    {
      ++end;
    }
    visit(begin, end);
    begin = end;
  }
}

/// Boundary loops as vertex sequences, following each boundary edge in its triangle's
/// direction. `closed` tells whether the chain came back to its start (it does not when the
/// orientation is inconsistent or a vertex has more outgoing than incoming boundary edges).
void TraceBoundaryLoops(const std::vector<HalfEdge>& halfEdges,
  std::vector<std::vector<Index>>& loops, std::vector<char>& closed);
}

#endif
