#include "Rotation.h"

#include "WignerD.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <vector>

namespace mobius
{
namespace
{
double WrapToTwoPi(double angle)
{
  angle = std::fmod(angle, 2.0 * M_PI);
  return angle < 0 ? angle + 2.0 * M_PI : angle;
}
}

Eigen::Matrix3d RotationAboutZ(double angle)
{
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  Eigen::Matrix3d r;
  r << c, -s, 0, s, c, 0, 0, 0, 1;
  return r;
}

Eigen::Matrix3d RotationAboutY(double angle)
{
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  Eigen::Matrix3d r;
  r << c, 0, s, 0, 1, 0, -s, 0, c;
  return r;
}

Eigen::Matrix3d EulerZYZToMatrix(double alpha, double beta, double gamma)
{
  return RotationAboutZ(alpha) * RotationAboutY(beta) * RotationAboutZ(gamma);
}

Eigen::Vector3d MatrixToEulerZYZ(const Eigen::Matrix3d& r)
{
  // Third column = (cosα sinβ, sinα sinβ, cosβ); third row = (-sinβ cosγ, sinβ sinγ, cosβ).
  const double sinBeta = std::hypot(r(0, 2), r(1, 2));
  const double beta = std::atan2(sinBeta, r(2, 2));
  if (sinBeta > 1e-9)
  {
    return Eigen::Vector3d(WrapToTwoPi(std::atan2(r(1, 2), r(0, 2))), beta,
      WrapToTwoPi(std::atan2(r(2, 1), -r(2, 0))));
  }
  if (r(2, 2) > 0)
  {
    // Rz(α + γ): put everything in α.
    return Eigen::Vector3d(WrapToTwoPi(std::atan2(r(1, 0), r(0, 0))), beta, 0.0);
  }
  // Rz(α) Ry(π) Rz(γ) = Rz(α - γ) Ry(π) = [[-c, -s, 0], [-s, c, 0], [0, 0, -1]].
  return Eigen::Vector3d(WrapToTwoPi(std::atan2(-r(1, 0), r(1, 1))), beta, 0.0);
}

double RotationAngleBetween(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b)
{
  const Eigen::Matrix3d relative = a * b.transpose();
  // acos is ill-conditioned near 0: use atan2(|axis part|, cos part).
  const Eigen::Vector3d axis(relative(2, 1) - relative(1, 2), relative(0, 2) - relative(2, 0),
    relative(1, 0) - relative(0, 1));
  return std::atan2(0.5 * axis.norm(), 0.5 * (relative.trace() - 1.0));
}

std::array<double, 9> ToRowMajor(const Eigen::Matrix3d& m)
{
  return { m(0, 0), m(0, 1), m(0, 2), m(1, 0), m(1, 1), m(1, 2), m(2, 0), m(2, 1), m(2, 2) };
}

void ReflectCoefficients(SphericalHarmonicCoefficients& coefficients)
{
  for (int l = 1; l < coefficients.Bandwidth; l += 2)
  {
    for (int m = -l; m <= l; ++m)
    {
      coefficients(l, m) = -coefficients(l, m);
    }
  }
}

void RotateCoefficients(const SphericalHarmonicCoefficients& input, const Eigen::Matrix3d& transform,
  SphericalHarmonicCoefficients& output)
{
  const int bandwidth = input.Bandwidth;
  output.Resize(bandwidth);
  if (bandwidth == 0)
  {
    return;
  }
  const bool reflection = transform.determinant() < 0;
  const Eigen::Matrix3d rotation = reflection ? Eigen::Matrix3d(-transform) : transform;
  const Eigen::Vector3d euler = MatrixToEulerZYZ(rotation);
  // (Λ(R) f)_lm = Σ_n e^{-imα} d^l_mn(β) e^{-inγ} f_ln; f(-x) has coefficients (-1)^l f_ln.
  std::vector<double> d(bandwidth);
  for (int m = -(bandwidth - 1); m < bandwidth; ++m)
  {
    const std::complex<double> phaseM = std::polar(1.0, -m * euler[0]);
    for (int n = -(bandwidth - 1); n < bandwidth; ++n)
    {
      const std::complex<double> phase = phaseM * std::polar(1.0, -n * euler[2]);
      WignerSmallDSequence(m, n, bandwidth - 1, euler[1], d.data());
      for (int l = std::max(std::abs(m), std::abs(n)); l < bandwidth; ++l)
      {
        const double parity = (reflection && (l & 1)) ? -1.0 : 1.0;
        output(l, m) += phase * (parity * d[l]) * input(l, n);
      }
    }
  }
}
}
