// PortableMath: PortableAtan2 against the exact angle (long double) on two million points of
// every size and quadrant, PortableSinCos against long double, std::atan2's results for zeros, infinities and NaN, and a few
// results pinned to their bits: they are the same on every CPU, and change only if the
// function's arithmetic does (or the compiler fuses its products and sums, as with
// -march=native on a CPU with FMA: then maps differ from those of the baseline build).
#include "CoreTest.h"

#include "PortableMath.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

namespace
{
std::uint64_t Bits(double value)
{
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

// Units in the last place of `value` between it and `exact`.
double Ulps(double value, long double exact)
{
  const double magnitude = std::abs(static_cast<double>(exact));
  const double ulp = std::nextafter(magnitude, std::numeric_limits<double>::infinity()) - magnitude;
  return static_cast<double>(std::abs(static_cast<long double>(value) - exact)) / ulp;
}
}

int main()
{
  using mobius::PortableAtan2;
  // Points of every quadrant and size: both coordinates uniform in (-1, 1), every third y and
  // every fifth x scaled by a power of two (exact, so that the points are the same on every
  // CPU) between 2^-100 and 2^100.
  std::mt19937_64 random(52);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-100, 100);
  double worstError = 0, worstUlps = 0;
  for (int i = 0; i < 2000000; ++i)
  {
    const double y = std::ldexp(unit(random), i % 3 == 0 ? exponent(random) : 0);
    const double x = std::ldexp(unit(random), i % 5 == 0 ? exponent(random) : 0);
    const long double exact = std::atan2(static_cast<long double>(y), static_cast<long double>(x));
    const double angle = PortableAtan2(y, x);
    worstError = std::max(worstError, static_cast<double>(std::abs(angle - exact)));
    worstUlps = std::max(worstUlps, Ulps(angle, exact));
  }
  std::cout << "PortableAtan2: largest error " << worstError << " (" << worstUlps << " ulps)\n";
  // Measured 8.0e-16 (1.8 ulps of an angle near pi) and 5.9 ulps (of an angle near 0.5, after
  // three halvings); std::atan2 is within 0.52 ulps. The angle defects the function serves
  // sum a handful of angles of about 1, so a few ulps more are below 1e-14 of the curvature.
  MOBIUS_CHECK(worstError < 1.5e-15);
  MOBIUS_CHECK(worstUlps <= 10.0);

  // The special cases are std::atan2's, sign of zero included.
  const double inf = std::numeric_limits<double>::infinity();
  const double special[][2] = { { 0.0, 0.0 }, { -0.0, 0.0 }, { 0.0, -0.0 }, { -0.0, -0.0 },
    { 1.0, 0.0 }, { -1.0, -0.0 }, { 0.0, -1.0 }, { -0.0, -1.0 }, { 0.0, 2.0 }, { inf, 1.0 },
    { 1.0, -inf }, { -inf, inf }, { 1e-310, 1.0 } };
  for (const auto& point : special)
  {
    MOBIUS_CHECK(Bits(PortableAtan2(point[0], point[1])) == Bits(std::atan2(point[0], point[1])));
  }
  MOBIUS_CHECK(std::isnan(PortableAtan2(std::nan(""), 1.0)));
  MOBIUS_CHECK(std::isnan(PortableAtan2(1.0, std::nan(""))));

  // Pinned results (the last one is one ulp from std::atan2's here).
  MOBIUS_CHECK(PortableAtan2(1.0, 2.0) == 0x1.dac670561bb4fp-2);
  MOBIUS_CHECK(PortableAtan2(0.3, -0.7) == 0x1.5e4c36ca0118ap+1);
  MOBIUS_CHECK(PortableAtan2(-2.5, 1e-3) == -0x1.92057e616f2a1p+0);
  MOBIUS_CHECK(PortableAtan2(1e-5, 1.0) == 0x1.4f8b588e06854p-17);
  MOBIUS_CHECK(PortableAtan2(0.8660254037844386, 0.5) == 0x1.0c152382d7364p+0);

  // PortableSinCos against long double on angles of up to 4 turns either way (the hole
  // filling lays out its rings at angles in [0, 2 pi]) and a few large ones, the identity
  // sin^2 + cos^2 = 1, exact quadrant points, and std's results outside its range.
  using mobius::PortableSinCos;
  std::uniform_real_distribution<double> turns(-8 * M_PI, 8 * M_PI);
  double worstSinCos = 0;
  for (int i = 0; i < 1000000; ++i)
  {
    const double angle = i % 100 == 0 ? std::ldexp(turns(random), 14) : turns(random);
    double sine, cosine;
    PortableSinCos(angle, sine, cosine);
    const long double exactAngle = angle;
    worstSinCos = std::max({ worstSinCos,
      static_cast<double>(std::abs(static_cast<long double>(sine) - std::sin(exactAngle))),
      static_cast<double>(std::abs(static_cast<long double>(cosine) - std::cos(exactAngle))) });
  }
  std::cout << "PortableSinCos: largest error " << worstSinCos << "\n";
  MOBIUS_CHECK(worstSinCos < 5e-16);
  double sine, cosine;
  PortableSinCos(0.0, sine, cosine);
  MOBIUS_CHECK(sine == 0.0 && cosine == 1.0);
  PortableSinCos(M_PI / 2, sine, cosine);
  MOBIUS_CHECK(sine == 1.0 && std::abs(cosine) < 1e-16);
  PortableSinCos(-M_PI, sine, cosine);
  MOBIUS_CHECK(std::abs(sine) < 1e-15 && cosine == -1.0);
  PortableSinCos(3e7, sine, cosine); // beyond the reduction's range: std's values
  MOBIUS_CHECK(sine == std::sin(3e7) && cosine == std::cos(3e7));
  PortableSinCos(std::nan(""), sine, cosine);
  MOBIUS_CHECK(std::isnan(sine) && std::isnan(cosine));
  return MOBIUS_TEST_RESULT();
}
