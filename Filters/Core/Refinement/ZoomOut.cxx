#include "ZoomOut.h"

#include "CotangentLaplacian.h"
#include "Curvature.h"
#include "ParallelFor.h"
#include "SurfaceSampling.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <utility>

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

// Rows with more columns appended, or the rows as they are when there are none.
RowMatrix Appended(const RowMatrix& rows, const RowMatrix& extra)
{
  if (extra.cols() == 0)
  {
    return rows;
  }
  RowMatrix out(rows.rows(), rows.cols() + extra.cols());
  out << rows, extra;
  return out;
}

// Rows with the anchor's coordinates appended (weighted), or the rows as they are.
RowMatrix Anchored(const RowMatrix& rows, const RowMatrix& anchor, double weight)
{
  return weight == 0 ? rows : Appended(rows, weight * anchor);
}

using CurvatureWeightArray = std::array<double, kPolishCurvatures.size()>;

// The curvatures with a weight that both surfaces have: only those are compared, so that
// queries and points get the same columns.
std::vector<size_t> SharedCurvatures(const SpectralSurface& source,
  const SpectralSurface& target, const CurvatureWeightArray& weights)
{
  auto has = [](const SpectralSurface& s, size_t k) {
    return k < s.PolishCurvatures.size() && s.PolishCurvatures[k].size() == s.Positions.rows() &&
      s.Positions.rows() > 0;
  };
  std::vector<size_t> shared;
  for (size_t k = 0; k < weights.size(); ++k)
  {
    if (weights[k] != 0 && has(source, k) && has(target, k))
    {
      shared.push_back(k);
    }
  }
  return shared;
}

// The `shared` curvatures of `surface` at `vertices` as columns, weighted: each over the
// target's root mean square of it, so that source and target share one scale and a weight
// of 1 spreads like one mass-normalized eigenfunction.
RowMatrix CurvatureColumns(const SpectralSurface& surface, const std::vector<Index>& vertices,
  const SpectralSurface& target, const CurvatureWeightArray& weights,
  const std::vector<size_t>& shared)
{
  RowMatrix columns(static_cast<Index>(vertices.size()), static_cast<Index>(shared.size()));
  for (size_t c = 0; c < shared.size(); ++c)
  {
    const Vector& reference = target.PolishCurvatures[shared[c]];
    const double rms = std::sqrt(reference.squaredNorm() / static_cast<double>(reference.size()));
    const double scale = rms > 0 ? weights[shared[c]] / rms : 0.0;
    for (size_t i = 0; i < vertices.size(); ++i)
    {
      columns(static_cast<Index>(i), static_cast<Index>(c)) =
        scale * surface.PolishCurvatures[shared[c]][vertices[i]];
    }
  }
  return columns;
}

std::vector<Index> AllVertices(Index count)
{
  std::vector<Index> vertices(static_cast<size_t>(count));
  for (Index i = 0; i < count; ++i)
  {
    vertices[static_cast<size_t>(i)] = i;
  }
  return vertices;
}

// Least-squares C with A C ~ B (A, B: samples x k): the functional map of a sample map.
// Farthest-point samples are spread evenly, so equal weights stand in for the mass; a
// pinned sample (a landmark) counts kPinnedSampleWeight times.
Eigen::MatrixXd FitFunctionalMap(const RowMatrix& a, const RowMatrix& b,
  const std::vector<std::pair<Index, Index>>& pins = {})
{
  Eigen::MatrixXd normal = a.transpose() * a;
  Eigen::MatrixXd right = a.transpose() * b;
  for (const auto& pin : pins)
  {
    const double extra = kPinnedSampleWeight - 1.0;
    normal += extra * a.row(pin.first).transpose() * a.row(pin.first);
    right += extra * a.row(pin.first).transpose() * b.row(pin.first);
  }
  return normal.ldlt().solve(right);
}

// The pinned samples sent to their target vertices.
void ApplyPins(const std::vector<std::pair<Index, Index>>& pins, std::vector<Index>& targetVertex)
{
  for (const auto& pin : pins)
  {
    targetVertex[static_cast<size_t>(pin.first)] = pin.second;
  }
}
}

