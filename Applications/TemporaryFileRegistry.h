// The names of the temporary files a program is writing, removed if a signal ends it.
// SIGINT, SIGTERM and SIGHUP (and SIGXFSZ, the signal of a file grown past `ulimit -f`)
// get a handler, unless the program was started with them ignored (nohup, a background
// job): it unlinks every registered name, then ends the program by the same signal with
// its default action, so the caller still sees "killed by SIGTERM".
//
// Register and forget names from one thread, the writing thread (the first to register).
// A signal that the kernel delivers to another thread is passed on to the writing thread,
// so the handler never runs while the registry is being changed, and SignalsHeld delays
// it while files are being moved into place.
#ifndef TemporaryFileRegistry_h
#define TemporaryFileRegistry_h

#include <csignal>
#include <string>

/// Remembers `path` for the signal handler (installed on first use); returns its slot, or
/// -1 when the registry is full or the path too long (then the file must not be created).
int RegisterTemporaryFile(const std::string& path);
/// Forgets the name in `slot` (the file has been renamed or removed).
void ForgetTemporaryFile(int slot);

/// While alive, the cleanup signals wait (in this thread, and so in the whole program: the
/// other threads pass them on to this one): a group of renames is never cut in half.
class SignalsHeld
{
public:
  SignalsHeld();
  ~SignalsHeld();
  SignalsHeld(const SignalsHeld&) = delete;
  SignalsHeld& operator=(const SignalsHeld&) = delete;

private:
  sigset_t Previous;
};

#endif
