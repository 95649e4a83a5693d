#include "MeshEdges.h"

#include <algorithm>
#include <unordered_map>

namespace mobius
{
std::vector<char> ValidTriangles(const Triangles& triangles, Index numberOfPoints)
{
  std::vector<char> valid(static_cast<size_t>(triangles.rows()), 0);
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    const Index a = triangles(t, 0), b = triangles(t, 1), c = triangles(t, 2);
    const bool inRange = a >= 0 && b >= 0 && c >= 0 && a < numberOfPoints &&
      b < numberOfPoints && c < numberOfPoints;
    valid[t] = inRange && a != b && b != c && c != a;
  }
  return valid;
}

std::vector<HalfEdge> SortedHalfEdges(
  const Triangles& triangles, const std::vector<char>& valid, Index numberOfPoints)
{
  auto produce = [&](auto emit) {
    for (Index t = 0; t < triangles.rows(); ++t)
    {
      if (valid[t])
      {
        for (int k = 0; k < 3; ++k)
        {
          const Index from = triangles(t, k), to = triangles(t, (k + 1) % 3);
          emit(HalfEdge{ std::min(from, to), std::max(from, to), from, t });
        }
      }
    }
  };
  if (numberOfPoints > 4 * 3 * triangles.rows() + 1024)
  {
    // Indices far beyond the mesh's size (OrientConsistently takes the largest index as
    // the point count): a bucket per index would cost more than a comparison sort. Same
    // order: stable, by (Low, High).
    std::vector<HalfEdge> halfEdges;
    produce([&](const HalfEdge& h) { halfEdges.push_back(h); });
    std::stable_sort(halfEdges.begin(), halfEdges.end(), [](const HalfEdge& x, const HalfEdge& y) {
      return x.Low != y.Low ? x.Low < y.Low : x.High < y.High;
    });
    return halfEdges;
  }
  return BucketSorted<HalfEdge>(
    numberOfPoints, produce, [](const HalfEdge& h) { return h.Low; },
    [](const HalfEdge& x, const HalfEdge& y) { return x.High < y.High; });
}

void TraceBoundaryLoops(const std::vector<HalfEdge>& halfEdges,
  std::vector<std::vector<Index>>& loops, std::vector<char>& closed)
{
  // Directed boundary edges from -> to, looked up by their start.
  std::unordered_map<Index, std::vector<Index>> outgoing;
  Index count = 0;
  ForEachEdge(halfEdges, [&](size_t begin, size_t end) {
    if (end - begin == 1)
    {
      const HalfEdge& h = halfEdges[begin];
      outgoing[h.From].push_back(h.From == h.Low ? h.High : h.Low);
      ++count;
    }
  });
  // Start chains at vertices with more outgoing than incoming edges first, so that open
  // chains are traced from their beginning; then the rest, which are cycles.
  std::unordered_map<Index, Index> balance;
  for (const auto& entry : outgoing)
  {
    balance[entry.first] += static_cast<Index>(entry.second.size());
    for (Index to : entry.second)
    {
      balance[to] -= 1;
    }
  }
  std::vector<Index> starts;
  for (const auto& entry : outgoing)
  {
    starts.push_back(entry.first);
  }
  std::sort(starts.begin(), starts.end(), [&](Index a, Index b) {
    const bool openA = balance[a] > 0, openB = balance[b] > 0;
    return openA != openB ? openA : a < b;
  });
  for (Index start : starts)
  {
    while (!outgoing[start].empty())
    {
      std::vector<Index> loop{ start };
      Index current = start;
      while (true)
      {
        auto& next = outgoing[current];
        if (next.empty())
        {
          break;
        }
        current = next.back();
        next.pop_back();
        if (current == start)
        {
          break;
        }
        loop.push_back(current);
      }
      loops.push_back(std::move(loop));
      closed.push_back(current == start);
    }
  }
}
}
