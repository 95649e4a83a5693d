// A minimal dynamic parallel loop on worker threads (WorkerThread): calls work(index, thread) for every index in
// [0, count), handing out indices one at a time so uneven work balances out. thread is in
// [0, numberOfThreads) and lets the caller keep per-thread scratch space; thread 0 is the
// calling thread.
//
// An exception thrown by work (std::bad_alloc on a large grid, say) is carried to the caller
// and rethrown there after every thread has been joined: escaping a thread it would
// call std::terminate and take the whole application (ParaView) down with it.
#ifndef mobius_ParallelFor_h
#define mobius_ParallelFor_h

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "WorkerThread.h"

#ifdef __linux__
#include <sched.h>
#endif

namespace mobius
{
/// The cores this process may run on: its CPU affinity mask (a cpuset, `taskset`, or an MPI
/// launcher binding each rank to its share), not every core of the machine, which
/// std::thread::hardware_concurrency reports.
inline int AvailableCoreCount()
{
#ifdef __linux__
  cpu_set_t cores;
  CPU_ZERO(&cores);
  if (sched_getaffinity(0, sizeof(cores), &cores) == 0 && CPU_COUNT(&cores) > 0)
  {
    return CPU_COUNT(&cores);
  }
#endif
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

/// The thread count for a request: a positive request as given; 0 (or less) means
/// automatic: one thread per available core, at most VTK_SMP_MAX_THREADS when that
/// environment variable holds a positive number (the limit VTK's own threaded filters
/// honour, so one setting governs both).
inline int ResolveThreadCount(int requested)
{
  if (requested > 0)
  {
    return requested;
  }
  int threads = AvailableCoreCount();
  if (const char* limit = std::getenv("VTK_SMP_MAX_THREADS"))
  {
    char* end = nullptr;
    const long value = std::strtol(limit, &end, 10);
    if (end != limit && *end == '\0' && value > 0)
    {
      threads = static_cast<int>(std::min<long>(threads, value));
    }
  }
  return std::max(1, threads);
}

template <typename Work>
void ParallelFor(int count, int numberOfThreads, Work&& work)
{
  const int threads = std::max(1, std::min(numberOfThreads, count));
  std::atomic<int> next(0);
  std::mutex failureMutex;
  std::exception_ptr failure;
  // After a failure the other threads take no new index, so the caller hears of it soon.
  auto stop = [&](std::exception_ptr exception) {
    next = count;
    std::lock_guard<std::mutex> lock(failureMutex);
    if (!failure)
    {
      failure = exception;
    }
  };
  auto run = [&](int thread) {
    try
    {
      for (int index = next++; index < count; index = next++)
      {
        work(index, thread);
      }
    }
    catch (...)
    {
      stop(std::current_exception());
    }
  };
  std::vector<WorkerThread> pool;
  try
  {
    pool.reserve(threads - 1);
    for (int thread = 1; thread < threads; ++thread)
    {
      pool.emplace_back([&run, thread] { run(thread); });
    }
  }
  catch (...)
  {
    // No more threads to be had (std::system_error): the ones started and this one do all
    // the work. (Letting the exception out here would destroy joinable threads, which
    // terminates the program.)
  }
  run(0);
  for (WorkerThread& worker : pool)
  {
    worker.Join();
  }
  if (failure)
  {
    std::rethrow_exception(failure);
  }
}

/// Calls work(begin, end) on consecutive chunks of `chunk` indices of [0, count), the chunks
/// spread over `numberOfThreads` threads (0: automatic, see ResolveThreadCount). For
/// per-item loops whose items are too cheap to hand out one at a time.
template <typename Index, typename Work>
void ParallelForChunks(Index count, Index chunk, int numberOfThreads, Work&& work)
{
  const int chunks = static_cast<int>((count + chunk - 1) / chunk);
  ParallelFor(chunks, ResolveThreadCount(numberOfThreads), [&](int c, int) {
    work(static_cast<Index>(c) * chunk, std::min(count, static_cast<Index>(c + 1) * chunk));
  });
}
}

#endif
