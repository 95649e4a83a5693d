#include "ZoomOut.h"

#include "ParallelFor.h"
#include "SurfaceSampling.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace mobius
{
namespace
{
// Rows `vertices` of the first `columns` columns of an embedding.
RowMatrix GatherRows(const RowMatrix& embedding, const std::vector<Index>& vertices, int columns)
{
  RowMatrix rows(static_cast<Index>(vertices.size()), columns);
  for (size_t i = 0; i < vertices.size(); ++i)
  {
    rows.row(static_cast<Index>(i)) = embedding.row(vertices[i]).head(columns);
  }
  return rows;
}

// Least-squares C with A C ~ B (A, B: samples x k): the functional map of a sample map.
// Farthest-point samples are spread evenly, so equal weights stand in for the mass.
Eigen::MatrixXd FitFunctionalMap(const RowMatrix& a, const RowMatrix& b)
{
  const Eigen::MatrixXd normal = a.transpose() * a;
  return normal.ldlt().solve(a.transpose() * b);
}

// Calls work(begin, end) on chunks of [0, count) in parallel.
template <typename Work>
void ForChunks(Index count, int numberOfThreads, Work&& work)
{
  const Index chunk = 1024;
  const int chunks = static_cast<int>((count + chunk - 1) / chunk);
  ParallelFor(chunks, ResolveThreadCount(numberOfThreads), [&](int c, int) {
    work(c * chunk, std::min(count, (c + 1) * chunk));
  });
}
}

double OrthogonalityResidual(const Eigen::MatrixXd& functionalMap)
{
  const Eigen::Index k = functionalMap.cols();
  return (functionalMap.transpose() * functionalMap - Eigen::MatrixXd::Identity(k, k)).norm() /
    std::sqrt(static_cast<double>(k));
}

bool PrepareSpectralSurface(const Points& points, const Triangles& triangles, int basisSize,
  Index sampleCount, SpectralSurface& surface, std::string& error)
{
  LaplaceBeltramiBasis basis;
  if (!ComputeLaplaceBeltramiBasis(points, triangles, basisSize, basis, error))
  {
    return false;
  }
  if (getenv("MOBIUS_DEBUG")) { std::cerr << "eig " << basis.Eigenvalues.head(10).transpose() << " ... " << basis.Eigenvalues.tail(3).transpose() << std::endl; }
  surface.Faces = triangles;
  surface.Embedding = basis.Functions;
  surface.Eigenvalues = basis.Eigenvalues;
  surface.Mass = basis.Mass;
  surface.Neighbors = VertexNeighbors(points.rows(), triangles);
  surface.Corners = VertexTriangles(points.rows(), triangles);
  surface.Samples = FarthestPointSamples(points, sampleCount);
  surface.SampleLabels = NearestSampleLabels(points, surface.Neighbors, surface.Samples);
  return true;
}

SampleMap ZoomOutOnSamples(const SpectralSurface& source, const SpectralSurface& target,
  const std::vector<Index>& initialTargetVertex, const ZoomOutParameters& parameters)
{
  const int finalSize = std::min<int>(parameters.FinalSize,
    static_cast<int>(std::min(source.Embedding.cols(), target.Embedding.cols())));
  const int step = std::max(1, parameters.SizeStep);
  const RowMatrix sourceRows = GatherRows(source.Embedding, source.Samples, finalSize);
  const RowMatrix targetRows = GatherRows(target.Embedding, target.Samples, finalSize);

  SampleMap result;
  result.TargetVertex = initialTargetVertex;
  for (int k = std::min(parameters.StartSize, finalSize);; k = std::min(k + step, finalSize))
  {
    const RowMatrix a = sourceRows.leftCols(k);
    const Eigen::MatrixXd c =
      FitFunctionalMap(a, GatherRows(target.Embedding, result.TargetVertex, k));
    // Row i of Phi_S ~ row T(i) of Phi_T C^T: transform the target side, as ZoomOut does
    // (for an orthogonal C the same as comparing Phi_S C with Phi_T; for the shrunk C of a
    // noisy start it keeps the queries from collapsing onto the target's small rows).
    const RowMatrix candidates = targetRows.leftCols(k) * c.transpose();
    const std::vector<Index> nearest = NearestRows(a, candidates, parameters.NumberOfThreads);
    for (size_t i = 0; i < nearest.size(); ++i)
    {
      result.TargetVertex[i] = target.Samples[nearest[i]];
    }
    if (getenv("MOBIUS_DEBUG")) { std::cerr << "k " << k << " orth " << OrthogonalityResidual(c) << std::endl; }
    if (k == finalSize)
    {
      break;
    }
  }
  result.FunctionalMap =
    FitFunctionalMap(sourceRows, GatherRows(target.Embedding, result.TargetVertex, finalSize));
  result.OrthogonalityResidual = OrthogonalityResidual(result.FunctionalMap);
  std::vector<char> hit(static_cast<size_t>(target.Embedding.rows()), 0);
  for (Index v : result.TargetVertex)
  {
    hit[v] = 1;
  }
  Index covered = 0;
  for (Index v : target.Samples)
  {
    covered += hit[v];
  }
  result.TargetCoverage =
    target.Samples.empty() ? 0.0 : static_cast<double>(covered) / target.Samples.size();
  return result;
}

DenseMap ExtendToAllVertices(const SpectralSurface& source, const SpectralSurface& target,
  const SampleMap& samples, const ZoomOutParameters& parameters)
{
  const Index n = source.Embedding.rows();
  const Eigen::Index k = samples.FunctionalMap.cols();
  const RowMatrix sourceEmbedding = source.Embedding.leftCols(k);
  const RowMatrix targetEmbedding = target.Embedding.leftCols(k);

  DenseMap result;
  result.NearestVertex.resize(static_cast<size_t>(n));
  Eigen::MatrixXd c = samples.FunctionalMap;
  RowMatrix transformedTarget = targetEmbedding * c.transpose();
  ForChunks(n, parameters.NumberOfThreads, [&](Index begin, Index end) {
    for (Index i = begin; i < end; ++i)
    {
      const Index label = source.SampleLabels[i];
      const Index start = label >= 0 ? samples.TargetVertex[label] : 0;
      result.NearestVertex[i] = DescendToNearestVertex(
        sourceEmbedding.row(i), transformedTarget, target.Neighbors, start);
    }
  });

  for (int iteration = 0; iteration < parameters.FullResolutionIterations; ++iteration)
  {
    // C = Phi_S^T M_S Pi Phi_T: the mass-weighted projection, exact on all vertices.
    const RowMatrix mapped = GatherRows(targetEmbedding, result.NearestVertex, static_cast<int>(k));
    c = sourceEmbedding.transpose() * source.Mass.asDiagonal() * mapped;
    transformedTarget = targetEmbedding * c.transpose();
    ForChunks(n, parameters.NumberOfThreads, [&](Index begin, Index end) {
      for (Index i = begin; i < end; ++i)
      {
        result.NearestVertex[i] = DescendToNearestVertex(sourceEmbedding.row(i),
          transformedTarget, target.Neighbors, result.NearestVertex[i]);
      }
    });
  }
  result.FunctionalMap = sourceEmbedding.transpose() * source.Mass.asDiagonal() *
    GatherRows(targetEmbedding, result.NearestVertex, static_cast<int>(k));
  result.OrthogonalityResidual = OrthogonalityResidual(result.FunctionalMap);

  result.Triangle.resize(static_cast<size_t>(n));
  result.Barycentric.resize(static_cast<size_t>(n));
  ForChunks(n, parameters.NumberOfThreads, [&](Index begin, Index end) {
    for (Index i = begin; i < end; ++i)
    {
      ProjectOntoIncidentTriangles(sourceEmbedding.row(i), transformedTarget, target.Faces, target.Corners,
        result.NearestVertex[i], result.Triangle[i], result.Barycentric[i]);
    }
  });
  return result;
}
}
