// A minimal dynamic parallel loop on std::thread: calls work(index, thread) for every index in
// [0, count), handing out indices one at a time so uneven work balances out. thread is in
// [0, numberOfThreads) and lets the caller keep per-thread scratch space; thread 0 is the
// calling thread.
//
// An exception thrown by work (std::bad_alloc on a large grid, say) is carried to the caller
// and rethrown there after every thread has been joined: escaping a std::thread it would
// call std::terminate and take the whole application (ParaView) down with it.
#ifndef mobius_ParallelFor_h
#define mobius_ParallelFor_h

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace mobius
{
/// 0 (or less) means one thread per hardware core.
inline int ResolveThreadCount(int requested)
{
  if (requested > 0)
  {
    return requested;
  }
  return std::max(1u, std::thread::hardware_concurrency());
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
  std::vector<std::thread> pool;
  try
  {
    pool.reserve(threads - 1);
    for (int thread = 1; thread < threads; ++thread)
    {
      pool.emplace_back(run, thread);
    }
  }
  catch (...)
  {
    // No more threads to be had (std::system_error): the ones started and this one do all
    // the work. (Letting the exception out here would destroy joinable threads, which
    // terminates the program.)
  }
  run(0);
  for (std::thread& t : pool)
  {
    t.join();
  }
  if (failure)
  {
    std::rethrow_exception(failure);
  }
}
}

#endif
