// Math functions that give the same double on every x86-64 CPU. The C library picks its
// math routines by the CPU when a program starts (glibc: FMA and AVX2 versions of exp, log,
// sin, atan2, ... where the CPU has those instructions). Each is within an ulp of the exact
// value, but not always the same ulp, and a stage that iterates on such a value can turn one
// ulp into a visibly different result: the geometric polish, which matches the Gaussian
// curvature (angle defects, atan2), moved mapped points by up to 0.1 sqrt(area) between two
// dispatches of the same machine (docs/accuracy.md, "Reproducibility across CPUs"). These
// functions use only +, -, *, / and sqrt, which IEEE 754 rounds exactly, so every CPU
// computes the same bits. (The build targets baseline x86-64, which has no fused
// multiply-add instruction for the compiler to contract a product and a sum into.)
#ifndef mobius_PortableMath_h
#define mobius_PortableMath_h

namespace mobius
{
/// atan2(y, x): the angle of the point (x, y), in [-pi, pi], within 8e-16 and 6 units in the
/// last place of the exact value (std::atan2's: within one unit), the same bits on every CPU.
/// Zeros, infinities and NaN give std::atan2's exact results.
double PortableAtan2(double y, double x);

/// sin(angle) and cos(angle) for |angle| <= 1e6 (outside, or for NaN, std::sin's and
/// std::cos's), within 2e-16 of the exact values for angles of a few turns, the same bits on
/// every CPU.
void PortableSinCos(double angle, double& sine, double& cosine);
}

#endif
