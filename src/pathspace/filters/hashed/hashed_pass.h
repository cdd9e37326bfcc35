// One pass of hashed path space filtering (Binder, Fricke, Keller 2021, sec. 3.1-3.4), written once
// for both devices. HashedFilter (TBB, host memory) and CudaHashedFilter (kernels, device memory)
// each implement HashedPassSteps; which steps run for the settings, in which order, and how the
// pass is counted and timed are decided here only. What a step does to one vertex, cell or probe
// window is shared below the devices too (hashed_filter_steps.h, temporal_steps.h,
// overflow_settling.h); how a device goes over many of them is its own (a combining cache per
// thread on the CPU, warp aggregation on the GPU). A feature one device lacks is refused for it by
// check_hashed_filter_settings, before any pass.
#pragma once

#include <cstdint>

#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/filters/hashed/hashed_filter_stats.h"

namespace pathspace {

// The points of a pass where the device notes the time (steady clock on the CPU, CUDA events).
enum class PassMark : int { begin, cleared, accumulated, settled, listed, transferred, looked_up, end, count };

// What the steps of one pass counted, on either device.
struct HashedPassCounts {
  uint64_t vertices = 0, not_accumulated = 0;
  uint64_t insertions = 0, probes = 0, probes_max = 0;  // table insertions and the cells they inspected
  uint64_t failures = 0;                                // after settling: kept their own contribution
  uint64_t low_count = 0, neighbour_lookups = 0, multi_level_used = 0;
  uint64_t occupied_cells = 0;
  double expected_fingerprint_collisions = 0.0;  // the CPU's estimate; 0 on the GPU
  // --temporal (sec. 3.4): blended lookups and their alphas (fixed point 2^-32: the sum does not
  // depend on the order), level transfers, and the folding after the step.
  uint64_t blended = 0, alpha_fixed = 0, from_finer = 0, from_coarser = 0, folded = 0, evicted = 0;
};

// The steps of a pass over one vertex buffer, as one device runs them. The buffer, the output and
// the device's stream are the implementation's; calls come in the order of run_hashed_pass.
class HashedPassSteps {
 public:
  virtual ~HashedPassSteps() = default;
  virtual void mark(PassMark at) = 0;
  // Empties the table's sums (with --temporal its keys stay, so that they find their history).
  virtual void clear() = 0;
  // Keys and accumulation of every vertex (sec. 3.1-3.2, the coarse level of 3.3.2).
  virtual void accumulate(uint64_t pass_hash) = 0;
  // The vertices that found no cell within the probe limit in accumulate().
  virtual uint64_t probe_failures() = 0;
  // Full probe windows settled by fingerprint (hashed_filter_overflow.cpp); true when cells
  // changed hands.
  virtual bool settle_overflows(uint64_t pass_hash, uint64_t failures) = 0;
  // The cells the step used, once each, for the steps that visit cells (the CPU's; the GPU's
  // kernels visit the whole table).
  virtual void list_step_cells() = 0;
  // Sec. 3.4.2: new cells take their finer or coarser voxels' history. `step` counts from 0.
  virtual void transfer_levels(uint64_t pass_hash, uint32_t step) = 0;
  // Sec. 3.4.1, hybrid: the re-traced paths' changes into their cells, and this frame's paths that
  // the next frame re-traces.
  virtual void exchange_probes(uint64_t seed, uint32_t pass) = 0;
  // Every vertex's estimate (sec. 3.3; blended with the history, 3.4.1; the level of 3.1.3).
  virtual void lookup(uint64_t pass_hash) = 0;
  // Sec. 3.4.3: folding, priorities and eviction after the step; `step` counts from 1.
  virtual void end_step(uint32_t step) = 0;
  // Waits for the pass and returns its counts; then the time between two marks.
  virtual HashedPassCounts finish() = 0;
  virtual double milliseconds(PassMark from, PassMark to) const = 0;
};

// Runs one pass and adds it to `stats`.
void run_hashed_pass(HashedPassSteps& steps, const HashedFilterSettings& settings, uint64_t seed, uint32_t pass,
                     HashedFilterStats* stats);

}  // namespace pathspace
