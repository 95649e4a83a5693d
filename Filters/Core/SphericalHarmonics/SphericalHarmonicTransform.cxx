// Fast spherical harmonic transform on the cell-centered N = 2B equirectangular grid:
// FFTs along each latitude row, then per order m a Legendre sum over the rows, O(B^3) total.
//
// Forward:  f_lm = sum_j w_j Pbar_l^m(cos theta_j) G_j(m),
//           G_j(m) = (2 pi/N) sum_i f(theta_j, phi_i) e^{-i m phi_i} = (2 pi/N) e^{-i m pi/N} F_j(m),
// where F_j is the unshifted DFT of row j (FFTW r2c) and e^{-i m pi/N} accounts for the samples
// sitting at phi_i = 2 pi (i + 1/2)/N, i.e. half a cell east of 2 pi i/N.
// The azimuthal sum is exact for |m| < B because products e^{i(m'-m)phi} with |m'-m| < N do not
// alias on N points. The polar sum is exact because w_j (Fejer's first rule on the nodes
// theta_j = pi (2j+1)/(4B)) integrates polynomials in cos theta of degree < N = 2B exactly, and
// Pbar_l^m Pbar_l'^m is such a polynomial for l, l' < B.
//
// Symmetry halves the Legendre work: rows j and N-1-j have cos theta of opposite sign, and
// Pbar_l^m(-x) = (-1)^(l+m) Pbar_l^m(x), so only the B northern rows are recursed over.
#include "SphericalHarmonics.h"

