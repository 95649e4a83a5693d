// The stack the programs need. The pipeline's deepest calls (VTK's pipeline, then Eigen's
// matrix products, whose temporaries above 16 KB come from the heap) need about 64 KB on
// CGAL's meshes with the refinement and two threads (measured: 48 KB fails, 64 KB works);
// worker threads get stacks of the same size (the limit is glibc's default for them). A limit
// below twice that is refused with a message before any work, instead of a crash midway.
#ifndef StackLimit_h
#define StackLimit_h

#include <string>

/// The smallest stack limit (ulimit -s) the programs accept, in bytes.
inline constexpr long long MinimumStackBytes = 128 * 1024;

/// Empty when the stack limit is at least MinimumStackBytes (or unlimited), else the message:
/// "the stack limit is 100 KB (ulimit -s); PROGRAM needs at least 128 KB: ...".
std::string CheckStackLimit(const std::string& program);

#endif
