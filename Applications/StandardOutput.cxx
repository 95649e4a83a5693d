#include "StandardOutput.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

bool FlushStandardOutput(std::string& error)
{
  errno = 0;
  std::cout.flush();
  // Flushed even when an earlier write failed: whatever is still buffered is tried too.
  const bool flushed = std::fflush(stdout) == 0;
  if (flushed && std::cout.good() && !std::ferror(stdout))
  {
    return true;
  }
  // An error of an earlier write leaves errno unknown here.
  error = std::string("standard output: cannot write (") +
    (errno ? std::strerror(errno) : "write error") + ")";
  return false;
}
