// Orthonormal associated Legendre functions by the stable three-term recursion in the degree,
// for one order m at many latitudes at once (the inner loop over latitudes vectorizes).
//
//   Pbar_l^m(x) = sqrt((2l+1)/(4 pi) (l-m)!/(l+m)!) P_l^m(x),   Y_l^m = Pbar_l^m(cos theta) e^{i m phi},
// with the Condon-Shortley phase inside P_l^m:
//   Pbar_0^0 = 1/sqrt(4 pi),  Pbar_m^m = -sqrt((2m+1)/(2m)) sin(theta) Pbar_{m-1}^{m-1},
//   Pbar_{m+1}^m = sqrt(2m+3) x Pbar_m^m,
//   Pbar_l^m = a_lm (x Pbar_{l-1}^m - b_lm Pbar_{l-2}^m),
//   a_lm = sqrt((4l^2-1)/(l^2-m^2)),  b_lm = sqrt(((l-1)^2-m^2)/(4(l-1)^2-1)).
//
// Why the scaling: the seed Pbar_m^m ~ sin^m(theta) underflows near the poles for large m
// (sin(pi/2048)^511 ~ 1e-1440 at B = 512), yet later degrees of the same order can be of
// ordinary size. Each latitude therefore carries its value as p * 2^(-512 e) with an integer
// exponent e >= 0 (an "extended exponent" number): the seed is formed from its logarithm, the
// recursion runs on p, and p is rescaled by 2^-512 whenever it grows past 2^200 while e > 0.
// Values with e > 0 are below 2^-200 in magnitude; they are reported as p 2^(-512 e), which
// is exact where representable and flushes to (sub)normal or zero otherwise.
#ifndef mobius_NormalizedLegendre_h
#define mobius_NormalizedLegendre_h

#include <cmath>
#include <vector>

namespace mobius
{
namespace detail
{
class NormalizedLegendreRecursion
{
public:
  /// Calls visit(l, values) for l = m, ..., lEnd-1 with values[k] = Pbar_l^m(cosTheta[k]) for
  /// k < count. sinTheta[k] = sin(theta_k) >= 0 must be given (accurately, not from cosTheta).
  template <class Visit>
  void Run(int m, int lEnd, const double* cosTheta, const double* sinTheta, int count, Visit&& visit)
  {
    if (m >= lEnd || count <= 0)
    {
      return;
    }
    this->Previous.assign(count, 0.0);
    this->Current.resize(count);
    this->Values.resize(count);
    this->Exponent.assign(count, 0);

    // log2 |Pbar_m^m| = log2(1/sqrt(4 pi)) + 1/2 sum_{k=1}^m log2((2k+1)/(2k)) + m log2 sin(theta)
    double log2Coefficient = -0.5 * std::log2(4.0 * M_PI);
    for (int k = 1; k <= m; ++k)
    {
      log2Coefficient += 0.5 * std::log2((2.0 * k + 1.0) / (2.0 * k));
    }
    const double sign = (m % 2 == 0) ? 1.0 : -1.0;
    int scaledEnd = 0; // every latitude with a nonzero exponent has index < scaledEnd
    for (int k = 0; k < count; ++k)
    {
      double log2Value = -HUGE_VAL;
      if (m == 0)
      {
        log2Value = log2Coefficient;
      }
      else if (sinTheta[k] > 0.0)
      {
        log2Value = log2Coefficient + m * std::log2(sinTheta[k]);
      }
      if (log2Value == -HUGE_VAL)
      {
        this->Current[k] = 0.0; // exactly at a pole: Pbar_l^m = 0 for m > 0
      }
      else if (log2Value >= -200.0)
      {
        this->Current[k] = sign * std::exp2(log2Value);
      }
      else
      {
        const int exponent = static_cast<int>(std::ceil((-200.0 - log2Value) / 512.0));
        this->Exponent[k] = exponent;
        this->Current[k] = sign * std::exp2(log2Value + 512.0 * exponent);
        scaledEnd = k + 1;
      }
    }
    this->Emit(m, count, scaledEnd, visit);

    for (int l = m + 1; l < lEnd; ++l)
    {
      const double l2 = static_cast<double>(l) * l;
      const double m2 = static_cast<double>(m) * m;
      const double a = std::sqrt((4.0 * l2 - 1.0) / (l2 - m2));
      const double lm1 = l - 1.0;
      const double b = (l == m + 1) ? 0.0 : std::sqrt((lm1 * lm1 - m2) / (4.0 * lm1 * lm1 - 1.0));
      double* previous = this->Previous.data();
      double* current = this->Current.data();
      for (int k = 0; k < count; ++k)
      {
        const double next = a * (cosTheta[k] * current[k] - b * previous[k]);
        previous[k] = current[k];
        current[k] = next;
      }
      // Rescale latitudes still carrying an exponent once their mantissa has grown.
      int newScaledEnd = 0;
      for (int k = 0; k < scaledEnd; ++k)
      {
        if (this->Exponent[k] > 0)
        {
          if (std::abs(current[k]) > 0x1p200)
          {
            current[k] *= 0x1p-512;
            previous[k] *= 0x1p-512;
            --this->Exponent[k];
          }
          if (this->Exponent[k] > 0)
          {
            newScaledEnd = k + 1;
          }
        }
      }
      scaledEnd = newScaledEnd;
      this->Emit(l, count, scaledEnd, visit);
    }
  }

private:
  template <class Visit>
  void Emit(int l, int count, int scaledEnd, Visit& visit)
  {
    if (scaledEnd == 0)
    {
      visit(l, static_cast<const double*>(this->Current.data()));
      return;
    }
    for (int k = 0; k < count; ++k)
    {
      this->Values[k] = (k < scaledEnd && this->Exponent[k] > 0)
        ? std::ldexp(this->Current[k], -512 * this->Exponent[k])
        : this->Current[k];
    }
    visit(l, static_cast<const double*>(this->Values.data()));
  }

  std::vector<double> Previous, Current, Values;
  std::vector<int> Exponent;
};
}
}

#endif
