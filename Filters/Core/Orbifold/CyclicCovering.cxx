#include "CyclicCovering.h"

#include "MeshAdjacency.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

namespace mobius
{
Index CyclicCovering::Vertex(int copy, Index v) const
{
  return static_cast<Index>(copy) * (this->NumberOfInputVertices - 2) + this->NonConeRank[v];
}

Points CyclicCovering::CoveringPoints(const Points& points) const
{
  Points result(static_cast<Index>(this->SourceVertex.size()), 3);
  for (Index w = 0; w < result.rows(); ++w)
  {
    result.row(w) = points.row(this->SourceVertex[w]);
  }
  return result;
}

namespace
{
bool Fail(CyclicCovering& covering, const std::string& message)
{
  covering.Error = message;
  return false;
}

// Whether triangle t has the directed edge a -> b (a followed by b in its cyclic order).
bool HasDirectedEdge(const Triangles& triangles, Index t, Index a, Index b)
{
  for (int k = 0; k < 3; ++k)
  {
    if (triangles(t, k) == a && triangles(t, (k + 1) % 3) == b)
    {
      return true;
    }
  }
  return false;
}

// Splits the fan of triangles around cut vertex p (previous path vertex `before`, next
// `after`) into the two sides of the cut: the triangles reachable from the one left of the
// edge before -> p without crossing the cut edges. Marks the corner at p of each left
// triangle in leftCorners. False if the fan does not split cleanly.
bool MarkLeftSide(const Triangles& triangles, const VertexLists& vertexTriangles, Index p,
  Index before, Index after, std::vector<unsigned char>& leftCorners)
{
  // Fan triangles by the edges (p, w) they have at p.
  std::map<Index, std::vector<Index>> byEdge;
  Index start = -1, leftOfNext = -1, rightOfNext = -1, rightOfPrevious = -1;
  for (Index k = vertexTriangles.Begin(p); k < vertexTriangles.End(p); ++k)
  {
    const Index t = vertexTriangles.Items[k];
    for (int c = 0; c < 3; ++c)
    {
      const Index w = triangles(t, c);
      if (w != p)
      {
        byEdge[w].push_back(t);
      }
    }
    if (HasDirectedEdge(triangles, t, before, p))
    {
      start = t;
    }
    if (HasDirectedEdge(triangles, t, p, before))
    {
      rightOfPrevious = t;
    }
    if (HasDirectedEdge(triangles, t, p, after))
    {
      leftOfNext = t;
    }
    if (HasDirectedEdge(triangles, t, after, p))
    {
      rightOfNext = t;
    }
  }
  if (start < 0 || leftOfNext < 0 || rightOfNext < 0 || rightOfPrevious < 0)
  {
    return false;
  }
  std::set<Index> left{ start };
  std::vector<Index> stack{ start };
  while (!stack.empty())
  {
    const Index t = stack.back();
    stack.pop_back();
    for (int c = 0; c < 3; ++c)
    {
      const Index w = triangles(t, c);
      if (w == p || w == before || w == after)
      {
        continue; // the cut is not crossed
      }
      for (const Index u : byEdge[w])
      {
        if (left.insert(u).second)
        {
          stack.push_back(u);
        }
      }
    }
  }
  if (!left.count(leftOfNext) || left.count(rightOfNext) || left.count(rightOfPrevious))
  {
    return false;
  }
  for (const Index t : left)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (triangles(t, c) == p)
      {
        leftCorners[t] |= static_cast<unsigned char>(1u << c);
      }
    }
  }
  return true;
}
}

