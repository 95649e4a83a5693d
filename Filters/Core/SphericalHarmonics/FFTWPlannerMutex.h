// FFTW's planner (plan creation and destruction) is not thread-safe; executing a plan is.
// Every core algorithm that creates or destroys FFTW plans locks this one process-wide mutex
// (an inline function's static is a single object across translation units in C++17).
#ifndef mobius_FFTWPlannerMutex_h
#define mobius_FFTWPlannerMutex_h

#include <mutex>

namespace mobius
{
inline std::mutex& FFTWPlannerMutex()
{
  static std::mutex plannerMutex;
  return plannerMutex;
}
}

#endif
