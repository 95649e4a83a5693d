// ParallelFor: every index runs once (ParallelForChunks: every index once, in whole chunks); an
// exception thrown in a worker thread reaches the caller (instead of std::terminate), with its
// type and message, after all threads joined.
// ResolveThreadCount: the automatic count follows the CPU affinity mask and
// VTK_SMP_MAX_THREADS.
#include "CoreTest.h"
#include "ParallelFor.h"
#include "SphericalAreaGrid.h"

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <new>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using namespace mobius;

namespace
{
void EveryIndexOnce()
{
  std::vector<std::atomic<int>> visits(1000);
  ParallelFor(1000, 4, [&](int index, int thread) {
    MOBIUS_CHECK(thread >= 0 && thread < 4);
    ++visits[index];
  });
  for (auto& count : visits)
  {
    MOBIUS_CHECK(count == 1);
  }
}

// Chunks cover [0, count) once each, in ranges of at most `chunk`, whether the count is a
// multiple of the chunk or not (or zero).
void EveryIndexOnceInChunks()
{
  for (long count : { 0L, 1L, 511L, 512L, 1025L })
  {
    std::vector<std::atomic<int>> visits(static_cast<size_t>(count));
    ParallelForChunks<long>(count, 512, 3, [&](long begin, long end) {
      MOBIUS_CHECK(begin < end && end - begin <= 512 && begin % 512 == 0);
      for (long i = begin; i < end; ++i)
      {
        ++visits[static_cast<size_t>(i)];
      }
    });
    for (auto& visitCount : visits)
    {
      MOBIUS_CHECK(visitCount == 1);
    }
  }
}

// Only worker threads (not the caller, thread 0) throw; the caller is slowed down so the
// workers surely get indices.
template <class Exception>
void WorkerExceptionReachesCaller(const Exception& thrown, const std::string& what)
{
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> running(0);
  std::atomic<bool> workerThrew(false);
  bool caught = false;
  try
  {
    ParallelFor(64, 3, [&](int, int thread) {
      ++running;
      if (thread == 0)
      {
        MOBIUS_CHECK(std::this_thread::get_id() == caller);
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
      }
      else
      {
        MOBIUS_CHECK(std::this_thread::get_id() != caller);
        workerThrew = true;
        --running;
        throw thrown;
      }
      --running;
    });
  }
  catch (const Exception& exception)
  {
    caught = true;
    MOBIUS_CHECK(what.empty() || std::string(exception.what()) == what);
  }
  MOBIUS_CHECK(caught);
  MOBIUS_CHECK(workerThrew);
  MOBIUS_CHECK(running == 0); // every thread was done when the caller got the exception
}

// Every thread throws: the caller gets one exception, nothing is left running.
void AllThreadsThrow()
{
  int caught = 0;
  try
  {
    ParallelFor(100, 4, [&](int index, int) { throw std::runtime_error(std::to_string(index)); });
  }
  catch (const std::runtime_error&)
  {
    ++caught;
  }
  MOBIUS_CHECK(caught == 1);
}

// A single thread (no pool) passes the exception through as well.
void SingleThreadThrows()
{
  bool caught = false;
  try
  {
    ParallelFor(10, 1, [&](int index, int) {
      if (index == 5)
      {
        throw std::length_error("five");
      }
    });
  }
  catch (const std::length_error&)
  {
    caught = true;
  }
  MOBIUS_CHECK(caught);
}

// The rasterizer's own pool goes through ParallelFor too: a progress callback that throws
// (on the calling thread, while workers rasterize) reaches the caller.
void RasterizerPassesExceptions()
{
  Points points(3, 3);
  points << 1, 0, 0, 0, 1, 0, 0, 0, 1;
  Triangles triangles(4096 * 4, 3);
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    triangles.row(t) << 0, 1, 2;
  }
  const Vector areas = Vector::Constant(triangles.rows(), 1.0);
  SphericalAreaGridResult grid;
  std::string error;
  bool caught = false;
  try
  {
    RasterizeSphericalAreas(points, triangles, areas, 16, ScaleFactorValue::AreaRatio, grid, error,
      [](double) -> bool { throw std::runtime_error("from the progress callback"); }, 4);
  }
  catch (const std::runtime_error& exception)
  {
    caught = std::string(exception.what()) == "from the progress callback";
  }
  MOBIUS_CHECK(caught);
}

// Run with the process pinned to one core and with VTK_SMP_MAX_THREADS set: "automatic"
// must follow both (an MPI rank bound to its cores must not start one thread per core of
// the node); an explicit request is always kept.
void AutomaticThreadCount()
{
  MOBIUS_CHECK(ResolveThreadCount(3) == 3);
  unsetenv("VTK_SMP_MAX_THREADS");
  const int available = AvailableCoreCount();
  MOBIUS_CHECK(available >= 1);
  MOBIUS_CHECK(ResolveThreadCount(0) == available);

  setenv("VTK_SMP_MAX_THREADS", "1", 1);
  MOBIUS_CHECK(ResolveThreadCount(0) == 1);
  MOBIUS_CHECK(ResolveThreadCount(2) == 2);
  setenv("VTK_SMP_MAX_THREADS", "1000", 1);
  MOBIUS_CHECK(ResolveThreadCount(0) == available);
  for (const char* ignored : { "", "0", "-2", "two", "3x" })
  {
    setenv("VTK_SMP_MAX_THREADS", ignored, 1);
    MOBIUS_CHECK(ResolveThreadCount(0) == available);
  }
  unsetenv("VTK_SMP_MAX_THREADS");

#ifdef __linux__
  cpu_set_t saved;
  CPU_ZERO(&saved);
  MOBIUS_CHECK(sched_getaffinity(0, sizeof(saved), &saved) == 0);
  cpu_set_t one;
  CPU_ZERO(&one);
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
  {
    if (CPU_ISSET(cpu, &saved))
    {
      CPU_SET(cpu, &one);
      break;
    }
  }
  MOBIUS_CHECK(sched_setaffinity(0, sizeof(one), &one) == 0);
  MOBIUS_CHECK(AvailableCoreCount() == 1);
  MOBIUS_CHECK(ResolveThreadCount(0) == 1);
  MOBIUS_CHECK(sched_setaffinity(0, sizeof(saved), &saved) == 0);
  MOBIUS_CHECK(AvailableCoreCount() == available);
#endif
}
}

int main()
{
  AutomaticThreadCount();
  EveryIndexOnce();
  EveryIndexOnceInChunks();
  WorkerExceptionReachesCaller(std::runtime_error("worker failed"), "worker failed");
  WorkerExceptionReachesCaller(std::bad_alloc(), "");
  AllThreadsThrow();
  SingleThreadThrows();
  RasterizerPassesExceptions();
  return MOBIUS_TEST_RESULT();
}
