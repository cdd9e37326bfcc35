// The median of a benchmark's per-run figures (the mean of the middle two for an even count; 0 for
// none): what the hand-timed benchmarks report instead of a mean that one slow run would move.
#pragma once

#include <algorithm>
#include <vector>

namespace pathspace {

inline double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

}  // namespace pathspace
