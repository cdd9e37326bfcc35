// Deterministic overflow of the hashed filter's probe windows (docs/hashed-filter.md, "Determinism").
// When more new keys want a probe window (one cache line of fingerprints) than it has free cells,
// the keys that got a cell during accumulation are the ones whose threads came first. After the
// pass, each overflowing window is settled by a rule that does not depend on timing: among all keys
// that wanted a new cell in it this pass, those with the smallest fingerprints keep or get the
// window's new cells; the others' vertices keep their own contributions (probe-limit fallbacks).
// Sums are integers, so re-adding vertices in any order gives the same cells.
#include <algorithm>
#include <atomic>
#include <map>
#include <vector>

#include "pathspace/filters/hashed/hashed_filter.h"
#include "pathspace/filters/hashed/overflow_settling.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace {

namespace {
constexpr uint64_t kWindow = kFingerprintsPerLine;
}  // namespace
// The decision itself is filters/hashed/overflow_settling.cpp, shared with the GPU filter.

bool HashedFilter::settle_overflows(const VertexBuffer& b, uint64_t pass_hash) {
  const VoxelHashTableView view = table_.view();
  // Per window: the stored fingerprints of the keys that failed, and of each one's vertices.
  std::map<uint64_t, std::vector<uint32_t>> failed_keys;  // window -> keys (sorted, unique below)
  std::vector<std::pair<size_t, uint32_t>> failed;        // (record slot, key)
  for (size_t path = 0; path < b.paths(); ++path)
    for (int r = 0; r < b.count[path]; ++r) {
      const size_t i = b.slot(path, r);
      if (slots_[i] != -1) continue;
      const VoxelHash h = hash_voxel_key(key_for_pass(b, i, pass_hash), settings_.key.normal);
      const uint32_t key = view.stored_fingerprint(h);
      failed_keys[(h.index & view.mask) / kWindow].push_back(key);
      failed.push_back({i, key});
    }
  if (failed.empty()) return false;
  // A cell is new this pass when the table is cleared every pass, or when it has no history yet.
  const auto is_new = [&](uint64_t c) { return !history_ || !(history_->at(c).weight > 0.f); };
  const OverflowDecision d = decide_overflows(std::move(failed_keys), view.key_mask,
                                              [&](uint64_t c) { return view.fingerprints[c]; }, is_new);
  const auto& assigned = d.assigned;
  const auto& cell_of_key = d.cell_of_key;
  if (assigned.empty()) return false;
  for (const auto& [cell, key] : assigned) {
    view.fingerprints[cell] = key;
    view.cells[cell] = VoxelCell{};
  }
  // The losers' vertices fall back to their own contributions ...
  std::vector<uint8_t> reassigned(size_t(table_.cells()), 0);
  for (const auto& a : assigned) reassigned[a.first] = 1;
  std::atomic<uint64_t> lost{0};
  parallel_for(b.paths(), kGrain, [&](size_t begin, size_t end) {
    uint64_t n = 0;
    for (size_t path = begin; path < end; ++path)
      for (int r = 0; r < b.count[path]; ++r) {
        const size_t i = b.slot(path, r);
        if (slots_[i] >= 0 && reassigned[size_t(slots_[i])]) slots_[i] = -1, ++n;
      }
    lost += n;
  });
  // ... and the winners' vertices fill their cells.
  uint64_t won = 0;
  const HashedStepSettings steps = step_settings(settings_);
  for (const auto& [i, key] : failed) {
    const auto it = cell_of_key.find(key);
    if (it == cell_of_key.end()) continue;
    uint64_t fixed[3];
    if (!accumulated_fixed_point(steps, b.contribution[i], fixed)) continue;  // not accumulated (never the case for a failure)
    view.add(it->second, fixed);
    slots_[i] = int32_t(it->second);
    table_records_.local().push_back(i);  // a vertex of one of the step's cells
    ++won;
  }
  pass_counts_.failures = pass_counts_.failures + lost.load() - won;
  return true;
}

}  // namespace pathspace
