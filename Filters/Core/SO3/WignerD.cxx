#include "WignerD.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <vector>

namespace mobius
{
namespace
{
inline double Sign(int parity)
{
  return (parity & 1) ? -1.0 : 1.0;
}
}

void ComputeWignerDeltaQuadrant(int l, double* quadrant)
{
  // The recursion yields columns (fixed m, all k); Δ_km = (-1)^(k-m) Δ_mk turns them into
  // rows, so every write is contiguous: quadrant[m * (l+1) + k] = Δ_mk = (-1)^(k+m) Δ_km.
  const int size = l + 1;
  std::vector<double> workspace;
  VisitWignerDeltaColumns(l, workspace, [&](int m, const double* column) {
    double* row = quadrant + static_cast<std::size_t>(m) * size;
    const double sign = Sign(m);
    for (int k = 0; k < size; k += 2)
    {
      row[k] = sign * column[k];
    }
    for (int k = 1; k < size; k += 2)
    {
      row[k] = -sign * column[k];
    }
  });
}

double WignerDeltaFromQuadrant(const double* quadrant, int l, int k, int m)
{
  double sign = 1.0;
  if (k < 0)
  {
    sign *= Sign(l + m);
    k = -k;
  }
  if (m < 0)
  {
    sign *= Sign(l + k);
    m = -m;
  }
  return sign * quadrant[static_cast<std::size_t>(k) * (l + 1) + m];
}

void WignerSmallDSequence(int m, int n, int lMax, double beta, double* values)
{
  const int l0 = std::max(std::abs(m), std::abs(n));
  for (int l = 0; l <= lMax && l < l0; ++l)
  {
    values[l] = 0.0;
  }
  if (l0 > lMax)
  {
    return;
  }
  // Closed form at l0 = max(|m|,|n|) (from Wigner's formula):
  //   d^j_{j,n}  = (-1)^(j-n) sqrt(C(2j, j+n)) c^(j+n) s^(j-n)
  //   d^j_{-j,n} =            sqrt(C(2j, j+n)) c^(j-n) s^(j+n)
  //   d^j_{m,j}  =            sqrt(C(2j, j+m)) c^(j+m) s^(j-m)
  //   d^j_{m,-j} = (-1)^(j+m) sqrt(C(2j, j+m)) c^(j-m) s^(j+m)
  // with c = cos(β/2), s = sin(β/2); evaluated in logs (long double) to avoid overflow.
  const long double c = std::cos(static_cast<long double>(beta) / 2);
  const long double s = std::sin(static_cast<long double>(beta) / 2);
  const int j = l0;
  int other = 0;
  int cosPower = 0;
  int sinPower = 0;
  long double sign = 1;
  if (std::abs(m) >= std::abs(n))
  {
    other = n;
    if (m == j)
    {
      cosPower = j + n;
      sinPower = j - n;
      sign = Sign(j - n);
    }
    else
    {
      cosPower = j - n;
      sinPower = j + n;
    }
  }
  else
  {
    other = m;
    if (n == j)
    {
      cosPower = j + m;
      sinPower = j - m;
    }
    else
    {
      cosPower = j - m;
      sinPower = j + m;
      sign = Sign(j + m);
    }
  }
  long double start = 0;
  const bool zero = (cosPower > 0 && c == 0) || (sinPower > 0 && s == 0);
  if (!zero)
  {
    long double logValue = 0.5L * (std::lgamma(2.0L * j + 1) - std::lgamma(1.0L * j + other + 1) -
                                   std::lgamma(1.0L * j - other + 1));
    if (cosPower > 0)
    {
      logValue += cosPower * std::log(std::fabs(c));
    }
    if (sinPower > 0)
    {
      logValue += sinPower * std::log(std::fabs(s));
    }
    start = sign * std::exp(logValue);
    if (cosPower % 2 == 1 && c < 0)
    {
      start = -start;
    }
    if (sinPower % 2 == 1 && s < 0)
    {
      start = -start;
    }
  }
  // (l+1) sqrt(((l+1)^2-m^2)((l+1)^2-n^2)) / ... three-term recursion in l:
  // d^{l+1} = (l+1)(2l+1)/sqrt(((l+1)^2-m^2)((l+1)^2-n^2)) (cosβ - mn/(l(l+1))) d^l
  //         - (l+1) sqrt((l^2-m^2)(l^2-n^2)) / (l sqrt(((l+1)^2-m^2)((l+1)^2-n^2))) d^{l-1}
  const long double cosBeta = std::cos(static_cast<long double>(beta));
  long double previous = 0;
  long double current = start;
  values[j] = static_cast<double>(current);
  const long double mm = static_cast<long double>(m) * m;
  const long double nn = static_cast<long double>(n) * n;
  for (int l = j; l < lMax; ++l)
  {
    const long double next1 = static_cast<long double>(l + 1) * (l + 1);
    const long double denominator = std::sqrt((next1 - mm) * (next1 - nn));
    long double next;
    if (l == 0)
    {
      next = cosBeta * current; // m = n = 0: Legendre P_1
    }
    else
    {
      const long double ll = static_cast<long double>(l) * l;
      next = (l + 1) * (2.0L * l + 1) / denominator *
          (cosBeta - static_cast<long double>(m) * n / (static_cast<long double>(l) * (l + 1))) *
          current -
        (l + 1) * std::sqrt((ll - mm) * (ll - nn)) / (l * denominator) * previous;
    }
    previous = current;
    current = next;
    values[l + 1] = static_cast<double>(current);
  }
}
}