// Share of the source's sample triangles that face the same way after mapping: the normal of
// the triangle of images, against the target's normals there, has the sign the triangle's
// own normal has against the source's normals.
double OrientationAgreement(const SpectralSurface& source, const SpectralSurface& target,
  const std::vector<Index>& targetVertex)
{
  auto facing = [](const SpectralSurface& surface, Index a, Index b, Index c) {
    const Eigen::RowVector3d pa = surface.Positions.row(a), pb = surface.Positions.row(b),
                             pc = surface.Positions.row(c);
    const Eigen::RowVector3d normal =
      surface.Normals.row(a) + surface.Normals.row(b) + surface.Normals.row(c);
    return (pb - pa).cross(pc - pa).dot(normal);
  };
  Index agree = 0, counted = 0;
  for (const auto& triangle : source.SampleTriangles)
  {
    const double before = facing(source, source.Samples[triangle[0]],
      source.Samples[triangle[1]], source.Samples[triangle[2]]);
    const Index a = targetVertex[triangle[0]], b = targetVertex[triangle[1]],
                c = targetVertex[triangle[2]];
    if (before == 0 || a == b || b == c || c == a)
    {
      continue; // collapsed images say nothing about orientation
    }
    ++counted;
    agree += (facing(target, a, b, c) > 0) == (before > 0) ? 1 : 0;
  }
  return counted > 0 ? static_cast<double>(agree) / counted : 0.0;
}

double CurvatureDifference(const SpectralSurface& source, const SpectralSurface& target,
  const std::vector<Index>& targetVertex)
{
  if (source.Curvature.size() == 0 || target.Curvature.size() == 0 || targetVertex.empty())
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  double sum = 0;
  for (size_t s = 0; s < targetVertex.size(); ++s)
  {
    sum += std::abs(source.Curvature[source.Samples[s]] - target.Curvature[targetVertex[s]]);
  }
  return sum / static_cast<double>(targetVertex.size());
}

void AddPinnedSamples(SpectralSurface& surface, const std::vector<Index>& vertices)
{
  for (Index vertex : vertices)
  {
    const auto found = std::find(surface.Samples.begin(), surface.Samples.end(), vertex);
    const auto position = static_cast<Index>(found - surface.Samples.begin());
    if (found == surface.Samples.end())
    {
      surface.Samples.push_back(vertex);
    }
    surface.SampleLabels[static_cast<size_t>(vertex)] = position;
  }
}

int NextBasisSize(int size, double growth)
{
  return size + std::max(1, static_cast<int>(size * growth));
}

double OrthogonalityResidual(const Eigen::MatrixXd& functionalMap)
{
  const Eigen::Index k = functionalMap.cols();
  return (functionalMap.transpose() * functionalMap - Eigen::MatrixXd::Identity(k, k)).norm() /
    std::sqrt(static_cast<double>(k));
}

bool PrepareSpectralSurface(const Points& points, const Triangles& triangles, int basisSize,
  Index sampleCount, SpectralSurface& surface, std::string& error, double consistentMassShare)
{
  LaplaceBeltramiBasis basis;
  if (!ComputeLaplaceBeltramiBasis(points, triangles, basisSize, basis, error, consistentMassShare))
  {
    return false;
  }
  PrepareSpectralSurface(points, triangles, std::move(basis), sampleCount, surface);
  return true;
}

void PrepareSpectralSurface(const Points& points, const Triangles& triangles,
  LaplaceBeltramiBasis basis, Index sampleCount, SpectralSurface& surface)
{
  surface.Positions = points;
  surface.Normals = AreaWeightedVertexNormals(points, triangles);
  std::vector<CurvatureScale> scales{ kCandidateCurvature };
  scales.insert(scales.end(), kPolishCurvatures.begin(), kPolishCurvatures.end());
  std::vector<Vector> curvatures = SmoothedCurvatures(points, triangles, scales);
  surface.Curvature = std::move(curvatures[0]);
  surface.PolishCurvatures.assign(
    std::make_move_iterator(curvatures.begin() + 1), std::make_move_iterator(curvatures.end()));
  surface.Faces = triangles;
  surface.Embedding = basis.Functions;
  surface.Eigenvalues = std::move(basis.Eigenvalues);
  surface.Mass = std::move(basis.Mass);
  surface.Neighbors = VertexNeighbors(points.rows(), triangles);
  surface.Corners = VertexTriangles(points.rows(), triangles);
  surface.Samples = FarthestPointSamples(points, sampleCount);
  surface.SampleLabels = NearestSampleLabels(points, surface.Neighbors, surface.Samples);
  // The orientation check runs on a coarser triangulation, of the first eighth of the
  // samples (farthest-point order makes them an even sampling too): its triangles are
  // several target-sample spacings wide, so the quantization of the images to target
  // samples does not scramble their orientation.
  const std::vector<Index> coarse(surface.Samples.begin(),
    surface.Samples.begin() + std::max<size_t>(3, surface.Samples.size() / 8));
  const std::vector<Index> coarseLabels = NearestSampleLabels(points, surface.Neighbors, coarse);
  surface.SampleTriangles.clear();
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    const std::array<Index, 3> labels = { coarseLabels[triangles(t, 0)],
      coarseLabels[triangles(t, 1)], coarseLabels[triangles(t, 2)] };
    if (labels[0] >= 0 && labels[0] != labels[1] && labels[1] != labels[2] &&
      labels[2] != labels[0])
    {
      surface.SampleTriangles.push_back(labels);
    }
  }
}

