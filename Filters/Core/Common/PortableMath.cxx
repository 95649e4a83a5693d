#include "PortableMath.h"

#include <cmath>

namespace mobius
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

// atan(t) for 0 <= t <= 1. Halvings of the angle, atan(t) = 2 atan(t / (1 + sqrt(1 + t^2))),
// at most three, take t below tan(pi / 32) < 0.0985; there the series t - t^3/3 + t^5/5 - ...
// is summed to its term t^17/17, the next being below 1e-19 t.
double AtanOfUnitInterval(double t)
{
  constexpr double kSeriesLimit = 0.0985; // below tan(pi / 32)
  constexpr int kLastTerm = 8;            // the series up to (-1)^8 t^17 / 17
  double factor = 1.0;
  while (t > kSeriesLimit)
  {
    t = t / (1.0 + std::sqrt(1.0 + t * t));
    factor *= 2.0;
  }
  const double square = t * t;
  double sum = 0.0;
  for (int k = kLastTerm; k >= 0; --k)
  {
    sum = sum * square + (k % 2 == 0 ? 1.0 : -1.0) / (2 * k + 1);
  }
  return factor * (t * sum);
}

// sin and cos of |x| <= pi / 4 by their series to the x^17 and x^18 terms (the next are
// below 1e-19 there). Each factor is divided out exactly where it can be, so every CPU sums
// the same terms.
void SinCosOfEighthTurn(double x, double& sine, double& cosine)
{
  const double square = x * x;
  double s = 1.0, c = 1.0;
  for (int k = 9; k >= 1; --k)
  {
    s = 1.0 - s * square / ((2.0 * k) * (2.0 * k + 1.0));
    c = 1.0 - c * square / ((2.0 * k - 1.0) * (2.0 * k));
  }
  sine = x * s;
  cosine = c;
}
}

double PortableAtan2(double y, double x)
{
  if (!std::isfinite(x) || !std::isfinite(y) || (x == 0 && y == 0))
  {
    return std::atan2(y, x); // exact values (0, +-pi/2, +-pi, ...), alike in every C library
  }
  const double ax = std::abs(x), ay = std::abs(y);
  double angle = ay <= ax ? AtanOfUnitInterval(ay / ax) : kPi / 2 - AtanOfUnitInterval(ax / ay);
  if (x < 0)
  {
    angle = kPi - angle;
  }
  return std::copysign(angle, y);
}

void PortableSinCos(double angle, double& sine, double& cosine)
{
  constexpr double kLargestReduced = 1e6; // quarter turns counted exactly, error below 1e-10
  if (!(std::abs(angle) <= kLargestReduced))
  {
    sine = std::sin(angle);
    cosine = std::cos(angle);
    return;
  }
  // angle = quarter * pi / 2 + x, |x| <= pi / 4; pi / 2 in two parts whose first has so few
  // bits that quarter times it is exact (Cody and Waite's reduction).
  constexpr double kHalfPiHigh = 1.5707963267341256;     // 33 bits of pi / 2
  constexpr double kHalfPiLow = 6.077100506506192e-11;   // pi / 2 - kHalfPiHigh
  const double quarter = std::nearbyint(angle / (kPi / 2));
  const double x = (angle - quarter * kHalfPiHigh) - quarter * kHalfPiLow;
  double s, c;
  SinCosOfEighthTurn(x, s, c);
  switch (static_cast<long long>(quarter) & 3)
  {
    case 0: sine = s; cosine = c; break;
    case 1: sine = c; cosine = -s; break;
    case 2: sine = -s; cosine = -c; break;
    default: sine = -c; cosine = s; break;
  }
}
}
