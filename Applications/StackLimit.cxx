#include "StackLimit.h"

#include <sys/resource.h>

std::string CheckStackLimit(const std::string& program)
{
  struct rlimit limit;
  if (getrlimit(RLIMIT_STACK, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY ||
    static_cast<long long>(limit.rlim_cur) >= MinimumStackBytes)
  {
    return {};
  }
  return "the stack limit is " + std::to_string(static_cast<long long>(limit.rlim_cur) / 1024) +
    " KB (ulimit -s); " + program + " needs at least " + std::to_string(MinimumStackBytes / 1024) +
    " KB: raise it (ulimit -s " + std::to_string(MinimumStackBytes / 1024) +
    " or more; 8192 is the usual default) and run again";
}