bool BuildCyclicCovering(Index numberOfPoints, const Triangles& triangles,
  const std::vector<Index>& cutPath, int copies, CyclicCovering& covering)
{
  covering = CyclicCovering();
  covering.Copies = copies;
  covering.CutPath = cutPath;
  covering.NumberOfInputVertices = numberOfPoints;
  if (copies < 2)
  {
    return Fail(covering, "the covering needs at least 2 copies");
  }
  if (cutPath.size() < 3)
  {
    return Fail(covering,
      "the cut path needs at least two edges (the cones must not be neighbours: the covering "
      "of an edge between the two cones would be shared by every copy)");
  }
  std::vector<int> pathPosition(static_cast<size_t>(numberOfPoints), -1);
  for (size_t j = 0; j < cutPath.size(); ++j)
  {
    const Index v = cutPath[j];
    if (v < 0 || v >= numberOfPoints)
    {
      return Fail(covering, "the cut path names a vertex that does not exist");
    }
    if (pathPosition[v] >= 0)
    {
      return Fail(covering, "the cut path visits a vertex twice");
    }
    pathPosition[v] = static_cast<int>(j);
  }
  const Index cone0 = cutPath.front(), cone1 = cutPath.back();
  const VertexLists neighbors = VertexNeighbors(numberOfPoints, triangles);
  auto adjacent = [&](Index a, Index b) {
    return std::find(neighbors.Items.begin() + neighbors.Begin(a),
             neighbors.Items.begin() + neighbors.End(a), b) !=
      neighbors.Items.begin() + neighbors.End(a);
  };
  for (size_t j = 0; j + 1 < cutPath.size(); ++j)
  {
    if (!adjacent(cutPath[j], cutPath[j + 1]))
    {
      return Fail(covering, "consecutive vertices of the cut path do not share an edge");
    }
  }
  if (adjacent(cone0, cone1))
  {
    return Fail(covering,
      "the two cones share an edge: its covering would be shared by every copy; choose "
      "cones further apart");
  }

  // Sides of the cut at each interior cut vertex.
  covering.LeftCorners.assign(static_cast<size_t>(triangles.rows()), 0);
  const VertexLists vertexTriangles = VertexTriangles(numberOfPoints, triangles);
  for (size_t j = 1; j + 1 < cutPath.size(); ++j)
  {
    if (!MarkLeftSide(triangles, vertexTriangles, cutPath[j], cutPath[j - 1], cutPath[j + 1],
          covering.LeftCorners))
    {
      std::ostringstream s;
      s << "cannot split the triangles around cut vertex " << cutPath[j]
        << " into the two sides of the cut (the mesh is not a consistently oriented manifold "
           "there)";
      return Fail(covering, s.str());
    }
  }

  // Vertices: n copies of every non-cone vertex, then the two cones.
  covering.NonConeRank.assign(static_cast<size_t>(numberOfPoints), -1);
  Index rank = 0;
  for (Index v = 0; v < numberOfPoints; ++v)
  {
    if (v != cone0 && v != cone1)
    {
      covering.NonConeRank[v] = rank++;
    }
  }
  const Index perCopy = numberOfPoints - 2;
  const Index total = copies * perCopy + 2;
  covering.SourceVertex.resize(static_cast<size_t>(total));
  covering.VertexCopy.resize(static_cast<size_t>(total));
  covering.NextCopyVertex.resize(static_cast<size_t>(total));
  for (Index v = 0; v < numberOfPoints; ++v)
  {
    if (v == cone0 || v == cone1)
    {
      continue;
    }
    for (int i = 0; i < copies; ++i)
    {
      const Index w = covering.Vertex(i, v);
      covering.SourceVertex[w] = v;
      covering.VertexCopy[w] = i;
      covering.NextCopyVertex[w] = covering.Vertex((i + 1) % copies, v);
    }
  }
  covering.ConeVertices[0] = total - 2;
  covering.ConeVertices[1] = total - 1;
  for (int c = 0; c < 2; ++c)
  {
    const Index w = covering.ConeVertices[c];
    covering.SourceVertex[w] = c == 0 ? cone0 : cone1;
    covering.VertexCopy[w] = -1;
    covering.NextCopyVertex[w] = w;
  }

  // Triangles: copy i uses copy i + 1's vertices at the corners left of the cut, which
  // glues its left side to the right side of copy i + 1.
  const Index F = triangles.rows();
  covering.CoveringTriangles.resize(copies * F, 3);
  for (int i = 0; i < copies; ++i)
  {
    for (Index t = 0; t < F; ++t)
    {
      for (int c = 0; c < 3; ++c)
      {
        const Index v = triangles(t, c);
        Index w;
        if (v == cone0)
        {
          w = covering.ConeVertices[0];
        }
        else if (v == cone1)
        {
          w = covering.ConeVertices[1];
        }
        else
        {
          const bool left = (covering.LeftCorners[t] >> c) & 1u;
          w = covering.Vertex(left ? (i + 1) % copies : i, v);
        }
        covering.CoveringTriangles(i * F + t, c) = w;
      }
    }
  }
  return true;
}
}
