// Rotational (and reflective) alignment of two real spherical functions by correlation over
// SO(3) (paper §6.2). Given harmonic coefficients of a source f and a target g, finds the
// orthogonal T maximizing
//     C(T) = ∫_{S²} f(T⁻¹ x) g(x) dx,
// i.e. the transform that, applied to the source, best matches the target.
//
// Pipeline (two bandwidths):
// 1. Search. A coarse correlation bandwidth B' is chosen from the product spectrum with a loose
//    tolerance (after heat smoothing, the high bands carry almost no energy and cannot move a
//    peak by more than a fraction of a grid cell). The Fourier tensor of C at B'
//    (SO3CorrelationTensor.h) is synthesized on the Euler grid α, γ ∈ 2πa/(2B'),
//    β ∈ πj/B', one β slice at a time (O(B'^2) memory per thread), keeping the best local
//    maxima, which Newton's method on the B' tensor moves off the grid.
// 2. Refinement. The few best well-separated candidates are polished by Newton's method on the
//    correlation summed over all bands l < B'' (EvaluateCorrelationSamples: value, gradient
//    and Hessian from the Wigner Δ matrices, O(B''^3) per pass for all candidates at once).
//    B'' drops only bands whose contribution to C and its first two derivatives is below
//    RefinementTolerance (round-off by default), so the answer does not depend on B'.
// Reflections: f(-x) has coefficients (-1)^l f_lm, so T = R·(-I) (det -1) is found by
// correlating the antipodal source.
#ifndef mobius_SO3Correlation_h
#define mobius_SO3Correlation_h

#include "MeshTypes.h" // ProgressCallback
#include "SphericalHarmonics.h"

#include <Eigen/Core>

#include <vector>

