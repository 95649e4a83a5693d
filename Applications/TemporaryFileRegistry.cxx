#include "TemporaryFileRegistry.h"

#include <atomic>
#include <climits>
#include <cstring>
#include <pthread.h>
#include <unistd.h>

namespace
{
// Fixed storage: the handler may neither allocate nor lock.
constexpr int Slots = 16;
char Names[Slots][PATH_MAX];
std::atomic<bool> InUse[Slots];

constexpr int CleanupSignals[] = { SIGINT, SIGTERM, SIGHUP, SIGXFSZ };
std::atomic<bool> Installed{ false };
pthread_t WritingThread;

void RemoveTemporariesAndDie(int signal)
{
  if (!pthread_equal(pthread_self(), WritingThread))
  {
    // Only the writing thread changes the registry; it takes over (or holds the signal
    // until its renames are done).
    pthread_kill(WritingThread, signal);
    return;
  }
  for (int i = 0; i < Slots; ++i)
  {
    if (InUse[i].load())
    {
      unlink(Names[i]);
    }
  }
  // The default action, delivered when the handler returns (the signal is blocked in here).
  struct sigaction fallback = {};
  fallback.sa_handler = SIG_DFL;
  sigaction(signal, &fallback, nullptr);
  raise(signal);
}

void InstallHandlers()
{
  WritingThread = pthread_self();
  Installed = true;
  for (int signal : CleanupSignals)
  {
    struct sigaction current = {};
    if (sigaction(signal, nullptr, &current) != 0 || current.sa_handler == SIG_IGN)
    {
      continue; // ignored on purpose by whoever started us: keep it so
    }
    struct sigaction handler = {};
    handler.sa_handler = RemoveTemporariesAndDie;
    sigfillset(&handler.sa_mask);
    sigaction(signal, &handler, nullptr);
  }
}
}

int RegisterTemporaryFile(const std::string& path)
{
  if (!Installed.load())
  {
    InstallHandlers();
  }
  if (path.size() >= PATH_MAX)
  {
    return -1;
  }
  for (int i = 0; i < Slots; ++i)
  {
    if (!InUse[i].load())
    {
      std::memcpy(Names[i], path.c_str(), path.size() + 1);
      InUse[i].store(true);
      return i;
    }
  }
  return -1;
}

void ForgetTemporaryFile(int slot)
{
  if (slot >= 0 && slot < Slots)
  {
    InUse[slot].store(false);
  }
}

SignalsHeld::SignalsHeld()
{
  sigset_t held;
  sigemptyset(&held);
  for (int signal : CleanupSignals)
  {
    sigaddset(&held, signal);
  }
  pthread_sigmask(SIG_BLOCK, &held, &this->Previous);
}

SignalsHeld::~SignalsHeld()
{
  pthread_sigmask(SIG_SETMASK, &this->Previous, nullptr);
}
