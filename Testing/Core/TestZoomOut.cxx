// Spectral refinement core: the Laplace-Beltrami basis of a sphere has the known spectrum
// and is mass-orthonormal, with the blended mass matrix nearer the exact spectrum than the
// lumped one; a basis of many functions (found in slices of the spectrum) is the lowest part
// of the whole spectrum, none missed or repeated; ZoomOut recovers the identity map of a
// shape without symmetries from a perturbed start, and an isometric (rigidly moved) copy
// with another vertex order; the curvatures join the nearest-row searches when and where
// they should; the orientation check turns a symmetric shape's mirror map into the identity.
#include "CoreTest.h"
#include "CotangentLaplacian.h"
#include "Icosphere.h"
#include "LaplaceBeltramiBasis.h"
#include "MeshAdjacency.h"
#include "ZoomOut.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numeric>
#include <random>
#include <string>

using namespace mobius;

namespace
{
// A sphere squashed into an ellipsoid with distinct axes and a bump, so that no rotation or
// reflection maps it onto itself (ZoomOut could otherwise converge to a symmetry).
void MakeAsymmetricBlob(Points& points, Triangles& triangles, int subdivisions = 4)
{
  MakeIcosphere(subdivisions, points, triangles);
  for (Index i = 0; i < points.rows(); ++i)
  {
    const Eigen::Vector3d p = points.row(i);
    const double bump = 0.4 * std::exp(-8.0 * (p - Eigen::Vector3d(0.6, 0.64, 0.48)).squaredNorm());
    points.row(i) << 1.6 * p.x() * (1 + bump), p.y() * (1 + bump), 0.7 * p.z() * (1 + bump);
  }
}

void TestSphereSpectrum()
{
  Points points;
  Triangles triangles;
  MakeIcosphere(4, points, triangles);
  LaplaceBeltramiBasis basis;
  std::string error;
  MOBIUS_CHECK(ComputeLaplaceBeltramiBasis(points, triangles, 9, basis, error));
  MOBIUS_CHECK(error.empty());
  // Unit area: radius^2 = 1 / (4 pi), eigenvalues l (l + 1) / radius^2 with multiplicity 2l+1.
  MOBIUS_CHECK_NEAR(basis.Eigenvalues[0], 0.0, 1e-6);
  for (int j = 1; j < 4; ++j)
  {
    MOBIUS_CHECK_NEAR(basis.Eigenvalues[j], 8 * M_PI, 0.01 * 8 * M_PI);
  }
  for (int j = 4; j < 9; ++j)
  {
    MOBIUS_CHECK_NEAR(basis.Eigenvalues[j], 24 * M_PI, 0.01 * 24 * M_PI);
  }
  const Eigen::MatrixXd gram =
    basis.Functions.transpose() * (basis.Mass * basis.Functions);
  MOBIUS_CHECK_NEAR((gram - Eigen::MatrixXd::Identity(9, 9)).norm(), 0.0, 1e-8);
  MOBIUS_CHECK_NEAR(basis.Mass.sum(), 1.0, 1e-12);
  // Too large a basis is refused with a reason.
  MOBIUS_CHECK(!ComputeLaplaceBeltramiBasis(points, triangles, static_cast<int>(points.rows()),
    basis, error));
  MOBIUS_CHECK(error.find("basis size") != std::string::npos);
}

// The blended (half consistent, half lumped) mass matrix against the lumped one: the same
// total area, a diagonal matrix at share 0, and eigenvalues nearer the sphere's exact ones
// (the lumped mass puts them too low, the consistent one too high).
void TestMassMatrixBlend()
{
  Points points;
  Triangles triangles;
  MakeIcosphere(3, points, triangles);
  SparseMatrix lumpedMatrix, blendedMatrix;
  MOBIUS_CHECK(BuildMassMatrix(points, triangles, true, 0.0, lumpedMatrix));
  MOBIUS_CHECK(BuildMassMatrix(points, triangles, true, 0.5, blendedMatrix));
  const double area = TriangleAreas(points, triangles).sum();
  MOBIUS_CHECK_NEAR(lumpedMatrix.sum(), area, 1e-12 * area);
  MOBIUS_CHECK_NEAR(blendedMatrix.sum(), area, 1e-12 * area);
  MOBIUS_CHECK_NEAR((Vector(lumpedMatrix.diagonal()) - LumpedMass(points, triangles)).norm(),
    0.0, 1e-12 * area);
  MOBIUS_CHECK(blendedMatrix.diagonal().sum() < 0.9 * area); // off-diagonal mass

  LaplaceBeltramiBasis lumped, blended, consistent;
  std::string error;
  MOBIUS_CHECK(ComputeLaplaceBeltramiBasis(points, triangles, 16, lumped, error, 0.0));
  MOBIUS_CHECK(ComputeLaplaceBeltramiBasis(points, triangles, 16, blended, error, 0.5));
  MOBIUS_CHECK(ComputeLaplaceBeltramiBasis(points, triangles, 16, consistent, error, 1.0));
  double lumpedError = 0, blendedError = 0;
  for (int j = 9; j < 16; ++j) // l = 3: 48 pi on the unit-area sphere
  {
    const double exact = 48 * M_PI;
    MOBIUS_CHECK(lumped.Eigenvalues[j] < exact && consistent.Eigenvalues[j] > exact);
    lumpedError += std::abs(lumped.Eigenvalues[j] - exact);
    blendedError += std::abs(blended.Eigenvalues[j] - exact);
  }
  std::cout << "l = 3 eigenvalue error, lumped " << lumpedError / 7 << ", blended "
            << blendedError / 7 << "\n";
  MOBIUS_CHECK(blendedError < 0.25 * lumpedError);
  const Eigen::MatrixXd gram = blended.Functions.transpose() * (blended.Mass * blended.Functions);
  MOBIUS_CHECK_NEAR((gram - Eigen::MatrixXd::Identity(16, 16)).norm(), 0.0, 1e-8);
}

// Many eigenpairs (several windows of the spectrum) against the whole spectrum of the same
// generalized problem by a dense solver: the same eigenvalues, none missed or found twice
// where windows meet, on a shape without symmetries and on a sphere, whose eigenvalues come
// in clusters of 2l + 1 that a window's edge can cut.
void TestManyEigenpairsMatchDenseSpectrum()
{
  for (const bool sphere : { false, true })
  {
    Points points;
    Triangles triangles;
    if (sphere)
    {
      MakeIcosphere(3, points, triangles); // 642 vertices
    }
    else
    {
      MakeAsymmetricBlob(points, triangles, 3);
    }
    const int count = 121; // several windows; ends inside the sphere's l = 10 cluster
    LaplaceBeltramiBasis basis;
    std::string error;
    MOBIUS_CHECK(ComputeLaplaceBeltramiBasis(points, triangles, count, basis, error));
    SparseMatrix stiffness;
    CotangentStiffnessInfo info;
    MOBIUS_CHECK(BuildCotangentStiffness(points, triangles, true, stiffness, info));
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(
      Eigen::MatrixXd(stiffness), Eigen::MatrixXd(basis.Mass));
    double largestError = 0;
    for (int j = 1; j < count; ++j)
    {
      largestError = std::max(largestError,
        std::abs(basis.Eigenvalues[j] - dense.eigenvalues()[j]) / dense.eigenvalues()[j]);
    }
    std::cout << (sphere ? "sphere" : "blob") << ": largest relative eigenvalue error "
              << largestError << "\n";
    MOBIUS_CHECK(largestError < 1e-7);
    const Eigen::MatrixXd gram = basis.Functions.transpose() * (basis.Mass * basis.Functions);
    MOBIUS_CHECK_NEAR((gram - Eigen::MatrixXd::Identity(count, count)).norm(), 0.0, 1e-8);
    const Eigen::MatrixXd residual = stiffness * basis.Functions -
      basis.Mass * basis.Functions * basis.Eigenvalues.asDiagonal();
    MOBIUS_CHECK(residual.norm() < 1e-6 * basis.Eigenvalues[count - 1]);
  }
}

double MeanVertexError(const std::vector<Index>& map, const std::vector<Index>& truth,
  const Points& targetPoints)
{
  double sum = 0;
  for (size_t i = 0; i < map.size(); ++i)
  {
    sum += (targetPoints.row(map[i]) - targetPoints.row(truth[i])).norm();
  }
  return sum / map.size();
}

// Every sample sent to a vertex two random steps away.
std::vector<Index> PerturbedStart(const SpectralSurface& surface)
{
  std::mt19937 random(7);
  std::vector<Index> start;
  for (Index s : surface.Samples)
  {
    Index v = s;
    for (int step = 0; step < 2; ++step)
    {
      const Index degree = surface.Neighbors.End(v) - surface.Neighbors.Begin(v);
      v = surface.Neighbors.Items[surface.Neighbors.Begin(v) + random() % degree];
    }
    start.push_back(v);
  }
  return start;
}

void TestIdentityFromPerturbedStart()
{
  Points points;
  Triangles triangles;
  MakeAsymmetricBlob(points, triangles);
  SpectralSurface surface;
  std::string error;
  MOBIUS_CHECK(PrepareSpectralSurface(points, triangles, 40, 500, surface, error));
  const std::vector<Index> start = PerturbedStart(surface);
  MOBIUS_CHECK(MeanVertexError(start, surface.Samples, points) > 0.05);
  ZoomOutParameters parameters;
  parameters.StartSize = 10;
  parameters.FinalSize = 40;
  const SampleMap samples = ZoomOutOnSamples(surface, surface, start, parameters);
  MOBIUS_CHECK_NEAR(MeanVertexError(samples.TargetVertex, surface.Samples, points), 0.0, 1e-12);
  MOBIUS_CHECK_NEAR(samples.OrthogonalityResidual, 0.0, 1e-6);
  MOBIUS_CHECK_NEAR(samples.TargetCoverage, 1.0, 1e-12);
  const DenseMap dense = ExtendToAllVertices(surface, surface, samples, parameters);
  std::vector<Index> identity(static_cast<size_t>(points.rows()));
  std::iota(identity.begin(), identity.end(), Index(0));
  MOBIUS_CHECK_NEAR(MeanVertexError(dense.NearestVertex, identity, points), 0.0, 1e-12);
  double pointError = 0;
  for (Index i = 0; i < points.rows(); ++i)
  {
    Eigen::RowVector3d mapped = Eigen::RowVector3d::Zero();
    for (int k = 0; k < 3; ++k)
    {
      mapped += dense.Barycentric[i][k] * points.row(triangles(dense.Triangle[i], k));
    }
    pointError = std::max(pointError, (mapped - points.row(i)).norm());
  }
  MOBIUS_CHECK_NEAR(pointError, 0.0, 1e-9);
  std::cout << "identity: sample residual " << samples.OrthogonalityResidual << ", max point error "
            << pointError << std::endl;
}

// The curvatures in the nearest-row searches: the sample iterations take them only from
// SampleCurvatureFromSize on, and a curvature that one surface lacks is left out on both sides
// (the queries and the points must have the same coordinates). The pair: the blob onto a
// copy stretched along x, so that the maps are not exact and the coordinates matter.
void TestCurvatureCoordinates()
{
  Points points, stretchedPoints;
  Triangles triangles;
  MakeAsymmetricBlob(points, triangles);
  stretchedPoints = points;
  stretchedPoints.col(0) *= 1.3;
  SpectralSurface source, target;
  std::string error;
  MOBIUS_CHECK(PrepareSpectralSurface(points, triangles, 40, 500, source, error));
  MOBIUS_CHECK(PrepareSpectralSurface(stretchedPoints, triangles, 40, 500, target, error));
  MOBIUS_CHECK(source.PolishCurvatures.size() == kPolishCurvatures.size());
  const std::vector<Index> start = PerturbedStart(source);

  ZoomOutParameters plain;
  plain.StartSize = 10;
  plain.FinalSize = 40;
  plain.SampleCurvatureWeights = { 0.0, 0.0 };
  plain.FullResolutionCurvatureWeights = { 0.0, 0.0 };
  ZoomOutParameters curved = plain;
  curved.SampleCurvatureWeights = { 30.0, 30.0 }; // the curvatures outweigh the eigenfunctions
  curved.FullResolutionCurvatureWeights = { 30.0, 30.0 };
  curved.SampleCurvatureFromSize = 0;
  ZoomOutParameters late = curved;
  late.SampleCurvatureFromSize = plain.FinalSize + 1;

  const SampleMap withoutCurvature = ZoomOutOnSamples(source, target, start, plain);
  MOBIUS_CHECK(ZoomOutOnSamples(source, target, start, late).TargetVertex ==
    withoutCurvature.TargetVertex);
  const SampleMap withCurvature = ZoomOutOnSamples(source, target, start, curved);
  MOBIUS_CHECK(withCurvature.TargetVertex != withoutCurvature.TargetVertex);

  // A source without curvatures: the target's are not compared either.
  SpectralSurface bare = source;
  bare.PolishCurvatures.clear();
  MOBIUS_CHECK(ZoomOutOnSamples(bare, target, start, curved).TargetVertex ==
    withoutCurvature.TargetVertex);
  const DenseMap bareDense = ExtendToAllVertices(bare, target, withoutCurvature, curved);
  MOBIUS_CHECK(bareDense.NearestVertex ==
    ExtendToAllVertices(bare, target, withoutCurvature, plain).NearestVertex);
  MOBIUS_CHECK(ExtendToAllVertices(source, target, withoutCurvature, curved).NearestVertex !=
    bareDense.NearestVertex);
}

// The orientation check of ZoomOutOnSamples, on a shape whose only symmetry is the mirror
// x -> -x (an ellipsoid with two bumps placed symmetrically about x = 0), mapped onto
// itself from its mirror map, with the first iteration's basis holding exactly one
// antisymmetric eigenfunction: the state the real refinement is in when that function
// first enters with the wrong sign. The mirror map is a fixed point of ZoomOut, so without
// the check (Orientation 0) the result stays the mirror image; expecting orientation to be
// preserved, the negated row turns it into the identity, and expecting it reversed keeps
// the mirror map.
void TestOrientationCheck()
{
  Points points;
  Triangles triangles;
  MakeIcosphere(4, points, triangles);
  for (Index i = 0; i < points.rows(); ++i)
  {
    const Eigen::Vector3d p = points.row(i);
    const Eigen::Vector3d mirrored(-p.x(), p.y(), p.z());
    const Eigen::Vector3d center(0.6, 0.64, 0.48);
    const double bump = 0.4 * std::exp(-8.0 * (p - center).squaredNorm()) +
      0.4 * std::exp(-8.0 * (mirrored - center).squaredNorm());
    points.row(i) << 1.6 * p.x() * (1 + bump), p.y() * (1 + bump), 0.7 * p.z() * (1 + bump);
  }
  // The icosphere is symmetric about x = 0 vertex for vertex: find each vertex's mirror.
  std::vector<Index> mirror(static_cast<size_t>(points.rows()), -1);
  for (Index i = 0; i < points.rows(); ++i)
  {
    const Eigen::RowVector3d image(-points(i, 0), points(i, 1), points(i, 2));
    for (Index j = 0; j < points.rows(); ++j)
    {
      if ((points.row(j) - image).norm() < 1e-9)
      {
        mirror[i] = j;
      }
    }
  }
  MOBIUS_CHECK(std::find(mirror.begin(), mirror.end(), Index(-1)) == mirror.end());
  SpectralSurface surface;
  std::string error;
  MOBIUS_CHECK(PrepareSpectralSurface(points, triangles, 40, 500, surface, error));
  // The first antisymmetric eigenfunction (phi(mirror(v)) = -phi(v)).
  int firstAntisymmetric = 0;
  for (int j = 1; j < 40 && firstAntisymmetric == 0; ++j)
  {
    double product = 0, square = 0;
    for (Index v = 0; v < points.rows(); ++v)
    {
      product += surface.Embedding(v, j) * surface.Embedding(mirror[v], j);
      square += surface.Embedding(v, j) * surface.Embedding(v, j);
    }
    firstAntisymmetric = product < -0.99 * square ? j : 0;
  }
  MOBIUS_CHECK(firstAntisymmetric > 0);
  std::vector<Index> start;
  for (Index s : surface.Samples)
  {
    start.push_back(mirror[s]);
  }
  ZoomOutParameters parameters;
  parameters.StartSize = firstAntisymmetric + 1;
  parameters.Growth = 0; // one function per iteration: the next antisymmetric one enters alone
  parameters.FinalSize = 40;
  // Mean distances from the identity and from the mirror map (a sample's mirror image need
  // not be a sample, so a map between samples can only come near the latter: measured
  // 0.066, where the mirror map is 1.57 from the identity on this blob 3.2 long).
  double errors[3], mirrorErrors[3], agreement[3];
  for (int orientation : { 0, 1, -1 })
  {
    parameters.Orientation = orientation;
    const SampleMap map = ZoomOutOnSamples(surface, surface, start, parameters);
    errors[orientation + 1] = MeanVertexError(map.TargetVertex, surface.Samples, points);
    mirrorErrors[orientation + 1] = MeanVertexError(map.TargetVertex, start, points);
    agreement[orientation + 1] = map.OrientationAgreement;
    std::cout << "from the mirror map, orientation " << orientation << ": error "
              << errors[orientation + 1] << " (from the mirror map "
              << mirrorErrors[orientation + 1] << "), orientation agreement "
              << map.OrientationAgreement << std::endl;
  }
  // Without the check: the mirror image (far from the identity, every triangle flipped).
  MOBIUS_CHECK(errors[1] > 1 && mirrorErrors[1] < 0.1);
  MOBIUS_CHECK(agreement[1] < 0.05);
  // Expecting orientation preserved: the identity.
  MOBIUS_CHECK_NEAR(errors[2], 0.0, 1e-12);
  MOBIUS_CHECK(agreement[2] > 0.99);
  // Expecting it reversed: the mirror map stays.
  MOBIUS_CHECK(errors[0] > 1 && mirrorErrors[0] < 0.1 && agreement[0] < 0.05);
}
}

int main()
{
  TestSphereSpectrum();
  TestMassMatrixBlend();
  TestManyEigenpairsMatchDenseSpectrum();
  TestIdentityFromPerturbedStart();
  TestCurvatureCoordinates();
  TestOrientationCheck();
  return MOBIUS_TEST_RESULT();
}