namespace mobius
{
enum class SO3ReflectionMode
{
  RotationsOnly = 0,   // det +1
  ReflectionsOnly = 1, // det -1
  Both = 2             // whichever scores higher
};

struct SO3CorrelationOptions
{
  /// How many well-separated peaks to return (best first).
  int NumberOfCandidates = 4;
  /// Minimum geodesic distance (radians) between returned candidates of the same determinant.
  double MinimumCandidateSeparation = 10.0 * 3.14159265358979323846 / 180.0;
  SO3ReflectionMode Reflections = SO3ReflectionMode::RotationsOnly;
  /// Search grid: drop bands l >= B' when Σ_{l>=B'} |f_l||g_l| <= tolerance · Σ_l |f_l||g_l|
  /// (|f_l| the norm of band l). By Cauchy-Schwarz this bounds the change of C anywhere. Only
  /// the grid search and its first Newton steps use B'; the final peaks come from the
  /// refinement below, so this trades search speed against the risk of missing a peak, not
  /// accuracy. 0 keeps all bands.
  double BandwidthTolerance = 1e-3;
  /// B' is at least min(this, B) so that the grid is fine enough to catch every peak...
  int MinimumCorrelationBandwidth = 24;
  /// ...and at most this (0: no limit besides B).
  int MaximumCorrelationBandwidth = 0;
  /// Newton refinement of the peaks below grid resolution (first on the B' tensor, then on
  /// the full-band correlation).
  bool RefinePeaks = true;
  /// Refinement bandwidth B'': bands l >= B'' are left out of the refinement when
  /// Σ_{l>=B''} (l+1)^2 |f_l||g_l| <= tolerance · Σ_l |f_l||g_l|, which bounds their effect on
  /// C, its gradient and its Hessian (in Euler angles) alike. The default is at round-off;
  /// 0 uses every band both inputs have.
  double RefinementTolerance = 1e-15;
  /// 0: automatic (ResolveThreadCount). The result is the same bit for bit for any count.
  int NumberOfThreads = 0;
  /// Called on the calling thread between the stages and between blocks of grid slices with
  /// the fraction done; returning false stops the search (the result is then Aborted, with
  /// no candidates). The grid search is most of a registration's time at high resolution.
  ProgressCallback Progress;
};

struct SO3Candidate
{
  /// x' = Transform x; Transform = Rotation for det +1, Rotation · (-I) for det -1.
  Eigen::Matrix3d Transform = Eigen::Matrix3d::Identity();
  double Determinant = 1.0;
  /// ZYZ Euler angles (α, β, γ) of the rotation part: R = Rz(α) Ry(β) Rz(γ).
  Eigen::Vector3d EulerAngles = Eigen::Vector3d::Zero();
  /// C(Transform) of the band-limited correlation (bands l < RefinementBandwidth; the grid
  /// bandwidth B' if RefinePeaks is off).
  double Score = 0.0;
  /// (|f|² + |g|² - 2 C) / (|f|² + |g|²) = |f∘T⁻¹ - g|² / (|f|² + |g|²), in [0, 2].
  double RegistrationError = 0.0;
  /// Pearson correlation of f∘T⁻¹ with g over the sphere, in [-1, 1]: C(T) with the
  /// constant band left out, divided by the norms of the mean-free signals (0 if either is
  /// constant). Unlike the score it ignores the signals' means and sizes.
  double CorrelationCoefficient = 0.0;
};

struct SO3CorrelationResult
{
  /// The best candidate (copied from Candidates[0]).
  Eigen::Matrix3d Transform = Eigen::Matrix3d::Identity();
  double Determinant = 1.0;
  Eigen::Vector3d EulerAngles = Eigen::Vector3d::Zero();
  double Score = 0.0;
  double RegistrationError = 0.0;
  double CorrelationCoefficient = 0.0;
  /// Best first; rotations and reflections mixed in mode Both.
  std::vector<SO3Candidate> Candidates;
  int CorrelationBandwidth = 0; // B' of the search grid
  int GridResolution = 0;       // 2B' samples per 2π in α and γ; B'+1 in β over [0, π]
  int RefinementBandwidth = 0;  // B'' >= B' of the refinement (B' if RefinePeaks is off)
  bool Aborted = false;         // Progress asked to stop: no candidates
  double SourceEnergy = 0.0;    // |f|² = Σ |f_lm|²
  double TargetEnergy = 0.0;
};

/// Runs the whole alignment. source and target must be coefficients of real functions;
/// bands beyond the smaller of the two bandwidths are ignored.
SO3CorrelationResult CorrelateOverRotations(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, const SO3CorrelationOptions& options = {});

/// The result's best transform and figures from its first candidate (after the candidates
/// were put in another order, e.g. by landmarks); nothing without candidates.
void TakeFirstCandidate(SO3CorrelationResult& result);

/// A candidate for the orthogonal `transform` whose correlation is `score`: its Euler
/// angles, registration error and correlation coefficient.
SO3Candidate ScoredCandidate(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, const Eigen::Matrix3d& transform, double score);

/// The candidate of any orthogonal `transform`, its correlation evaluated over every band
/// both inputs have (EvaluateCorrelationSamples).
SO3Candidate ScoreTransform(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, const Eigen::Matrix3d& transform,
  int numberOfThreads = 0);

/// B' from the tail bound described at SO3CorrelationOptions::BandwidthTolerance, clamped to
/// [min(minimum, B), maximum or B] and rounded up to a size whose FFTs are fast (2^a 3^b 5^c).
int ChooseCorrelationBandwidth(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, double tolerance, int minimum = 16,
  int maximum = 0);

/// B'' from the weighted tail bound described at SO3CorrelationOptions::RefinementTolerance
/// (tolerance <= 0: all bands both inputs have).
int ChooseRefinementBandwidth(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, double tolerance);

/// One point of EvaluateCorrelationSamples: the input T = ±Rz(α)Ry(β)Rz(γ) and the outputs.
struct SO3CorrelationSample
{
  Eigen::Vector3d EulerAngles = Eigen::Vector3d::Zero(); // (α, β, γ), any real values
  bool ReflectSource = false;                           // T = -Rz(α)Ry(β)Rz(γ) (det -1)
  double Value = 0.0;                                   // C(T)
  Eigen::Vector3d Gradient = Eigen::Vector3d::Zero();   // ∂C/∂(α, β, γ)
  Eigen::Matrix3d Hessian = Eigen::Matrix3d::Zero();    // ∂²C/∂(α, β, γ)²
};

/// C and its derivatives at every sample, summed over the bands l < bandwidth (0: all bands
/// both inputs have) straight from the Wigner Δ matrices: per band, Δ^l is generated once and
/// applied to all samples together (dense products on its four parity blocks), so a call costs
/// about (6 · samples + 3) B^3 / 3 flops with O(B^2) memory per thread. Exact to round-off for
/// any angles (no grid); the result does not depend on the thread count.
void EvaluateCorrelationSamples(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, std::vector<SO3CorrelationSample>& samples,
  int bandwidth = 0, int numberOfThreads = 0);
}

#endif
