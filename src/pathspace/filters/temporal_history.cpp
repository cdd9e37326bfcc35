#include "pathspace/filters/temporal_history.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>

#include "pathspace/parallel/parallel_for.h"

namespace pathspace {

namespace {

constexpr uint64_t kWindow = kFingerprintsPerLine;  // eviction works one cache line of fingerprints at a time

}  // namespace

TemporalHistory::TemporalHistory(const TemporalSettings& settings, uint64_t cells)
    : settings_(settings), history_(cells), change_(settings.mode == TemporalMode::hybrid ? cells : 0) {}

void TemporalHistory::add_change(uint64_t slot, float before, float now) {
  VoxelChange& c = change_[slot];
  if (c.magnitude == 0.f && c.difference == 0.f) changed_cells_.push_back(slot);
  c.difference += std::fabs(now - before);
  c.magnitude += std::max(std::fabs(now), std::fabs(before));
  if (c.magnitude == 0.f && c.difference == 0.f) c.magnitude = 1e-30f;  // black both times: probed, no change
}

float TemporalHistory::change(uint64_t slot) const {
  if (!change_.empty()) {
    const VoxelChange& c = change_[slot];
    if (c.magnitude > 0.f) return c.difference / c.magnitude;
  }
  return history_[slot].change;
}

Rgb TemporalHistory::blend(uint64_t slot, const VoxelCell& current, float* alpha) const {
  const Rgb fresh = from_fixed_point(current.sum, current.count);
  const VoxelHistory& h = history_[slot];
  if (!(h.weight > 0.f)) {
    *alpha = 0.f;
    return fresh;
  }
  double a = settings_.mode == TemporalMode::ema ? double(settings_.alpha)
                                                 : double(h.weight) / (double(h.weight) + double(current.count));
  if (settings_.mode == TemporalMode::hybrid)  // fig. 9c: from integration (no change) to 0 (changed)
    a *= std::max(0.0, 1.0 - double(change(slot)) / double(settings_.change_threshold));
  *alpha = float(a);
  return {float(a * double(h.mean[0]) + (1.0 - a) * double(fresh.r)), float(a * double(h.mean[1]) + (1.0 - a) * double(fresh.g)),
          float(a * double(h.mean[2]) + (1.0 - a) * double(fresh.b))};
}

uint32_t TemporalHistory::priority(const VoxelHistory& h, uint32_t step) {
  const uint32_t age = step - h.last_step;
  const uint32_t recency = 15u - std::min<uint32_t>(age, 15u);
  const uint64_t w = uint64_t(std::max(0.f, h.weight)) + 1;
  const uint32_t size = std::min<uint32_t>(15u, uint32_t(std::bit_width(w) - 1));
  return recency << 4 | size;
}

TemporalStepStats TemporalHistory::end_step(const VoxelHashTableView& table, uint32_t step) {
  const auto t0 = std::chrono::steady_clock::now();
  const uint64_t cells = table.mask + 1;
  const uint32_t keep = uint32_t(std::clamp(std::floor(double(settings_.occupancy) * double(kWindow)), 1.0, double(kWindow)));
  std::atomic<uint64_t> evicted_total{0}, occupied_total{0}, folded_total{0};
  parallel_for(size_t(cells / kWindow), 1024, [&](size_t begin, size_t end) {
    uint64_t evicted = 0, occupied = 0, folded = 0;
    for (size_t w = begin; w < end; ++w) {
      const uint64_t first = uint64_t(w) * kWindow;
      uint32_t used = 0;
      for (uint64_t c = first; c < first + kWindow; ++c) {
        uint32_t& word = table.fingerprints[c];
        if (word == kEmptyFingerprint) continue;
        VoxelHistory& h = history_[c];
        const VoxelCell& cell = table.cells[c];
        if (cell.count > 0) {  // used in this step: its blend becomes the history
          float alpha = 0.f;
          const Rgb mean = blend(c, cell, &alpha);
          h.mean[0] = mean.r, h.mean[1] = mean.g, h.mean[2] = mean.b;
          // Hybrid: the history weight behind the alpha used, N' = alpha n / (1 - alpha), so that
          // an unchanged voxel integrates and a changed one starts again from this step.
          double weight = settings_.mode == TemporalMode::hybrid && alpha < 1.f ? double(cell.count) / (1.0 - double(alpha))
                                                                               : double(h.weight) + double(cell.count);
          if (settings_.max_frames > 0) weight = std::min(weight, double(settings_.max_frames) * double(cell.count));
          h.weight = float(weight);
          h.last_step = step;
          h.change = change(c);
          ++folded;
        }
        const bool stale = settings_.eviction == EvictionPolicy::stale && step - h.last_step > uint32_t(settings_.stale_frames);
        if (stale) {
          word = kEmptyFingerprint;
          h = VoxelHistory{};
          ++evicted;
          continue;
        }
        word = priority(h, step) << kPriorityShift | (word & kKeyBitsMask);
        ++used;
      }
      if (settings_.eviction != EvictionPolicy::stale) {
        // Down to the target fill: the smallest word (priority), or the least recently used with the
        // smallest word among equals (lru).
        for (; used > keep; --used, ++evicted) {
          uint64_t victim = first;
          bool found = false;
          for (uint64_t c = first; c < first + kWindow; ++c) {
            const uint32_t word = table.fingerprints[c];
            if (word == kEmptyFingerprint) continue;
            const VoxelHistory& h = history_[c];
            const VoxelHistory& v = history_[victim];
            const bool lower = !found || (settings_.eviction == EvictionPolicy::lru
                                              ? (h.last_step < v.last_step || (h.last_step == v.last_step && word < table.fingerprints[victim]))
                                              : word < table.fingerprints[victim]);
            if (lower) victim = c, found = true;
          }
          table.fingerprints[victim] = kEmptyFingerprint;
          history_[victim] = VoxelHistory{};
        }
      }
      occupied += used;
    }
    evicted_total += evicted;
    occupied_total += occupied;
    folded_total += folded;
  });
  for (const uint64_t c : changed_cells_) change_[c] = VoxelChange{};
  changed_cells_.clear();
  TemporalStepStats s;
  s.evicted = evicted_total;
  s.occupied = occupied_total;
  s.folded = folded_total;
  s.fold_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return s;
}

}  // namespace pathspace
