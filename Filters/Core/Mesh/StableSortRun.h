// A stable sort for the short runs of a per-vertex bucket (a vertex's edges, triangles or
// half-edges): insertion sort, which needs no buffer and beats a general sort on the half
// dozen items of an ordinary vertex, and std::stable_sort for a long run (a hub vertex of
// thousands of triangles), where insertion sort would be quadratic.
#ifndef mobius_StableSortRun_h
#define mobius_StableSortRun_h

#include <algorithm>
#include <iterator>

namespace mobius
{
template <typename Iterator, typename Less>
void StableSortRun(Iterator begin, Iterator end, Less less)
{
  if (end - begin > 32)
  {
    std::stable_sort(begin, end, less);
    return;
  }
  if (begin == end)
  {
    return;
  }
  for (Iterator i = begin + 1; i < end; ++i)
  {
    auto item = std::move(*i);
    Iterator j = i;
    for (; j > begin && less(item, *(j - 1)); --j)
    {
      *j = std::move(*(j - 1));
    }
    *j = std::move(item);
  }
}
}

#endif
