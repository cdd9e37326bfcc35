// What a voxel of the hashed filter's table keeps from earlier steps (2021 paper sec. 3.4), beside
// the table's per-step sums. A step is one pass: one frame of an animation rendered at 1 spp.
//  * Blending (3.4.1): a vertex looks up its voxel's history combined with this step's average,
//    by temporal integration (alpha = N_old / (N_old + N_new)), an exponential moving average, or
//    the hybrid of fig. 9c: integration scaled down to 0 as the voxel's measured change (temporal
//    finite differences of re-traced paths, HashedFilter::temporal_probes) reaches a threshold;
//    with rectify (beyond the paper) a probed voxel's history is first scaled by its re-traced
//    paths' luminance ratio now / before.
//  * Folding: after the step's lookups, every voxel used in the step stores that combination as its
//    new history, its weight capped at max_frames steps' worth of vertices.
//  * Eviction (3.4.3): the top kPriorityShift.. bits of each fingerprint word hold a priority
//    (recency in the high nibble, log2 of the weight in the low one), so the window's smallest word
//    is the cell to evict and pseudo-random low bits spread evictions uniformly over the scene. The
//    paper decides this with one atomicMin while inserting; here it is decided between steps, one
//    probe window at a time, which keeps every frame independent of thread timing (bit-identical
//    images for any thread count).
// The per-cell arithmetic is temporal_steps.h, which the GPU filter runs too.
#pragma once

#include <cstdint>
#include <vector>

#include "pathspace/filters/hashed/temporal_settings.h"
#include "pathspace/filters/hashed/temporal_steps.h"
#include "pathspace/filters/hashed/voxel_hash_table.h"
#include "pathspace/math/rgb.h"

namespace pathspace {

// Hybrid blending: what the re-traced paths of one step found in a cell.
struct VoxelChange {
  float difference = 0.f;  // sum of |luminance now - luminance in the previous frame|
  float magnitude = 0.f;   // sum of the larger of the two
  float now = 0.f, before = 0.f;  // sums of the luminance now and in the previous frame (--temporal-rectify)
};

struct TemporalStepStats {
  uint64_t evicted = 0;       // cells evicted after the step
  uint64_t occupied = 0;      // cells holding a key after eviction
  uint64_t folded = 0;        // cells used in the step
  double fold_ms = 0.0;       // folding, priorities and eviction
};

class TemporalHistory {
 public:
  TemporalHistory(const TemporalSettings& settings, uint64_t cells);

  const TemporalSettings& settings() const { return settings_; }
  size_t bytes() const { return history_.size() * sizeof(VoxelHistory); }
  const VoxelHistory& at(uint64_t slot) const { return history_[slot]; }
  const std::vector<VoxelHistory>& cells() const { return history_; }
  // Sec. 3.4.2: gives the new cell `slot` (no history) the history `from` (serial per cell; before
  // the step's lookups).
  void transfer(uint64_t slot, const VoxelHistory& from) { history_[slot] = from; }
  void restore(std::vector<VoxelHistory> cells) { history_ = std::move(cells); }

  // The estimate of a cell for this step from its history and this step's sum and count (count > 0);
  // *alpha receives the weight of the history (0: none).
  Rgb blend(uint64_t slot, const VoxelCell& current, float* alpha) const;
  // Hybrid: a re-traced path in cell `slot` whose contribution's luminance was `before` in the
  // previous frame and is `now` (serial; before the step's lookups).
  void add_change(uint64_t slot, float before, float now);
  // --temporal-rectify, after the step's add_change calls and before its lookups: each probed cell's
  // history mean times min(sum now / sum before, kMaxRectification) (serial, in the order the cells
  // were first probed).
  void rectify();
  // The relative change of a cell: this step's probes', else the last one measured.
  float change(uint64_t slot) const;
  // After the step's lookups: folds each used cell into its history, writes the priorities into the
  // fingerprint words and evicts (see above). `step` counts from 1.
  TemporalStepStats end_step(const VoxelHashTableView& table, uint32_t step);

  // The priority byte of a cell: recency (15 - steps since use, at least 0) above min(15, log2 weight).
  static uint32_t priority(const VoxelHistory& h, uint32_t step) { return temporal_priority(h, step); }

 private:
  TemporalSettings settings_;
  std::vector<VoxelHistory> history_;
  std::vector<VoxelChange> change_;     // hybrid: this step's probes per cell (cleared by end_step)
  std::vector<uint64_t> changed_cells_;  // the cells with probes in this step
};

}  // namespace pathspace