namespace
{
// Share of a sample map's triangles on the side parameters.Orientation expects.
double ExpectedSideShare(const SpectralSurface& source, const SpectralSurface& target,
  const std::vector<Index>& targetVertex, int orientation)
{
  const double agreement = OrientationAgreement(source, target, targetVertex);
  return orientation > 0 ? agreement : 1.0 - agreement;
}

// What the sample searches compare besides the eigenfunctions, per source and per target
// sample: the anchor's coordinates (weighted), and from SampleCurvatureFromSize on the
// curvatures.
struct SearchColumns
{
  RowMatrix Source, Target;
};

SearchColumns SampleSearchColumns(const SpectralSurface& source, const SpectralSurface& target,
  const SampleAnchor& anchor, const CurvatureWeightArray& weights)
{
  const std::vector<size_t> shared = SharedCurvatures(source, target, weights);
  SearchColumns columns;
  columns.Source = Anchored(CurvatureColumns(source, source.Samples, target, weights, shared),
    anchor.Source, anchor.Weight);
  columns.Target = Anchored(CurvatureColumns(target, target.Samples, target, weights, shared),
    anchor.Target, anchor.Weight);
  return columns;
}

// One ZoomOut iteration's map came out as `targetVertex` from the functional map `c`: if it
// is decisively of the wrong orientation, the sign of one eigenfunction is wrong (the mirror
// symmetry negates the antisymmetric ones, and at the first of them the fit is a coin
// flip); redo the nearest-row search with each non-constant row of c negated in turn and
// keep the best-oriented map if it is decisively of the right orientation. Only the first
// kOrientationRows rows are tried: the sign that decides the orientation is that of the
// first antisymmetric function, which enters early. True if it tried.
bool KeepOrientation(const SpectralSurface& source, const SpectralSurface& target,
  const RowMatrix& sourceRows, const RowMatrix& targetRows, const Eigen::MatrixXd& c,
  const ZoomOutParameters& parameters, const SearchColumns& extra,
  std::vector<Index>& targetVertex)
{
  if (ExpectedSideShare(source, target, targetVertex, parameters.Orientation) >
    kOrientationDecided)
  {
    return false;
  }
  const int k = static_cast<int>(c.rows());
  const RowMatrix a = Appended(sourceRows.leftCols(k), extra.Source);
  double bestShare = 1.0 - kOrientationDecided;
  for (int row = 1; row < std::min(k, kOrientationRows + 1); ++row) // row 0: the constant
  {
    Eigen::MatrixXd flipped = c;
    flipped.row(row) *= -1;
    const std::vector<Index> nearest = NearestRows(
      a, Appended(targetRows.leftCols(k) * flipped.transpose(), extra.Target),
      parameters.NumberOfThreads);
    std::vector<Index> map(nearest.size());
    for (size_t i = 0; i < nearest.size(); ++i)
    {
      map[i] = target.Samples[nearest[i]];
    }
    const double share = ExpectedSideShare(source, target, map, parameters.Orientation);
    if (share >= bestShare)
    {
      bestShare = share;
      targetVertex = std::move(map);
    }
  }
  return true;
}
}

