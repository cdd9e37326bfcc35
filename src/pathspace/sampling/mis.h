// Multiple importance sampling weights (Veach 1997, ch. 9): balance and power (beta = 2) heuristics.
#pragma once

#include "pathspace/base/platform.h"

namespace pathspace {

enum class MisHeuristic { balance, power };

// Weight of the technique with pdf `a` (taken with na samples) against `b` (nb samples).
PS_INLINE float mis_weight(MisHeuristic h, float a, float b) {
  if (h == MisHeuristic::power) {
    a *= a;
    b *= b;
  }
  const float sum = a + b;
  return sum > 0.f ? a / sum : 0.f;
}

}  // namespace pathspace
