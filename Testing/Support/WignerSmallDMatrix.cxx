#include "WignerSmallDMatrix.h"

#include "WignerD.h"

#include <cmath>
#include <vector>

namespace mobius
{
Eigen::MatrixXd WignerSmallDMatrix(int l, double beta)
{
  std::vector<double> quadrant(static_cast<std::size_t>(l + 1) * (l + 1));
  ComputeWignerDeltaQuadrant(l, quadrant.data());
  const int size = 2 * l + 1;
  Eigen::MatrixXd delta(size, size);
  for (int k = -l; k <= l; ++k)
  {
    for (int m = -l; m <= l; ++m)
    {
      delta(k + l, m + l) = WignerDeltaFromQuadrant(quadrant.data(), l, k, m);
    }
  }
  // d_mn = i^(m-n) Σ_k Δ_km Δ_kn e^{-ikβ}. The result is real: pairing k with -k gives
  // Δ_km Δ_kn (e^{-ikβ} + (-1)^(m+n) e^{ikβ}), i.e. 2cos(kβ) or -2i sin(kβ).
  Eigen::MatrixXd d(size, size);
  for (int m = -l; m <= l; ++m)
  {
    for (int n = -l; n <= l; ++n)
    {
      double sum = delta(l, m + l) * delta(l, n + l); // k = 0
      const bool even = ((m + n) & 1) == 0;
      for (int k = 1; k <= l; ++k)
      {
        const double product = delta(k + l, m + l) * delta(k + l, n + l);
        sum += product * (even ? 2.0 * std::cos(k * beta) : 2.0 * std::sin(k * beta));
      }
      // even: i^(m-n) real = (-1)^((m-n)/2); odd: i^(m-n) (-i) = i^(m-n-1), (m-n-1) even.
      const int power = even ? (m - n) : (m - n - 1);
      const int quarter = ((power / 2) % 2 + 2) % 2;
      d(m + l, n + l) = (quarter ? -1.0 : 1.0) * sum;
    }
  }
  return d;
}
}
