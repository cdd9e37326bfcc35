#include "pathspace/filters/hashed/temporal_history.h"

#include <algorithm>
#include <atomic>
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
  c.now += now;
  c.before += before;
  if (c.magnitude == 0.f && c.difference == 0.f) c.magnitude = 1e-30f;  // black both times: probed, no change
}

void TemporalHistory::rectify() {
  for (const uint64_t slot : changed_cells_) {
    const VoxelChange& c = change_[slot];
    if (!(c.before > 0.f) || !(c.now >= 0.f)) continue;  // nothing to scale: the change alone decides
    const float r = std::min(c.now / c.before, kMaxRectification);
    for (float& m : history_[slot].mean) m *= r;
  }
}

float TemporalHistory::change(uint64_t slot) const {
  if (!change_.empty()) {
    const VoxelChange& c = change_[slot];
    if (c.magnitude > 0.f) return c.difference / c.magnitude;
  }
  return history_[slot].change;
}

Rgb TemporalHistory::blend(uint64_t slot, const VoxelCell& current, float* alpha) const {
  return temporal_blend(settings_, history_[slot], current, settings_.mode == TemporalMode::hybrid ? change(slot) : 0.f, alpha);
}

TemporalStepStats TemporalHistory::end_step(const VoxelHashTableView& table, uint32_t step) {
  const auto t0 = std::chrono::steady_clock::now();
  const uint64_t cells = table.mask + 1;
  const uint32_t keep = temporal_window_keep(settings_);
  std::atomic<uint64_t> evicted_total{0}, occupied_total{0}, folded_total{0};
  const auto change_of = [this](uint64_t c) { return change(c); };
  parallel_for(size_t(cells / kWindow), 1024, [&](size_t begin, size_t end) {
    uint64_t evicted = 0, occupied = 0, folded = 0;
    for (size_t w = begin; w < end; ++w) {
      const TemporalWindowCounts n = fold_and_evict_window(settings_, keep, table, history_.data(), uint64_t(w) * kWindow, step, change_of);
      evicted += n.evicted;
      occupied += n.occupied;
      folded += n.folded;
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