#include "FFTWPlannerMutex.h"
#include "NormalizedLegendre.h"
#include "ParallelFor.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mobius
{
namespace
{
/// Fejer's first-rule weights for theta_j = pi (2j+1)/(2n): with
/// w_j = sum_k a_k cos(k theta_j) and the discrete orthogonality of cos(k theta_j), requiring
/// sum_j w_j cos(k theta_j) = int_0^pi cos(k theta) sin(theta) dtheta = 2/(1-k^2) (k even), 0 (k odd)
/// gives a_0 = 2/n and a_k = 4/(n (1-k^2)) for even 0 < k < n.
std::vector<double> QuadratureWeights(int n)
{
  std::vector<double> weights(n);
  for (int j = 0; j < n; ++j)
  {
    const double theta = M_PI * (2.0 * j + 1.0) / (2.0 * n);
    double sum = 1.0;
    for (int p = 1; 2 * p < n; ++p)
    {
      sum -= 2.0 * std::cos(2.0 * p * theta) / (4.0 * p * p - 1.0);
    }
    weights[j] = 2.0 / n * sum;
  }
  return weights;
}
}

struct SphericalHarmonicTransform::FFTPlans
{
  fftw_plan RealToComplex = nullptr; // one row: N reals -> N/2+1 complex
  fftw_plan ComplexToReal = nullptr; // one row: N/2+1 complex -> N reals (destroys its input)
};

SphericalHarmonicTransform::SphericalHarmonicTransform(int bandwidth, int numberOfThreads)
  : Bandwidth(bandwidth)
  , NumberOfThreads(numberOfThreads)
  , Plans(new FFTPlans)
{
  if (bandwidth < 1)
  {
    throw std::invalid_argument("SphericalHarmonicTransform: bandwidth must be at least 1");
  }
  this->NumberOfThreads = ResolveThreadCount(this->NumberOfThreads);
  const int n = 2 * bandwidth;
  this->Weights = QuadratureWeights(n);
  this->Cosines.resize(bandwidth);
  this->Sines.resize(bandwidth);
  for (int j = 0; j < bandwidth; ++j)
  {
    const double theta = M_PI * (2.0 * j + 1.0) / (2.0 * n);
    this->Cosines[j] = std::cos(theta);
    this->Sines[j] = std::sin(theta);
  }

  // Plans are made once on scratch rows and executed later on arbitrary rows with the
  // new-array interface; FFTW_UNALIGNED because user grid rows carry no alignment promise.
  double* real = fftw_alloc_real(n);
  fftw_complex* spectrum = fftw_alloc_complex(n / 2 + 1);
  {
    std::lock_guard<std::mutex> lock(FFTWPlannerMutex());
    this->Plans->RealToComplex = fftw_plan_dft_r2c_1d(
      n, real, spectrum, FFTW_ESTIMATE | FFTW_UNALIGNED | FFTW_PRESERVE_INPUT);
    this->Plans->ComplexToReal = fftw_plan_dft_c2r_1d(
      n, spectrum, real, FFTW_ESTIMATE | FFTW_UNALIGNED | FFTW_DESTROY_INPUT);
  }
  fftw_free(real);
  fftw_free(spectrum);
  if (!this->Plans->RealToComplex || !this->Plans->ComplexToReal)
  {
    throw std::runtime_error("SphericalHarmonicTransform: FFTW planning failed");
  }
}

SphericalHarmonicTransform::~SphericalHarmonicTransform()
{
  std::lock_guard<std::mutex> lock(FFTWPlannerMutex());
  fftw_destroy_plan(this->Plans->RealToComplex);
  fftw_destroy_plan(this->Plans->ComplexToReal);
}

void SphericalHarmonicTransform::Forward(
  const double* grid, SphericalHarmonicCoefficients& coefficients) const
{
  const int b = this->Bandwidth;
  const int n = 2 * b;
  const int width = b + 1; // FFTW r2c output length n/2 + 1
  std::vector<std::complex<double>> spectra(static_cast<size_t>(n) * width);

  const int rowsPerTask = 16;
  ParallelFor((n + rowsPerTask - 1) / rowsPerTask, this->NumberOfThreads, [&](int task, int) {
    for (int j = task * rowsPerTask; j < std::min(n, (task + 1) * rowsPerTask); ++j)
    {
      fftw_execute_dft_r2c(this->Plans->RealToComplex, const_cast<double*>(grid + size_t(j) * n),
        reinterpret_cast<fftw_complex*>(spectra.data() + size_t(j) * width));
    }
  });

  coefficients.Resize(b);
  ParallelFor(b, this->NumberOfThreads, [&](int m, int) {
    // Even and odd (in cos theta) parts of the weighted row transforms, phase-shifted to
    // the cell centers and scaled by the azimuthal quadrature weight 2 pi/N.
    const std::complex<double> shift = std::polar(2.0 * M_PI / n, -M_PI * m / n);
    std::vector<double> evenRe(b), evenIm(b), oddRe(b), oddIm(b);
    for (int j = 0; j < b; ++j)
    {
      const std::complex<double> north = spectra[size_t(j) * width + m];
      const std::complex<double> south = spectra[size_t(n - 1 - j) * width + m];
      const std::complex<double> even = this->Weights[j] * shift * (north + south);
      const std::complex<double> odd = this->Weights[j] * shift * (north - south);
      evenRe[j] = even.real();
      evenIm[j] = even.imag();
      oddRe[j] = odd.real();
      oddIm[j] = odd.imag();
    }
    const double sign = (m % 2 == 0) ? 1.0 : -1.0;
    detail::NormalizedLegendreRecursion legendre;
    legendre.Run(m, b, this->Cosines.data(), this->Sines.data(), b, [&](int l, const double* p) {
      const bool even = ((l - m) % 2 == 0);
      const double* re = even ? evenRe.data() : oddRe.data();
      const double* im = even ? evenIm.data() : oddIm.data();
      double sumRe = 0.0, sumIm = 0.0;
      for (int j = 0; j < b; ++j)
      {
        sumRe += p[j] * re[j];
        sumIm += p[j] * im[j];
      }
      const std::complex<double> value(sumRe, sumIm);
      coefficients(l, m) = value;
      if (m > 0)
      {
        coefficients(l, -m) = sign * std::conj(value);
      }
    });
  });
}

void SphericalHarmonicTransform::Inverse(
  const SphericalHarmonicCoefficients& coefficients, double* grid) const
{
  const int b = this->Bandwidth;
  const int n = 2 * b;
  const int width = b + 1;
  const int bands = std::min(b, coefficients.Bandwidth);
  std::vector<std::complex<double>> spectra(static_cast<size_t>(n) * width, { 0.0, 0.0 });

  ParallelFor(bands, this->NumberOfThreads, [&](int m, int) {
    // Re sum_m g(m) e^{i m phi} = Re g(0) + sum_{m>0} Re(h(m) e^{i m phi}) with
    // h(m) = g(m) + conj(g(-m)) = sum_l (f_lm + (-1)^m conj(f_l,-m)) Pbar_l^m, which is exact
    // for any input and equals 2 g(m) for a real function's coefficients.
    const double sign = (m % 2 == 0) ? 1.0 : -1.0;
    std::vector<double> evenRe(b, 0.0), evenIm(b, 0.0), oddRe(b, 0.0), oddIm(b, 0.0);
    detail::NormalizedLegendreRecursion legendre;
    legendre.Run(m, bands, this->Cosines.data(), this->Sines.data(), b, [&](int l, const double* p) {
      std::complex<double> h = coefficients(l, m);
      if (m > 0)
      {
        h += sign * std::conj(coefficients(l, -m));
      }
      else
      {
        h = h.real();
      }
      const bool even = ((l - m) % 2 == 0);
      double* re = even ? evenRe.data() : oddRe.data();
      double* im = even ? evenIm.data() : oddIm.data();
      const double hr = h.real(), hi = h.imag();
      for (int j = 0; j < b; ++j)
      {
        re[j] += p[j] * hr;
        im[j] += p[j] * hi;
      }
    });
    // c2r computes in[0] + 2 Re sum_{0<m<N/2} in[m] e^{2 pi i m i'/N}; the factor e^{i m pi/N}
    // moves the synthesis to the cell centers phi_i = 2 pi (i + 1/2)/N.
    const std::complex<double> shift = std::polar(m == 0 ? 1.0 : 0.5, M_PI * m / n);
    for (int j = 0; j < b; ++j)
    {
      const std::complex<double> even(evenRe[j], evenIm[j]);
      const std::complex<double> odd(oddRe[j], oddIm[j]);
      spectra[size_t(j) * width + m] = shift * (even + odd);
      spectra[size_t(n - 1 - j) * width + m] = shift * (even - odd);
    }
  });

  const int rowsPerTask = 16;
  ParallelFor((n + rowsPerTask - 1) / rowsPerTask, this->NumberOfThreads, [&](int task, int) {
    for (int j = task * rowsPerTask; j < std::min(n, (task + 1) * rowsPerTask); ++j)
    {
      fftw_execute_dft_c2r(this->Plans->ComplexToReal,
        reinterpret_cast<fftw_complex*>(spectra.data() + size_t(j) * width), grid + size_t(j) * n);
    }
  });
}
}
