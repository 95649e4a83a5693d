// The correlation C(R) = ∫ f(R⁻¹x) g(x) dx of two real spherical functions as a 3-D Fourier
// series in the ZYZ Euler angles of R = Rz(α) Ry(β) Rz(γ):
//
//   C(α,β,γ) = Σ_l Σ_mn conj(g_lm) f_ln e^{-imα} d^l_mn(β) e^{-inγ}
//            = Σ_{m,k,n} T_mkn e^{-i(mα + kβ + nγ)},
//   T_mkn    = i^(m-n) Σ_l conj(g_lm) f_ln Δ^l_km Δ^l_kn        (d = i^(m-n) Σ_k Δ Δ e^{-ikβ}).
//
// Real f and g give T_{-m,-k,-n} = conj(T_mkn) and, through Δ_{-k,m} = (-1)^(l+m) Δ_km,
// T_{m,-k,n} = (-1)^(m+n) T_mkn, so only m >= 0, k >= 0 are stored (all n), and in the sum over l
// only n >= 0 is needed (f_{l,-n} = (-1)^n conj(f_ln)). Per k the sum over l is a product of
// two real (m x l) and (n x l) matrices, done blockwise (they are triangular) as GEMMs:
// about B^4 real multiply-adds in all, versus 8 B^4 complex ones done naively.
//
// The tensor then switches in place between two representations:
//  - Fourier: T_mkn, used to evaluate C and its derivatives at any (α,β,γ) in O(B^3);
//  - β samples: S_mn(β_j) = Σ_k T_mkn e^{-ikβ_j} at β_j = πj/B, j = 0..B (a DCT-I or DST-I of
//    each (m, n) line, since the k-sequence is even or odd), from which each slice
//    C(·, β_j, ·) on the 2B x 2B grid in (α, γ) is one 2-D real inverse FFT.
// Memory: 16 (B+1) B (2B-1) bytes (0.54 GB at B = 256, 4.3 GB at B = 512).
#ifndef mobius_SO3CorrelationTensor_h
#define mobius_SO3CorrelationTensor_h

#include "SphericalHarmonics.h"

#include <Eigen/Core>

#include <complex>
#include <memory>
#include <vector>

namespace mobius
{
class SO3CorrelationTensor
{
public:
  /// Builds T in Fourier form from the bands l < bandwidth of source f and target g (both real
  /// functions). reflectSource correlates f(-x) instead of f(x), i.e. transforms R·(-I).
  SO3CorrelationTensor(const SphericalHarmonicCoefficients& source,
    const SphericalHarmonicCoefficients& target, int bandwidth, bool reflectSource,
    int numberOfThreads);
  ~SO3CorrelationTensor();
  SO3CorrelationTensor(const SO3CorrelationTensor&) = delete;
  SO3CorrelationTensor& operator=(const SO3CorrelationTensor&) = delete;

  int GetBandwidth() const { return this->Bandwidth; }
  /// Samples per 2π in α and γ of the grid slices: 2 * bandwidth.
  int GetGridResolution() const { return 2 * this->Bandwidth; }
  bool GetReflectSource() const { return this->ReflectSource; }

  /// Switch representation (each an O(B^3 log B) pass over the tensor).
  void TransformToBetaSamples();
  void TransformToFourier();
  bool HasBetaSamples() const { return this->BetaSamples; }

  /// Per-thread workspace for SynthesizeSlice (FFTW buffers and plan).
  class SliceWorkspace
  {
  public:
    explicit SliceWorkspace(int resolution);
    ~SliceWorkspace();
    SliceWorkspace(const SliceWorkspace&) = delete;
    SliceWorkspace& operator=(const SliceWorkspace&) = delete;

  private:
    friend class SO3CorrelationTensor;
    struct Buffers;
    Buffers* Data;
  };
  std::unique_ptr<SliceWorkspace> NewSliceWorkspace() const;

  /// Requires β samples. Writes C(α_a, β_j, γ_c) to slice[c * M + a], with M = 2B,
  /// α_a = 2πa/M, γ_c = 2πc/M, β_j = πj/B, 0 <= j <= B. Thread-safe with one workspace per
  /// thread.
  void SynthesizeSlice(int j, SliceWorkspace& workspace, double* slice) const;

  /// Requires Fourier form. C at Euler angles (α,β,γ) (any real values), and optionally its
  /// gradient and Hessian with respect to (α,β,γ). O(B^3), on numberOfThreads threads (0: the
  /// tensor's own count); the result does not depend on the thread count.
  double Evaluate(const Eigen::Vector3d& euler, Eigen::Vector3d* gradient = nullptr,
    Eigen::Matrix3d* hessian = nullptr, int numberOfThreads = 0) const;

private:
  std::complex<double>& At(int k, int m, int n)
  {
    return this->Data[(static_cast<std::size_t>(k) * this->Bandwidth + m) * this->RowLength +
      (n + this->Bandwidth - 1)];
  }
  const std::complex<double>& At(int k, int m, int n) const
  {
    return this->Data[(static_cast<std::size_t>(k) * this->Bandwidth + m) * this->RowLength +
      (n + this->Bandwidth - 1)];
  }
  void TransformLines(bool toBetaSamples);

  int Bandwidth = 0;
  int RowLength = 0; // 2B - 1 values of n
  int NumberOfThreads = 1;
  bool ReflectSource = false;
  bool BetaSamples = false;
  // [k or j][m][n + B - 1], k in [0, B) (Fourier) or j in [0, B] (β samples). Allocated
  // without zero-filling: every entry is written before it is read, and a separate fill pass
  // over hundreds of MB costs more than the GEMMs at moderate B.
  struct FreeDeleter
  {
    void operator()(void* p) const;
  };
  std::unique_ptr<std::complex<double>[], FreeDeleter> Data;
};
}

#endif
