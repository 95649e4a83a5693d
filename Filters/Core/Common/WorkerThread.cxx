#include "WorkerThread.h"

#include <algorithm>
#include <cerrno>
#include <pthread.h>
#include <sys/resource.h>
#include <system_error>

namespace mobius
{
struct WorkerThread::State
{
  pthread_t Handle{};
  std::function<void()> Work;
  bool Joinable = false;
};

namespace
{
void* RunWork(void* state)
{
  static_cast<std::function<void()>*>(state)->operator()();
  return nullptr;
}

std::size_t StackBytes()
{
  rlimit limit{};
  if (getrlimit(RLIMIT_STACK, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
  {
    return std::max<std::size_t>(WorkerStackBytes, static_cast<std::size_t>(limit.rlim_cur));
  }
  return WorkerStackBytes;
}
}

WorkerThread::WorkerThread(std::function<void()> work)
  : Thread(new State)
{
  this->Thread->Work = std::move(work);
  pthread_attr_t attributes;
  int status = pthread_attr_init(&attributes);
  if (status == 0)
  {
    status = pthread_attr_setstacksize(&attributes, StackBytes());
    if (status == 0)
    {
      status = pthread_create(&this->Thread->Handle, &attributes, RunWork, &this->Thread->Work);
    }
    pthread_attr_destroy(&attributes);
  }
  if (status != 0)
  {
    throw std::system_error(status, std::generic_category(), "cannot start a worker thread");
  }
  this->Thread->Joinable = true;
}

WorkerThread::WorkerThread(WorkerThread&& other) noexcept = default;

WorkerThread::~WorkerThread()
{
  this->Join();
}

void WorkerThread::Join()
{
  if (this->Thread && this->Thread->Joinable)
  {
    pthread_join(this->Thread->Handle, nullptr);
    this->Thread->Joinable = false;
  }
}
}
