// A minimal dynamic parallel loop on std::thread: calls work(index, thread) for every index in
// [0, count), handing out indices one at a time so uneven work balances out. thread is in
// [0, numberOfThreads) and lets the caller keep per-thread scratch space.
#ifndef mobius_ParallelFor_h
#define mobius_ParallelFor_h

#include <algorithm>
#include <atomic>
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
  auto run = [&](int thread) {
    for (int index = next++; index < count; index = next++)
    {
      work(index, thread);
    }
  };
  if (threads == 1)
  {
    run(0);
    return;
  }
  std::vector<std::thread> pool;
  for (int thread = 1; thread < threads; ++thread)
  {
    pool.emplace_back(run, thread);
  }
  run(0);
  for (std::thread& t : pool)
  {
    t.join();
  }
}
}

#endif
