// A stage's progress as it passes the fraction done on to its caller's: the algorithms it
// runs fail or come back aborted when the caller asks to stop, and the stage, remembering the
// request, reports itself stopped instead of wrong.
#ifndef mobius_StopWatchingProgress_h
#define mobius_StopWatchingProgress_h

#include "MeshTypes.h"

namespace mobius
{
struct StopWatchingProgress
{
  const ProgressCallback& Progress;
  bool StopAsked = false;

  /// Passes `fraction` on (when there is a caller's progress); false once it asked to stop.
  bool operator()(double fraction)
  {
    const bool goOn = !this->Progress || this->Progress(fraction);
    this->StopAsked = this->StopAsked || !goOn;
    return goOn;
  }
};
}

#endif
