// Minimal assertions for the core unit tests (plain executables run by ctest): each failed
// check prints where and why and makes the test return non-zero.
#ifndef mobius_CoreTest_h
#define mobius_CoreTest_h

#include <cmath>
#include <iostream>

namespace mobius_test
{
inline int& Failures()
{
  static int failures = 0;
  return failures;
}
}

#define MOBIUS_CHECK(condition)                                                                    \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #condition << std::endl;      \
      ++mobius_test::Failures();                                                                   \
    }                                                                                              \
  } while (false)

// |actual - expected| <= tolerance, with both values printed on failure.
#define MOBIUS_CHECK_NEAR(actual, expected, tolerance)                                             \
  do                                                                                               \
  {                                                                                                \
    const double mobiusActual_ = (actual);                                                         \
    const double mobiusExpected_ = (expected);                                                     \
    if (!(std::abs(mobiusActual_ - mobiusExpected_) <= (tolerance)))                               \
    {                                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": " #actual " = " << mobiusActual_              \
                << ", expected " << mobiusExpected_ << " +- " << (tolerance) << std::endl;         \
      ++mobius_test::Failures();                                                                   \
    }                                                                                              \
  } while (false)

#define MOBIUS_TEST_RESULT() (mobius_test::Failures() == 0 ? 0 : 1)

#endif
