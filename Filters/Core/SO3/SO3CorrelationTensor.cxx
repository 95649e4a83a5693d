#include "SO3CorrelationTensor.h"

#include "FFTWPlannerMutex.h"
#include "ParallelFor.h"
#include "WignerD.h"

#include <fftw3.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <new>
#include <mutex>
#include <stdexcept>

namespace mobius
{
namespace
{
// i^p for integer p.
inline std::complex<double> PowerOfI(int p)
{
  switch (((p % 4) + 4) % 4)
  {
    case 0:
      return { 1, 0 };
    case 1:
      return { 0, 1 };
    case 2:
      return { -1, 0 };
    default:
      return { 0, -1 };
  }
}

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic>;
}

SO3CorrelationTensor::SO3CorrelationTensor(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, int bandwidth, bool reflectSource,
  int numberOfThreads)
{
  if (bandwidth < 2 || bandwidth > source.Bandwidth || bandwidth > target.Bandwidth)
  {
    throw std::invalid_argument("SO3CorrelationTensor: bandwidth must be in [2, input bandwidth]");
  }
  const int B = bandwidth;
  this->Bandwidth = B;
  this->RowLength = 2 * B - 1;
  this->NumberOfThreads = ResolveThreadCount(numberOfThreads);
  this->ReflectSource = reflectSource;
  this->Data.reset(static_cast<std::complex<double>*>(std::malloc(
    sizeof(std::complex<double>) * static_cast<std::size_t>(B + 1) * B * this->RowLength)));
  if (!this->Data)
  {
    throw std::bad_alloc();
  }

  // Δ^l quadrants (0 <= k, m <= l) for every band, each computed independently.
  std::vector<std::size_t> offset(B + 1, 0);
  for (int l = 0; l < B; ++l)
  {
    offset[l + 1] = offset[l] + static_cast<std::size_t>(l + 1) * (l + 1);
  }
  std::vector<double> delta(offset[B]);
  ParallelFor(B, this->NumberOfThreads,
    [&](int l, int) { ComputeWignerDeltaQuadrant(l, delta.data() + offset[l]); });

  // For each k, with U[m,l] = conj(g_lm) Δ^l_km and V[n,l] = f_ln Δ^l_kn (m, n >= 0):
  //   Σ_l U V^T            gives T_{m,k,n}  = i^(m-n) (...)
  //   Σ_l (-1)^l U conj(V)^T gives T_{m,k,-n} = i^(m+n) (-1)^(n+k) (...)
  // Rows interleave real and imaginary parts (row 2m = Re, 2m+1 = Im), so one real GEMM gives
  // all four products Re·Re, Re·Im, Im·Re, Im·Im; even and odd l are accumulated apart
  // because they enter the second sum with opposite signs.
  const int threads = this->NumberOfThreads;
  struct Scratch
  {
    std::array<RowMatrix, 2> U, V, P;
  };
  std::vector<Scratch> scratch(threads);
  const double oddSign = reflectSource ? -1.0 : 1.0; // f(-x): band l times (-1)^l
  const int blockColumns = 24;

  ParallelFor(B, threads, [&](int k, int thread) {
    Scratch& s = scratch[thread];
    for (int parity = 0; parity < 2; ++parity)
    {
      int first = k + ((k + parity) & 1); // smallest l >= k with l % 2 == parity
      const int columns = first < B ? (B - 1 - first) / 2 + 1 : 0;
      RowMatrix& U = s.U[parity];
      RowMatrix& V = s.V[parity];
      RowMatrix& P = s.P[parity];
      U.setZero(2 * B, std::max(columns, 1));
      V.setZero(2 * B, std::max(columns, 1));
      P.setZero(2 * B, 2 * B);
      for (int c = 0; c < columns; ++c)
      {
        const int l = first + 2 * c;
        const double* q = delta.data() + offset[l] + static_cast<std::size_t>(k) * (l + 1);
        for (int m = 0; m <= l; ++m)
        {
          const std::complex<double> u = std::conj(target(l, m)) * q[m];
          const std::complex<double> v = source(l, m) * q[m];
          U(2 * m, c) = u.real();
          U(2 * m + 1, c) = u.imag();
          V(2 * m, c) = v.real();
          V(2 * m + 1, c) = v.imag();
        }
      }
      // Triangular structure: a block of columns with largest degree L touches rows <= L.
      for (int c0 = 0; c0 < columns; c0 += blockColumns)
      {
        const int width = std::min(blockColumns, columns - c0);
        const int rows = 2 * (first + 2 * (c0 + width - 1) + 1);
        P.topLeftCorner(rows, rows).noalias() +=
          U.block(0, c0, rows, width) * V.block(0, c0, rows, width).transpose();
      }
    }
    const RowMatrix& even = s.P[0];
    const RowMatrix& odd = s.P[1];
    for (int m = 0; m < B; ++m)
    {
      for (int n = 0; n < B; ++n)
      {
        auto part = [&](int a, int b) {
          return even(2 * m + a, 2 * n + b) + oddSign * odd(2 * m + a, 2 * n + b);
        };
        auto alternating = [&](int a, int b) {
          return even(2 * m + a, 2 * n + b) - oddSign * odd(2 * m + a, 2 * n + b);
        };
        // U V^T = (RR - II) + i (RI + IR);  U conj(V)^T = (RR + II) + i (IR - RI).
        const std::complex<double> plus(part(0, 0) - part(1, 1), part(0, 1) + part(1, 0));
        this->At(k, m, n) = PowerOfI(m - n) * plus;
        if (n > 0)
        {
          const std::complex<double> minus(
            alternating(0, 0) + alternating(1, 1), alternating(1, 0) - alternating(0, 1));
          const double sign = ((n + k) & 1) ? -1.0 : 1.0;
          this->At(k, m, -n) = PowerOfI(m + n) * sign * minus;
        }
      }
    }
  });
}

SO3CorrelationTensor::~SO3CorrelationTensor() = default;

void SO3CorrelationTensor::FreeDeleter::operator()(void* p) const
{
  std::free(p);
}

void SO3CorrelationTensor::TransformToBetaSamples()
{
  if (!this->BetaSamples)
  {
    this->TransformLines(true);
    this->BetaSamples = true;
  }
}

void SO3CorrelationTensor::TransformToFourier()
{
  if (this->BetaSamples)
  {
    this->TransformLines(false);
    this->BetaSamples = false;
  }
}

// Along k, T_{m,-k,n} = (-1)^(m+n) T_mkn, so S(β) = Σ_k T_k e^{-ikβ} is
//   m+n even: T_0 + 2 Σ_{k>0} T_k cos(kβ)   = REDFT00 (DCT-I, n = B+1) at β_j = πj/B,
//   m+n odd:  -2i Σ_{k>0} T_k sin(kβ)        = -i RODFT00 (DST-I, n = B-1) at j = 1..B-1,
// applied to real and imaginary parts. Both transforms are their own inverse up to 2B.
void SO3CorrelationTensor::TransformLines(bool toBetaSamples)
{
  const int B = this->Bandwidth;
  // One task = one whole m row (all n): per k that is one contiguous run of 16 (2B-1) bytes,
  // so the strided walk along k touches each page once instead of thrashing the TLB.
  const int block = this->RowLength;
  fftw_plan cosine;
  fftw_plan sine;
  {
    std::lock_guard<std::mutex> lock(FFTWPlannerMutex());
    double* in = fftw_alloc_real(B + 1);
    double* out = fftw_alloc_real(B + 1);
    cosine = fftw_plan_r2r_1d(B + 1, in, out, FFTW_REDFT00, FFTW_ESTIMATE | FFTW_UNALIGNED);
    sine = B > 2 ? fftw_plan_r2r_1d(B - 1, in, out, FFTW_RODFT00, FFTW_ESTIMATE | FFTW_UNALIGNED)
                 : nullptr;
    fftw_free(in);
    fftw_free(out);
  }
  const int blocksPerRow = (this->RowLength + block - 1) / block;
  const double scale = toBetaSamples ? 1.0 : 1.0 / (2.0 * B);
  std::vector<std::vector<double>> buffers(
    this->NumberOfThreads, std::vector<double>(static_cast<std::size_t>(4) * block * (B + 1)));

  ParallelFor(B * blocksPerRow, this->NumberOfThreads, [&](int task, int thread) {
    const int m = task / blocksPerRow;
    const int n0 = -(B - 1) + (task % blocksPerRow) * block;
    const int n1 = std::min(n0 + block, B);
    double* buffer = buffers[thread].data();
    const int stride = B + 1;
    // Gather: rows 2i (real) and 2i+1 (imaginary) hold line n0 + i.
    for (int n = n0; n < n1; ++n)
    {
      const bool even = ((m + n) & 1) == 0;
      double* re = buffer + static_cast<std::size_t>(2 * (n - n0)) * stride;
      double* im = re + stride;
      for (int k = 0; k <= B; ++k)
      {
        const bool stored = toBetaSamples ? k < B : true;
        const std::complex<double> value = stored ? this->At(k, m, n) : 0.0;
        if (even || toBetaSamples)
        {
          re[k] = value.real();
          im[k] = value.imag();
        }
        else
        {
          // Inverse of S = -i Y: Y = i S.
          re[k] = -value.imag();
          im[k] = value.real();
        }
      }
    }
    double* out = buffer + static_cast<std::size_t>(2 * block) * stride;
    for (int n = n0; n < n1; ++n)
    {
      const bool even = ((m + n) & 1) == 0;
      double* re = buffer + static_cast<std::size_t>(2 * (n - n0)) * stride;
      double* im = re + stride;
      double* outRe = out;
      double* outIm = out + stride;
      if (even)
      {
        fftw_execute_r2r(cosine, re, outRe);
        fftw_execute_r2r(cosine, im, outIm);
        const int count = toBetaSamples ? B + 1 : B;
        for (int k = 0; k < count; ++k)
        {
          this->At(k, m, n) = std::complex<double>(outRe[k], outIm[k]) * scale;
        }
      }
      else
      {
        // Forward input T_1..T_{B-1} sits at index 1; inverse input Y_1..Y_{B-1} likewise.
        std::fill(outRe, outRe + stride, 0.0);
        std::fill(outIm, outIm + stride, 0.0);
        if (sine)
        {
          fftw_execute_r2r(sine, re + 1, outRe + 1);
          fftw_execute_r2r(sine, im + 1, outIm + 1);
        }
        if (toBetaSamples)
        {
          for (int j = 0; j <= B; ++j)
          {
            // S = -i Y.
            this->At(j, m, n) = std::complex<double>(outIm[j], -outRe[j]);
          }
        }
        else
        {
          for (int k = 0; k < B; ++k)
          {
            this->At(k, m, n) = std::complex<double>(outRe[k], outIm[k]) * scale;
          }
          this->At(B, m, n) = 0.0;
        }
      }
      if (even && !toBetaSamples)
      {
        this->At(B, m, n) = 0.0;
      }
    }
  });
  {
    std::lock_guard<std::mutex> lock(FFTWPlannerMutex());
    fftw_destroy_plan(cosine);
    if (sine)
    {
      fftw_destroy_plan(sine);
    }
  }
}

struct SO3CorrelationTensor::SliceWorkspace::Buffers
{
  int Resolution;
  fftw_complex* Spectrum;
  double* Values;
  fftw_plan Plan;
};

SO3CorrelationTensor::SliceWorkspace::SliceWorkspace(int resolution)
  : Data(new Buffers)
{
  const int M = resolution;
  std::lock_guard<std::mutex> lock(FFTWPlannerMutex());
  this->Data->Resolution = M;
  this->Data->Spectrum = fftw_alloc_complex(static_cast<std::size_t>(M) * (M / 2 + 1));
  this->Data->Values = fftw_alloc_real(static_cast<std::size_t>(M) * M);
  this->Data->Plan =
    fftw_plan_dft_c2r_2d(M, M, this->Data->Spectrum, this->Data->Values, FFTW_ESTIMATE);
}

SO3CorrelationTensor::SliceWorkspace::~SliceWorkspace()
{
  {
    std::lock_guard<std::mutex> lock(FFTWPlannerMutex());
    fftw_destroy_plan(this->Data->Plan);
    fftw_free(this->Data->Spectrum);
    fftw_free(this->Data->Values);
  }
  delete this->Data;
}

std::unique_ptr<SO3CorrelationTensor::SliceWorkspace> SO3CorrelationTensor::NewSliceWorkspace()
  const
{
  return std::make_unique<SliceWorkspace>(this->GetGridResolution());
}

void SO3CorrelationTensor::SynthesizeSlice(int j, SliceWorkspace& workspace, double* slice) const
{
  if (!this->BetaSamples)
  {
    throw std::logic_error("SO3CorrelationTensor::SynthesizeSlice needs beta samples");
  }
  const int B = this->Bandwidth;
  SliceWorkspace::Buffers& buffers = *workspace.Data;
  const int M = buffers.Resolution;
  const int half = M / 2 + 1;
  // c2r computes out[p'][q'] = Σ in[p][q] e^{+2πi(p p' + q q')/M}; C = conj(C) =
  // Σ conj(S_mn) e^{+i(mα + nγ)}, so in[n mod M][m] = conj(S_mn), q' indexes α, p' indexes γ.
  // Hermitian completion over m < 0 is exactly S_{-m,-n} = conj(S_mn).
  std::fill(reinterpret_cast<double*>(buffers.Spectrum),
    reinterpret_cast<double*>(buffers.Spectrum) + 2 * static_cast<std::size_t>(M) * half, 0.0);
  for (int m = 0; m < B; ++m)
  {
    for (int n = -(B - 1); n < B; ++n)
    {
      const std::complex<double> value = this->At(j, m, n);
      fftw_complex& target = buffers.Spectrum[static_cast<std::size_t>((n + M) % M) * half + m];
      target[0] = value.real();
      target[1] = -value.imag();
    }
  }
  fftw_execute_dft_c2r(buffers.Plan, buffers.Spectrum, buffers.Values);
  std::copy(buffers.Values, buffers.Values + static_cast<std::size_t>(M) * M, slice);
}

double SO3CorrelationTensor::Evaluate(const Eigen::Vector3d& euler, Eigen::Vector3d* gradient,
  Eigen::Matrix3d* hessian, int numberOfThreads) const
{
  if (this->BetaSamples)
  {
    throw std::logic_error("SO3CorrelationTensor::Evaluate needs the Fourier form");
  }
  const int B = this->Bandwidth;
  const bool derivatives = gradient || hessian;
  const double alpha = euler[0];
  const double beta = euler[1];
  const double gamma = euler[2];
  // e^{-inγ} (-in)^p, p = 0, 1, 2.
  std::vector<std::complex<double>> phase0(this->RowLength), phase1(this->RowLength),
    phase2(this->RowLength);
  for (int n = -(B - 1); n < B; ++n)
  {
    const std::complex<double> e = std::polar(1.0, -n * gamma);
    phase0[n + B - 1] = e;
    phase1[n + B - 1] = std::complex<double>(0, -n) * e;
    phase2[n + B - 1] = -double(n) * n * e;
  }
  // C = Re Σ_{m>=0,k>=0} w_m e^{-imα} [c_k(β) E_km + s_k(β) O_km], w_0 = 1, w_m = 2,
  // c_0 = 1, c_k = 2cos(kβ), s_0 = 0, s_k = -2i sin(kβ); E (O) sums over n with m+n even (odd).
  // Derivatives: ∂α -> -im, ∂γ -> -in, ∂β acts on c_k, s_k.
  const int threads =
    std::min(numberOfThreads > 0 ? numberOfThreads : this->NumberOfThreads, B);
  // A fixed number of chunks, each summed on its own and added up in order: the result is the
  // same whichever thread ran which chunk.
  const int chunks = std::min(B, 8);
  std::vector<std::array<double, 10>> partial(chunks, std::array<double, 10>{});
  ParallelFor(chunks, threads, [&](int chunk, int) {
    std::array<double, 10>& sum = partial[chunk];
    for (int k = chunk; k < B; k += chunks)
    {
      const double ck = k == 0 ? 1.0 : 2.0 * std::cos(k * beta);
      const double sk = k == 0 ? 0.0 : -2.0 * std::sin(k * beta); // times i
      const double dck = -2.0 * k * std::sin(k * beta);
      const double dsk = -2.0 * k * std::cos(k * beta);          // times i
      const double ddck = -2.0 * k * k * std::cos(k * beta);
      const double ddsk = 2.0 * k * k * std::sin(k * beta);       // times i
      const std::complex<double> I(0, 1);
      for (int m = 0; m < B; ++m)
      {
        const std::complex<double>* row = &this->At(k, m, -(B - 1));
        std::complex<double> e[3], o[3];
        // n with m+n even start at index (B-1+m) & 1; the others at the next index.
        const int evenStart = (B - 1 + m) & 1;
        for (int parity = 0; parity < 2; ++parity)
        {
          std::complex<double>* target = parity == 0 ? e : o;
          const int start = parity == 0 ? evenStart : 1 - evenStart;
          // Plain real arithmetic: std::complex products carry NaN checks that stop vectorizing.
          double r0 = 0, i0 = 0, r1 = 0, i1 = 0, r2 = 0, i2 = 0;
          for (int n = start; n < this->RowLength; n += 2)
          {
            const double tr = row[n].real();
            const double ti = row[n].imag();
            r0 += tr * phase0[n].real() - ti * phase0[n].imag();
            i0 += tr * phase0[n].imag() + ti * phase0[n].real();
            if (derivatives)
            {
              r1 += tr * phase1[n].real() - ti * phase1[n].imag();
              i1 += tr * phase1[n].imag() + ti * phase1[n].real();
              r2 += tr * phase2[n].real() - ti * phase2[n].imag();
              i2 += tr * phase2[n].imag() + ti * phase2[n].real();
            }
          }
          target[0] = { r0, i0 };
          target[1] = { r1, i1 };
          target[2] = { r2, i2 };
        }
        const double w = m == 0 ? 1.0 : 2.0;
        const std::complex<double> em = w * std::polar(1.0, -m * alpha);
        const std::complex<double> minusIm(0, -m);
        const std::complex<double> value = em * (ck * e[0] + I * sk * o[0]);
        sum[0] += value.real();
        if (!derivatives)
        {
          continue;
        }
        const std::complex<double> dBeta = em * (dck * e[0] + I * dsk * o[0]);
        const std::complex<double> dGamma = em * (ck * e[1] + I * sk * o[1]);
        sum[1] += (minusIm * value).real();
        sum[2] += dBeta.real();
        sum[3] += dGamma.real();
        sum[4] += (minusIm * minusIm * value).real();                  // αα
        sum[5] += (minusIm * dBeta).real();                            // αβ
        sum[6] += (minusIm * dGamma).real();                           // αγ
        sum[7] += (em * (ddck * e[0] + I * ddsk * o[0])).real();       // ββ
        sum[8] += (em * (dck * e[1] + I * dsk * o[1])).real();         // βγ
        sum[9] += (em * (ck * e[2] + I * sk * o[2])).real();           // γγ
      }
    }
  });
  std::array<double, 10> total{};
  for (const auto& p : partial)
  {
    for (int i = 0; i < 10; ++i)
    {
      total[i] += p[i];
    }
  }
  if (gradient)
  {
    *gradient = Eigen::Vector3d(total[1], total[2], total[3]);
  }
  if (hessian)
  {
    *hessian << total[4], total[5], total[6], total[5], total[7], total[8], total[6], total[8],
      total[9];
  }
  return total[0];
}
}
