// What the GPU hashed filter did (gpu/cuda_hashed_filter.h), summed over passes, with the last
// pass's phase times for benchmarks. Plain data without CUDA, so that reporting it
// (cuda_hashed_filter_statistics.cpp) compiles in every build.
#pragma once

#include <cstddef>
#include <cstdint>

namespace pathspace {
class Statistics;
}

namespace pathspace::gpu {

struct CudaHashedFilterStats {
  uint64_t passes = 0, vertices = 0;
  uint64_t not_accumulated = 0;  // NaN/Inf/negative/huge: kept their own contribution
  uint64_t insertions = 0;       // find_or_insert calls: one per warp group of equal keys (sec. 4)
  uint64_t probes_total = 0, probes_max = 0;
  uint64_t probe_failures = 0;   // after settling: vertices that kept their own contribution
  uint64_t settled_passes = 0;   // passes whose full probe windows were settled by fingerprint
  uint64_t low_count = 0, neighbour_lookups = 0, multi_level_used = 0;
  uint64_t occupied_cells_last = 0, cells = 0;
  size_t table_bytes = 0;
  // Milliseconds by cudaEvents, summed over passes; accumulate includes settling.
  double clear_ms = 0, accumulate_ms = 0, settle_ms = 0, lookup_ms = 0;
  double clear_ms_last = 0, accumulate_ms_last = 0, settle_ms_last = 0, lookup_ms_last = 0;

  // --temporal (sec. 3.4): summed over steps (passes), and the last step's.
  bool temporal = false;
  uint64_t steps = 0, blended = 0, from_finer = 0, from_coarser = 0, evicted = 0, evicted_last = 0, folded_last = 0;
  double alpha_sum = 0, mean_alpha_last = 0;
  double temporal_ms = 0, temporal_ms_last = 0;  // level transfer, folding, priorities and eviction

  double mean_probes() const { return insertions ? double(probes_total) / double(insertions) : 0.0; }
};

// Fills `out` with "cuda_hashed.<what>" entries (named like HashedFilter's "hashed.<what>").
void report_statistics(const CudaHashedFilterStats& s, Statistics& out);

}  // namespace pathspace::gpu
