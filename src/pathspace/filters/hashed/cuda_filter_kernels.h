// What the GPU hashed filter's kernels share (cuda_hashed_filter.cu, cuda_hashed_filter_temporal.cu):
// the launch shape, the per-pass counters and their per-warp and per-block sums, and the record slot
// of a thread. CUDA sources only.
#pragma once

#include <cstddef>

#include "pathspace/filters/vertex_buffer_view.h"

namespace pathspace::gpu::filter_kernels {

inline constexpr int kBlock = 256;
inline constexpr unsigned kFullWarp = 0xffffffffu;

// Device counters of one pass, summed per warp before one atomic each.
enum Counter : int {
  kVertices,
  kNotAccumulated,
  kInsertions,
  kProbes,
  kProbesMax,
  kFailures,
  kLowCount,
  kNeighbourLookups,
  kMultiLevelUsed,
  kFailedListed,
  kLost,
  kWon,
  kOccupied,
  kBlended,      // --temporal: vertices whose estimate blended a history (sec. 3.4.1)
  kAlphaSum,     // their alphas, fixed point 2^-32 (added per block, not through the 32-bit block counters)
  kFromFiner,    // new cells that took their finer voxels' history (sec. 3.4.2)
  kFromCoarser,  // new cells that took their coarser voxel's history
  kFolded,       // cells used in the step (sec. 3.4.3)
  kEvicted,      // cells evicted after the step
  kCounters
};

// Per-pass counters are summed per warp, then per block in shared memory, and each block adds its
// sums to one of kCopies copies in global memory: one atomic per warp on a single global address
// serialised there and cost more than the filter itself (tens of thousands of warps per pass).
inline constexpr int kCopies = 16;

__device__ inline int lane_id() { return int(threadIdx.x & 31u); }

// Zeroes the block's counters; every thread of the block calls it.
__device__ inline void block_counters_init(unsigned* block) {
  for (int k = int(threadIdx.x); k < kCounters; k += int(blockDim.x)) block[k] = 0;
  __syncthreads();
}
// Adds the block's counters to the global copies; every thread of the block calls it.
__device__ inline void block_counters_flush(const unsigned* block, unsigned long long* counters) {
  __syncthreads();
  for (int k = int(threadIdx.x); k < kCounters; k += int(blockDim.x)) {
    if (block[k] == 0) continue;
    unsigned long long* c = &counters[(blockIdx.x % kCopies) * kCounters + k];
    if (k == kProbesMax) {
      atomicMax(c, (unsigned long long)block[k]);
    } else {
      atomicAdd(c, (unsigned long long)block[k]);
    }
  }
}
// Adds the values of the lanes of `mask` to the block's counter (the lowest lane of mask adds).
__device__ inline void warp_add(unsigned mask, unsigned* counter, unsigned value) {
  const unsigned total = __reduce_add_sync(mask, value);
  if (lane_id() == __ffs(mask) - 1 && total != 0) atomicAdd(counter, total);
}
__device__ inline void warp_max(unsigned mask, unsigned* counter, unsigned value) {
  const unsigned m = __reduce_max_sync(mask, value);
  if (lane_id() == __ffs(mask) - 1 && m != 0) atomicMax(counter, m);
}

__device__ inline size_t thread_index() { return size_t(blockIdx.x) * blockDim.x + threadIdx.x; }

// Whether slot i holds a record of its path.
__device__ inline bool valid_slot(const VertexBufferView& b, size_t i) {
  return i < b.slots() && int(i / b.paths) < int(b.count[i % b.paths]);  // record i / paths of path i % paths
}

inline unsigned blocks_for(size_t n) { return unsigned((n + kBlock - 1) / kBlock); }

}  // namespace pathspace::gpu::filter_kernels
