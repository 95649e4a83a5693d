// A thread with a stack of its own size. std::thread takes the default of the C library,
// which on Linux is the stack limit of the process (`ulimit -s`): under a small limit
// (256 KB) a worker overflowed inside Eigen, whose temporaries of up to 128 KB live on the
// stack, and the program died of a segmentation fault. A worker gets at least
// WorkerStackBytes, or the process's limit when that is larger.
#ifndef mobius_WorkerThread_h
#define mobius_WorkerThread_h

#include <cstddef>
#include <functional>
#include <memory>

namespace mobius
{
/// The stack a worker thread gets at least: the usual Linux default (`ulimit -s` 8192).
constexpr std::size_t WorkerStackBytes = std::size_t(8) << 20;

class WorkerThread
{
public:
  /// Starts `work` on a new thread; throws std::system_error if no thread can be started.
  explicit WorkerThread(std::function<void()> work);
  /// Joins the thread (work must not throw: catch inside it).
  ~WorkerThread();
  WorkerThread(const WorkerThread&) = delete;
  WorkerThread& operator=(const WorkerThread&) = delete;
  WorkerThread(WorkerThread&& other) noexcept;
  WorkerThread& operator=(WorkerThread&&) = delete;

  /// Waits for the thread to end; does nothing the second time.
  void Join();

private:
  struct State;
  std::unique_ptr<State> Thread;
};
}

#endif
