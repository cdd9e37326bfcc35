// The statistics of the hashed filter's table across frames (Binder et al. 2021, sec. 3.4), reported
// alike by the CPU filter ("hashed.temporal.*") and the GPU filter ("cuda_hashed.temporal.*").
#pragma once

#include <cstdint>
#include <string>

#include "pathspace/stats/statistics.h"

namespace pathspace {

// Summed over steps (passes), and the last step's.
struct TemporalTotals {
  uint64_t steps = 0, evicted = 0, evicted_last = 0, blended = 0, from_finer = 0, from_coarser = 0;
  double alpha_sum = 0.0;        // of the blended vertices' alphas
  double mean_alpha_last = 0.0;  // last step
  double temporal_ms = 0.0;      // what `timed` says
};

// "<prefix>temporal.<what>"; `timed`: the steps temporal_ms covers.
void report_temporal_statistics(const std::string& prefix, const TemporalTotals& t, const char* timed, Statistics& out);

}  // namespace pathspace