SampleMap ZoomOutOnSamples(const SpectralSurface& source, const SpectralSurface& target,
  const std::vector<Index>& initialTargetVertex, const ZoomOutParameters& parameters,
  const SampleAnchor& anchor)
{
  const int finalSize = std::min<int>(parameters.FinalSize,
    static_cast<int>(std::min(source.Embedding.cols(), target.Embedding.cols())));

  const RowMatrix sourceRows = GatherRows(source.Embedding, source.Samples, finalSize);
  const RowMatrix targetRows = GatherRows(target.Embedding, target.Samples, finalSize);

  const SearchColumns anchored = SampleSearchColumns(source, target, anchor, {});
  const SearchColumns withCurvatures =
    SampleSearchColumns(source, target, anchor, parameters.SampleCurvatureWeights);

  SampleMap result;
  result.TargetVertex = initialTargetVertex;
  ApplyPins(anchor.Pins, result.TargetVertex);
  int orientationTries = 0;
  for (int k = std::min(parameters.StartSize, finalSize);;
       k = std::min(NextBasisSize(k, parameters.Growth), finalSize))
  {
    const RowMatrix a = sourceRows.leftCols(k);
    const Eigen::MatrixXd c =
      FitFunctionalMap(a, GatherRows(target.Embedding, result.TargetVertex, k), anchor.Pins);
    // Row i of Phi_S ~ row T(i) of Phi_T C^T: transform the target side, as ZoomOut does
    // (for an orthogonal C the same as comparing Phi_S C with Phi_T; for the shrunk C of a
    // noisy start it keeps the queries from collapsing onto the target's small rows).
    const RowMatrix candidates = targetRows.leftCols(k) * c.transpose();
    const SearchColumns& extra =
      k >= parameters.SampleCurvatureFromSize ? withCurvatures : anchored;
    const std::vector<Index> nearest = NearestRows(Appended(a, extra.Source),
      Appended(candidates, extra.Target), parameters.NumberOfThreads);
    for (size_t i = 0; i < nearest.size(); ++i)
    {
      result.TargetVertex[i] = target.Samples[nearest[i]];
    }
    // A map that stays mirrored after a few tries (a shape with no mirror symmetry mapped
    // badly, or a flip that needs more than one sign) is left to RepairOrientation and the
    // candidate choice: retrying at every iteration tripled the candidate search on CGAL's
    // man, one of whose candidates stays mirrored.
    if (parameters.Orientation != 0 && orientationTries < kOrientationTries &&
      KeepOrientation(
        source, target, sourceRows, targetRows, c, parameters, extra, result.TargetVertex))
    {
      ++orientationTries;
    }
    ApplyPins(anchor.Pins, result.TargetVertex);
    if (k == finalSize)
    {
      break;
    }
  }
  result.FunctionalMap = FitFunctionalMap(
    sourceRows, GatherRows(target.Embedding, result.TargetVertex, finalSize), anchor.Pins);
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
  result.OrientationAgreement = OrientationAgreement(source, target, result.TargetVertex);
  result.CurvatureDifference = CurvatureDifference(source, target, result.TargetVertex);
  return result;
}

std::vector<Index> SampleMapFromFunctionalMap(const SpectralSurface& source,
  const SpectralSurface& target, const Eigen::MatrixXd& functionalMap, int numberOfThreads)
{
  const int k = static_cast<int>(functionalMap.rows());
  const RowMatrix candidates =
    GatherRows(target.Embedding, target.Samples, k) * functionalMap.transpose();
  const std::vector<Index> nearest =
    NearestRows(GatherRows(source.Embedding, source.Samples, k), candidates, numberOfThreads);
  std::vector<Index> map(nearest.size());
  for (size_t i = 0; i < nearest.size(); ++i)
  {
    map[i] = target.Samples[nearest[i]];
  }
  return map;
}

SampleMap RepairOrientation(const SpectralSurface& source, const SpectralSurface& target,
  const SampleMap& reversed, bool preserveOrientation, int flips,
  const ZoomOutParameters& parameters, const SampleAnchor& anchor)
{
  const int k = std::min<int>(flips + 1, static_cast<int>(reversed.FunctionalMap.rows()));
  // The reversed map's functional map on the first k functions, refitted from its samples.
  const Eigen::MatrixXd low = FitFunctionalMap(GatherRows(source.Embedding, source.Samples, k),
    GatherRows(target.Embedding, reversed.TargetVertex, k), anchor.Pins);
  ZoomOutParameters continued = parameters;
  continued.StartSize = NextBasisSize(k, parameters.Growth);
  SampleMap best = reversed;
  bool found = false;
  for (int row = 1; row < k; ++row) // row 0 is the constant function: never negated
  {
    Eigen::MatrixXd flipped = low;
    flipped.row(row) *= -1;
    SampleMap repaired = ZoomOutOnSamples(source, target,
      SampleMapFromFunctionalMap(source, target, flipped, parameters.NumberOfThreads), continued,
      anchor);
    if (HasOrientation(repaired, preserveOrientation) &&
      (!found || repaired.OrthogonalityResidual < best.OrthogonalityResidual))
    {
      best = std::move(repaired);
      found = true;
    }
  }
  return best;
}

