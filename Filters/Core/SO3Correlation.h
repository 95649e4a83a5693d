// Rotational (and reflective) alignment of two real spherical functions by correlation over
// SO(3) (paper §6.2). Given harmonic coefficients of a source f and a target g, finds the
// orthogonal T maximizing
//     C(T) = ∫_{S²} f(T⁻¹ x) g(x) dx,
// i.e. the transform that, applied to the source, best matches the target.
//
// Pipeline: choose a correlation bandwidth B' <= B from the spectra (bands whose product
// energy is negligible are dropped; fine angles come from refinement, not from a huge grid);
// build the Fourier tensor of C (SO3CorrelationTensor.h); synthesize C on the Euler grid
// α, γ ∈ 2πa/(2B'), β ∈ πj/B' one β slice at a time (O(B'^2) memory per thread) and keep the
// best local maxima; refine them by Newton's method on the exact band-limited C; return the
// best well-separated candidates. Reflections: f(-x) has coefficients (-1)^l f_lm, so
// T = R·(-I) (det -1) is found by correlating the antipodal source.
#ifndef mobius_SO3Correlation_h
#define mobius_SO3Correlation_h

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
  /// Drop bands l >= B' when Σ_{l>=B'} |f_l||g_l| <= tolerance · Σ_l |f_l||g_l| (|f_l| the
  /// norm of band l). By Cauchy-Schwarz this bounds the change of C anywhere. 0 keeps all.
  double BandwidthTolerance = 1e-12;
  /// B' is at least min(this, B) so that the grid is fine enough to catch every peak...
  int MinimumCorrelationBandwidth = 16;
  /// ...and at most this (0: no limit besides B).
  int MaximumCorrelationBandwidth = 0;
  /// Newton refinement of the peaks below grid resolution.
  bool RefinePeaks = true;
  /// 0: one thread per core.
  int NumberOfThreads = 0;
};

struct SO3Candidate
{
  /// x' = Transform x; Transform = Rotation for det +1, Rotation · (-I) for det -1.
  Eigen::Matrix3d Transform = Eigen::Matrix3d::Identity();
  double Determinant = 1.0;
  /// ZYZ Euler angles (α, β, γ) of the rotation part: R = Rz(α) Ry(β) Rz(γ).
  Eigen::Vector3d EulerAngles = Eigen::Vector3d::Zero();
  /// C(Transform) of the band-limited (B') correlation.
  double Score = 0.0;
  /// (|f|² + |g|² - 2 C) / (|f|² + |g|²) = |f∘T⁻¹ - g|² / (|f|² + |g|²), in [0, 2].
  double RegistrationError = 0.0;
};

struct SO3CorrelationResult
{
  /// The best candidate (copied from Candidates[0]).
  Eigen::Matrix3d Transform = Eigen::Matrix3d::Identity();
  double Determinant = 1.0;
  Eigen::Vector3d EulerAngles = Eigen::Vector3d::Zero();
  double Score = 0.0;
  double RegistrationError = 0.0;
  /// Best first; rotations and reflections mixed in mode Both.
  std::vector<SO3Candidate> Candidates;
  int CorrelationBandwidth = 0; // B'
  int GridResolution = 0;       // 2B' samples per 2π in α and γ; B'+1 in β over [0, π]
  double SourceEnergy = 0.0;    // |f|² = Σ |f_lm|²
  double TargetEnergy = 0.0;
};

/// Runs the whole alignment. source and target must be coefficients of real functions;
/// bands beyond the smaller of the two bandwidths are ignored.
SO3CorrelationResult CorrelateOverRotations(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, const SO3CorrelationOptions& options = {});

/// B' from the tail bound described at SO3CorrelationOptions::BandwidthTolerance, clamped to
/// [min(minimum, B), maximum or B] and rounded up to a size whose FFTs are fast (2^a 3^b 5^c).
int ChooseCorrelationBandwidth(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, double tolerance, int minimum = 16,
  int maximum = 0);

/// C(T) summed directly from Wigner D matrices (O(B^3), long-double recursion); for checks.
double EvaluateCorrelationDirectly(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, const Eigen::Matrix3d& transform);

/// The whole Euler grid at correlation bandwidth B' (memory (B'+1)(2B')^2 doubles; for tests
/// and visualization): value C(α_a, β_j, γ_c) at index (j * M + c) * M + a, M = 2B',
/// α_a = 2πa/M, β_j = πj/B' (0 <= j <= B'), γ_c = 2πc/M.
std::vector<double> ComputeCorrelationGrid(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, int correlationBandwidth, bool reflectSource,
  int numberOfThreads = 0);
}

#endif
