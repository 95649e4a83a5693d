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

namespace mobius
{
/// Δ^l_km = d^l_km(π/2) for 0 <= k, m <= l, written row-major into `quadrant`
/// ((l+1) x (l+1), quadrant[k * (l+1) + m]). Computed by the three-term recursion in m at
/// β = π/2, run from the edge m = l (closed form) down to m = 0, the direction in which the
/// wanted solution grows, so the recursion is stable; negative indices follow by symmetry.
/// Valid for l up to about 1000 (the edge value 2^-l must not underflow).
void ComputeWignerDeltaQuadrant(int l, double* quadrant);

/// Δ^l_km for any -l <= k, m <= l from a quadrant filled by ComputeWignerDeltaQuadrant.
double WignerDeltaFromQuadrant(const double* quadrant, int l, int k, int m);

/// The full matrix d^l(β), (2l+1) x (2l+1), entry (m+l, n+l), via the Δ factorization
/// (O(l^3); used for tests and small rotations).
Eigen::MatrixXd WignerSmallDMatrix(int l, double beta);

/// d^l_mn(β) for l = 0 .. lMax into values[l] (zero for l < max(|m|, |n|)), by the
/// three-term recursion in l for fixed (m, n) from the closed form at l = max(|m|, |n|).
/// Runs in long double so that starting values that would underflow a double survive.
void WignerSmallDSequence(int m, int n, int lMax, double beta, double* values);
}

#endif
