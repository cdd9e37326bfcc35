// The per-cell steps of the hashed filter's reuse of its table across frames (Binder et al. 2021,
// sec. 3.4) as PS_HD functions over VoxelHashTableView and a plain array of histories: the CPU filter
// (TemporalHistory, HashedFilter::transfer_levels) and the GPU filter (filters/hashed/cuda_hashed_filter.cu) run
// the same code, so their frames are the same bits. What the steps mean is in temporal_history.h.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "pathspace/base/platform.h"
#include "pathspace/filters/hashed/temporal_settings.h"
#include "pathspace/filters/hashed/voxel_hash_table_view.h"
#include "pathspace/math/rgb.h"

#if !defined(__CUDA_ARCH__)
#include <bit>
#endif

namespace pathspace {

struct VoxelHistory {
  float mean[3] = {0.f, 0.f, 0.f};
  float weight = 0.f;      // N_old: vertices behind the mean (0: no history)
  uint32_t last_step = 0;  // the step that last used the cell
  float change = 0.f;      // hybrid: the last relative change measured by re-traced paths
};

// Sec. 3.4.1: a cell's estimate for this step from its history and this step's sum and count
// (count > 0); *alpha receives the weight of the history (0: none). `change` (hybrid only): the
// cell's relative change measured by re-traced paths.
PS_INLINE Rgb temporal_blend(const TemporalSettings& s, const VoxelHistory& h, const VoxelCell& current, float change,
                             float* alpha) {
  const Rgb fresh = from_fixed_point(current.sum, current.count);
  if (!(h.weight > 0.f)) {
    *alpha = 0.f;
    return fresh;
  }
  double a = s.mode == TemporalMode::ema ? double(s.alpha) : double(h.weight) / (double(h.weight) + double(current.count));
  if (s.mode == TemporalMode::hybrid) {  // fig. 9c: from integration (no change) to 0 (changed)
    const double unchanged = 1.0 - double(change) / double(s.change_threshold);
    a *= unchanged > 0.0 ? unchanged : 0.0;
  }
  *alpha = float(a);
  return {float(a * double(h.mean[0]) + (1.0 - a) * double(fresh.r)), float(a * double(h.mean[1]) + (1.0 - a) * double(fresh.g)),
          float(a * double(h.mean[2]) + (1.0 - a) * double(fresh.b))};
}

// floor(log2(w)) for w >= 1.
PS_INLINE uint32_t floor_log2(uint64_t w) {
#if defined(__CUDA_ARCH__)
  return uint32_t(63 - __clzll((long long)w));
#else
  return uint32_t(std::bit_width(w) - 1);
#endif
}

// Sec. 3.4.3: the priority byte of a cell, recency (15 - steps since use, at least 0) above
// min(15, log2 weight).
PS_INLINE uint32_t temporal_priority(const VoxelHistory& h, uint32_t step) {
  const uint32_t age = step - h.last_step;
  const uint32_t recency = 15u - (age < 15u ? age : 15u);
  const uint64_t w = uint64_t(h.weight > 0.f ? h.weight : 0.f) + 1;
  const uint32_t size = floor_log2(w);
  return recency << 4 | (size < 15u ? size : 15u);
}

// How many cells of a probe window the priority and lru policies keep (the target fill).
// (Host only: the filters pass it to their steps.)
inline uint32_t temporal_window_keep(const TemporalSettings& s) {
  return uint32_t(std::clamp(std::floor(double(s.occupancy) * double(kFingerprintsPerLine)), 1.0, double(kFingerprintsPerLine)));
}

struct TemporalWindowCounts {
  uint32_t evicted = 0, occupied = 0, folded = 0;
};

// After a step's lookups, for the probe window (one cache line of fingerprints) starting at cell
// `first`: folds each cell used in the step into its history (its blend becomes the history, the
// weight capped at max_frames steps' worth of vertices), writes the priorities into the fingerprint
// words and evicts (stale cells, or down to `keep` cells by priority or recency). Windows are
// independent: any order of windows gives the same table. change_of(cell): the cell's relative
// change (hybrid; its history's otherwise).
template <class ChangeOf>
PS_INLINE TemporalWindowCounts fold_and_evict_window(const TemporalSettings& s, uint32_t keep, const VoxelHashTableView& table,
                                                     VoxelHistory* history, uint64_t first, uint32_t step, ChangeOf change_of) {
  TemporalWindowCounts n;
  uint32_t used = 0;
  for (uint64_t c = first; c < first + kFingerprintsPerLine; ++c) {
    uint32_t& word = table.fingerprints[c];
    if (word == kEmptyFingerprint) continue;
    VoxelHistory& h = history[c];
    const VoxelCell& cell = table.cells[c];
    if (cell.count > 0) {  // used in this step: its blend becomes the history
      const float change = change_of(c);
      float alpha = 0.f;
      const Rgb mean = temporal_blend(s, h, cell, change, &alpha);
      h.mean[0] = mean.r, h.mean[1] = mean.g, h.mean[2] = mean.b;
      // Hybrid: the history weight behind the alpha used, N' = alpha n / (1 - alpha), so that an
      // unchanged voxel integrates and a changed one starts again from this step.
      double weight = s.mode == TemporalMode::hybrid && alpha < 1.f ? double(cell.count) / (1.0 - double(alpha))
                                                                     : double(h.weight) + double(cell.count);
      if (s.max_frames > 0) {
        const double cap = double(s.max_frames) * double(cell.count);
        weight = cap < weight ? cap : weight;
      }
      h.weight = float(weight);
      h.last_step = step;
      h.change = change;
      ++n.folded;
    }
    if (s.eviction == EvictionPolicy::stale && step - h.last_step > uint32_t(s.stale_frames)) {
      word = kEmptyFingerprint;
      h = VoxelHistory{};
      ++n.evicted;
      continue;
    }
    word = temporal_priority(h, step) << kPriorityShift | (word & kKeyBitsMask);
    ++used;
  }
  if (s.eviction != EvictionPolicy::stale) {
    // Down to the target fill: the smallest word (priority), or the least recently used with the
    // smallest word among equals (lru).
    for (; used > keep; --used, ++n.evicted) {
      uint64_t victim = first;
      bool found = false;
      for (uint64_t c = first; c < first + kFingerprintsPerLine; ++c) {
        const uint32_t word = table.fingerprints[c];
        if (word == kEmptyFingerprint) continue;
        const VoxelHistory& h = history[c];
        const VoxelHistory& v = history[victim];
        const bool lower = !found || (s.eviction == EvictionPolicy::lru
                                          ? (h.last_step < v.last_step || (h.last_step == v.last_step && word < table.fingerprints[victim]))
                                          : word < table.fingerprints[victim]);
        if (lower) victim = c, found = true;
      }
      table.fingerprints[victim] = kEmptyFingerprint;
      history[victim] = VoxelHistory{};
    }
  }
  n.occupied = used;
  return n;
}

// The history of the voxel with this key, if it is in the table and has one.
PS_INLINE bool history_of_key(const VoxelHashTableView& table, const VoxelHistory* history, NormalKeyMode normal,
                              const VoxelKey& key, VoxelHistory* out) {
  const ProbeResult r = table.find(hash_voxel_key(key, normal));
  if (r.slot < 0) return false;
  *out = history[r.slot];
  return out->weight > 0.f;
}

enum class LevelTransfer : uint8_t { none, from_finer, from_coarser };

// Sec. 3.4.2: what a cell new to the table (no history) whose vertices have this key starts from,
// read from the histories as they were before the step. Going coarser, the eight finer voxels' sums
// and counts add up exactly; going finer, the coarser voxel's average with finer_weight times its
// weight (docs/animation.md). `step`: the steps before this one.
PS_INLINE LevelTransfer level_transfer(const TemporalSettings& s, const VoxelHashTableView& table, const VoxelHistory* history,
                                       NormalKeyMode normal, const VoxelKey& key, uint32_t step, VoxelHistory* out) {
  double sum[3] = {0.0, 0.0, 0.0}, weight = 0.0;
  for (int child = 0; child < 8; ++child) {
    VoxelKey k = key;
    k.level = int16_t(key.level - 1);
    for (int a = 0; a < 3; ++a) k.cell[a] = key.cell[a] * 2 + ((child >> a) & 1);
    VoxelHistory h;
    if (!history_of_key(table, history, normal, k, &h)) continue;
    for (int c = 0; c < 3; ++c) sum[c] += double(h.mean[c]) * double(h.weight);
    weight += double(h.weight);
  }
  LevelTransfer kind = LevelTransfer::none;
  *out = VoxelHistory{};
  if (weight > 0.0) {
    for (int c = 0; c < 3; ++c) out->mean[c] = float(sum[c] / weight);
    out->weight = float(weight);
    kind = LevelTransfer::from_finer;
  } else if (s.finer_weight > 0.f && history_of_key(table, history, normal, coarser_key(key), out)) {
    out->weight *= s.finer_weight;
    kind = LevelTransfer::from_coarser;
  } else {
    return LevelTransfer::none;
  }
  out->last_step = step;
  return kind;
}

}  // namespace pathspace
