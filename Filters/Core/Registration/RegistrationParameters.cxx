#include "RegistrationParameters.h"

#include <algorithm>

namespace mobius
{
bool RefinementApplies(Index vertexCount, int basisSize)
{
  return vertexCount >= 2 * static_cast<Index>(basisSize);
}

int ClampToBasisSize(int size, int basisSize)
{
  return std::min(size, basisSize);
}
}
