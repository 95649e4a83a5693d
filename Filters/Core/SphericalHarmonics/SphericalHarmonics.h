// Complex spherical harmonics and a fast transform on the cell-centered equirectangular grid.
//
// Conventions (shared with the SO(3) correlation; see docs/architecture.md, "Conventions"):
// - z is the polar axis, theta in [0, pi] from +z, phi = atan2(y, x) in [0, 2 pi).
// - The grid has N = 2B rows and columns for bandwidth B. Cell (j, i) spans
//   theta in [pi j/N, pi (j+1)/N], phi in [2 pi i/N, 2 pi (i+1)/N] and holds the sample at its
//   center theta_j = pi (j + 1/2)/N, phi_i = 2 pi (i + 1/2)/N, stored at values[j*N + i]
//   (row j is a latitude band counted from the north pole).
// - Y_l^m(theta, phi) = sqrt((2l+1)/(4 pi) (l-m)!/(l+m)!) P_l^m(cos theta) e^{i m phi}, orthonormal on
//   the unit sphere, with the Condon-Shortley phase (-1)^m inside P_l^m, so that
//   Y_l^{-m} = (-1)^m conj(Y_l^m) and a real function has f_{l,-m} = (-1)^m conj(f_{l,m}).
#ifndef mobius_SphericalHarmonics_h
#define mobius_SphericalHarmonics_h

#include <complex>
#include <memory>
#include <vector>

namespace mobius
{
/// Coefficients f_lm of a band-limited function, 0 <= l < Bandwidth, -l <= m <= l.
struct SphericalHarmonicCoefficients
{
  int Bandwidth = 0;
  std::vector<std::complex<double>> Values; // size Bandwidth^2, ordered by Index(l, m)

  static int Index(int l, int m) { return l * l + l + m; }
  /// Sets the bandwidth and zero-fills all coefficients.
  void Resize(int bandwidth);
  std::complex<double>& operator()(int l, int m) { return Values[Index(l, m)]; }
  const std::complex<double>& operator()(int l, int m) const { return Values[Index(l, m)]; }
};

/// Forward and inverse transforms on the cell-centered N = 2B grid, O(B^3) each,
/// multi-threaded over the order m. Construction plans the FFTs (under the process-wide FFTW
/// planner mutex, see FFTWPlannerMutex.h); Forward and Inverse may be called concurrently.
class SphericalHarmonicTransform
{
public:
  /// bandwidth >= 1; numberOfThreads = 0 means automatic (ResolveThreadCount).
  explicit SphericalHarmonicTransform(int bandwidth, int numberOfThreads = 0);
  ~SphericalHarmonicTransform();
  SphericalHarmonicTransform(const SphericalHarmonicTransform&) = delete;
  SphericalHarmonicTransform& operator=(const SphericalHarmonicTransform&) = delete;

  int GetBandwidth() const { return this->Bandwidth; }
  int GetResolution() const { return 2 * this->Bandwidth; }

  /// grid: N*N real samples (layout above). Exact to round-off for functions band-limited
  /// to l < B. Resizes `coefficients` to this bandwidth; fills all m, negative m by the
  /// real-function symmetry.
  void Forward(const double* grid, SphericalHarmonicCoefficients& coefficients) const;

  /// Writes the real part of sum_{l,m} f_lm Y_lm at the N*N cell centers (for coefficients of
  /// a real function this is the function itself). Coefficients with l >= B are ignored; a
  /// smaller coefficient bandwidth means the missing ones are zero.
  void Inverse(const SphericalHarmonicCoefficients& coefficients, double* grid) const;

  /// Quadrature weight of row j (includes sin theta): sum_j w_j p(cos theta_j) equals
  /// the integral of p over [-1, 1] for polynomials of degree < N.
  double GetQuadratureWeight(int row) const { return this->Weights[row]; }

private:
  struct FFTPlans;
  int Bandwidth;
  int NumberOfThreads;
  std::vector<double> Weights;  // N quadrature weights (symmetric in j <-> N-1-j)
  std::vector<double> Cosines;  // cos theta_j for the B northern rows
  std::vector<double> Sines;    // sin theta_j for the B northern rows
  std::unique_ptr<FFTPlans> Plans;
};

/// Heat-kernel low pass: f_lm *= exp(-t l(l+1)).
void SmoothWithHeatKernel(SphericalHarmonicCoefficients& coefficients, double time);

/// The energy of each degree, E_l = sum over m of |f_lm|^2, l = 0 .. Bandwidth-1: the
/// function's power spectrum. A rotation (or reflection) of the sphere mixes the
/// coefficients only within a degree, unitarily, so E_l does not change: a descriptor of a
/// centered map that needs no alignment (their sum is the integral of f^2).
std::vector<double> DegreeEnergies(const SphericalHarmonicCoefficients& coefficients);
}

#endif
