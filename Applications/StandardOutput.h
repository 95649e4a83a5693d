// Standard output as a result like the output files: what was written to it and lost (a
// full disk, a closed pipe, /dev/full) is a failure.
#ifndef StandardOutput_h
#define StandardOutput_h

#include <string>

/// Flushes std::cout and stdout; false, with `error` set, if any of it could not be written.
bool FlushStandardOutput(std::string& error);

#endif
