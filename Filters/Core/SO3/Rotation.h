// Rotations of R^3 and of spherical functions given by their harmonic coefficients.
//
// Conventions (docs/architecture.md; checked in TestSO3Correlation by applying matrices to points):
// a rotation acts on column vectors, x' = R x; ZYZ Euler angles mean
// R = Rz(α) Ry(β) Rz(γ) with Rz, Ry the right-handed rotations about +z, +y. Rotating a
// function by R means f ↦ f∘R⁻¹, so the rotated function at R x equals f at x. A matrix with
// det = -1 is read as R = Q · (-I) with Q a rotation (antipodal map, then rotation).
#ifndef mobius_Rotation_h
#define mobius_Rotation_h

#include "SphericalHarmonics.h"

#include <Eigen/Core>

#include <array>

namespace mobius
{
Eigen::Matrix3d RotationAboutZ(double angle);
Eigen::Matrix3d RotationAboutY(double angle);

/// R = Rz(alpha) Ry(beta) Rz(gamma).
Eigen::Matrix3d EulerZYZToMatrix(double alpha, double beta, double gamma);

/// (alpha, beta, gamma) with beta in [0, π] and alpha, gamma in [0, 2π); at beta = 0 or π only
/// alpha ± gamma is defined and gamma is set to 0. `rotation` must be a rotation (det +1).
Eigen::Vector3d MatrixToEulerZYZ(const Eigen::Matrix3d& rotation);

/// Geodesic distance on O(3) between two orthogonal matrices of equal determinant: the angle
/// of the rotation a bᵀ, in [0, π].
double RotationAngleBetween(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b);

/// Row-major copy (the storage convention of the VTK layer).
std::array<double, 9> ToRowMajor(const Eigen::Matrix3d& matrix);

/// f(x) -> f(-x): multiplies band l by (-1)^l.
void ReflectCoefficients(SphericalHarmonicCoefficients& coefficients);

/// output = coefficients of x -> f(T⁻¹ x) for an orthogonal T (det ±1), computed band by band
/// with Wigner D matrices in O(B^3). `output` may not alias `input`.
void RotateCoefficients(const SphericalHarmonicCoefficients& input, const Eigen::Matrix3d& transform,
  SphericalHarmonicCoefficients& output);
}

#endif
