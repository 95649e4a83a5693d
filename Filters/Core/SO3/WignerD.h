// Wigner small-d functions for the complex, orthonormal, Condon-Shortley spherical harmonics
// of SphericalHarmonics.h.
//
// Convention (verified numerically in TestWignerD and TestSO3Correlation): rotating a
// function, (Λ(R) f)(x) = f(R⁻¹ x), acts on its coefficients band by band as
//     (Λ(R) f)_lm = Σ_n D^l_mn(R) f_ln,
//     D^l_mn(Rz(α) Ry(β) Rz(γ)) = e^{-imα} d^l_mn(β) e^{-inγ},
// with d^l_mn(β) real and given by Wigner's sum formula
//     d^l_mn(β) = Σ_s (-1)^(m-n+s) sqrt((l+m)!(l-m)!(l+n)!(l-n)!)
//                 / ((l+n-s)! s! (m-n+s)! (l-m-s)!) cos(β/2)^(2l+n-m-2s) sin(β/2)^(m-n+2s).
// Symmetries used throughout: d_mn = (-1)^(m-n) d_nm = d_{-n,-m}; and for Δ^l = d^l(π/2):
//     Δ_{k,-m} = (-1)^(l+k) Δ_km,  Δ_{-k,m} = (-1)^(l+m) Δ_km,
// and the factorization through a rotation taking z to y:
//     d^l_mn(β) = i^(m-n) Σ_k Δ^l_km Δ^l_kn e^{-ikβ}.
#ifndef mobius_WignerD_h
#define mobius_WignerD_h

#include <Eigen/Core>

#include <cmath>
#include <utility>
#include <vector>

namespace mobius
{
/// Generates the columns of the Δ^l quadrant, m = l, l-1, ..., 0 in that order, and calls
/// visit(m, column) with column[k] = Δ^l_km for 0 <= k <= l (valid only during the call).
/// The three-term recursion in m at β = π/2,
///     2k Δ_{k,m} = -[sqrt((l+m)(l-m+1)) Δ_{k,m-1} + sqrt((l-m)(l+m+1)) Δ_{k,m+1}],
/// is run from the closed-form edge Δ_{k,l} = 2^-l sqrt(binomial(2l, l+k)) down to m = 0, the
/// direction in which the wanted solution grows, so it is stable. All k advance together
/// (the inner loop is over k and vectorizes); the square roots depend on (l, m) only and are
/// taken once per column. `workspace` is resized as needed and may be reused across calls.
/// Valid for l up to about 1000 (the edge value 2^-l must not underflow).
template <typename Visit>
void VisitWignerDeltaColumns(int l, std::vector<double>& workspace, Visit&& visit)
{
  const int size = l + 1;
  workspace.resize(3 * static_cast<std::size_t>(size));
  double* current = workspace.data();
  double* above = current + size; // Δ_{k,m+1}, then reused for Δ_{k,m-1}
  double* twiceK = above + size;
  // Edge column: Δ_{0,l}^2 = Π_{i=1..l} (2i-1)/(2i) (= binomial(2l,l)/4^l, no overflow), then
  // Δ_{k+1,l} = Δ_{k,l} sqrt((l-k)/(l+k+1)).
  double edge = 1.0;
  for (int i = 1; i <= l; ++i)
  {
    edge *= (2.0 * i - 1.0) / (2.0 * i);
  }
  edge = std::sqrt(edge);
  for (int k = 0; k <= l; ++k)
  {
    current[k] = edge;
    above[k] = 0.0;
    twiceK[k] = 2.0 * k;
    if (k < l)
    {
      edge *= std::sqrt(double(l - k) / double(l + k + 1));
    }
  }
  visit(l, static_cast<const double*>(current));
  for (int m = l; m >= 1; --m)
  {
    const double inverse = 1.0 / std::sqrt(double(l + m) * (l - m + 1));
    const double ratio = std::sqrt(double(l - m) * (l + m + 1)) * inverse;
    for (int k = 0; k <= l; ++k)
    {
      above[k] = -(twiceK[k] * inverse * current[k] + ratio * above[k]);
    }
    std::swap(current, above);
    visit(m - 1, static_cast<const double*>(current));
  }
}

/// Δ^l_km = d^l_km(π/2) for 0 <= k, m <= l, written row-major into `quadrant`
/// ((l+1) x (l+1), quadrant[k * (l+1) + m]), by VisitWignerDeltaColumns; negative indices
/// follow by symmetry (WignerDeltaFromQuadrant).
void ComputeWignerDeltaQuadrant(int l, double* quadrant);

/// Δ^l_km for any -l <= k, m <= l from a quadrant filled by ComputeWignerDeltaQuadrant.
double WignerDeltaFromQuadrant(const double* quadrant, int l, int k, int m);

/// d^l_mn(β) for l = 0 .. lMax into values[l] (zero for l < max(|m|, |n|)), by the
/// three-term recursion in l for fixed (m, n) from the closed form at l = max(|m|, |n|).
/// Runs in long double so that starting values that would underflow a double survive.
void WignerSmallDSequence(int m, int n, int lMax, double beta, double* values);
}

#endif