DenseMap ExtendToAllVertices(const SpectralSurface& source, const SpectralSurface& target,
  const SampleMap& samples, const ZoomOutParameters& parameters,
  const std::vector<std::pair<Index, Index>>& pinned)
{
  const Index n = source.Embedding.rows();
  const Eigen::Index k = samples.FunctionalMap.cols();
  const RowMatrix sourceEmbedding = source.Embedding.leftCols(k);
  const RowMatrix targetEmbedding = target.Embedding.leftCols(k);

  DenseMap result;
  result.NearestVertex.resize(static_cast<size_t>(n));
  Eigen::MatrixXd c = samples.FunctionalMap;
  RowMatrix transformedTarget = targetEmbedding * c.transpose();
  ParallelForChunks<Index>(n, 1024, parameters.NumberOfThreads, [&](Index begin, Index end) {
    for (Index i = begin; i < end; ++i)
    {
      const Index label = source.SampleLabels[i];
      const Index start = label >= 0 ? samples.TargetVertex[label] : 0;
      result.NearestVertex[i] = DescendToNearestVertex(
        sourceEmbedding.row(i), transformedTarget, target.Neighbors, start);
    }
  });
  ApplyPins(pinned, result.NearestVertex);

  const auto& weights = parameters.FullResolutionCurvatureWeights;
  const std::vector<size_t> shared = SharedCurvatures(source, target, weights);
  const RowMatrix sourceQueries =
    Appended(sourceEmbedding, CurvatureColumns(source, AllVertices(n), target, weights, shared));
  const RowMatrix targetCurvatures = CurvatureColumns(
    target, AllVertices(target.Embedding.rows()), target, weights, shared);
  for (int iteration = 0; iteration < parameters.FullResolutionIterations; ++iteration)
  {
    // C = Phi_S^T M_S Pi Phi_T: the mass-weighted projection, exact on all vertices.
    const RowMatrix mapped = GatherRows(targetEmbedding, result.NearestVertex, static_cast<int>(k));
    c = sourceEmbedding.transpose() * (source.Mass * mapped);
    transformedTarget = targetEmbedding * c.transpose();
    // The nearest rows themselves, not a descent's local minima: on FAUST_r pairs a descent
    // stops short on 9-16% of the vertices, typically 2 edges from the nearest row and up to
    // 30, and maps with the nearest rows are about 2% better (docs/DEVELOPMENT.md, "The exact
    // nearest vertex"). The target's sample cells are the search's clusters.
    result.NearestVertex = NearestRowsByClusters(sourceQueries,
      Appended(transformedTarget, targetCurvatures), target.SampleLabels,
      parameters.NumberOfThreads);
    ApplyPins(pinned, result.NearestVertex);
  }
  result.FunctionalMap = sourceEmbedding.transpose() *
    (source.Mass * GatherRows(targetEmbedding, result.NearestVertex, static_cast<int>(k)));
  result.OrthogonalityResidual = OrthogonalityResidual(result.FunctionalMap);

  result.Triangle.resize(static_cast<size_t>(n));
  result.Barycentric.resize(static_cast<size_t>(n));
  ParallelForChunks<Index>(n, 1024, parameters.NumberOfThreads, [&](Index begin, Index end) {
    for (Index i = begin; i < end; ++i)
    {
      ProjectOntoIncidentTriangles(sourceEmbedding.row(i), transformedTarget, target.Faces, target.Corners,
        result.NearestVertex[i], result.Triangle[i], result.Barycentric[i]);
    }
  });
  // A landmark lands on its target vertex itself, a corner of a triangle around it.
  for (const auto& pin : pinned)
  {
    PlaceAtVertex(target.Faces, target.Corners, pin.second,
      result.Triangle[static_cast<size_t>(pin.first)],
      result.Barycentric[static_cast<size_t>(pin.first)]);
  }
  return result;
}
}
