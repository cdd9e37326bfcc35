// parallel_sort(first, last): sorts a random-access range on the worker threads (oneTBB), with
// operator<. Sort values whose order is total (e.g. (key, index) pairs) so that the result does
// not depend on the thread count.
#pragma once

#include <tbb/parallel_sort.h>

namespace pathspace {

template <typename Iterator>
void parallel_sort(Iterator first, Iterator last) {
  tbb::parallel_sort(first, last);
}

}  // namespace pathspace
