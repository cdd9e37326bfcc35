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

#include "pathspace/filters/hashed_filter.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace {

namespace {
constexpr uint64_t kWindow = kFingerprintsPerLine;
}  // namespace

void HashedFilter::settle_overflows(const VertexBuffer& b, uint64_t pass_hash) {
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
  if (failed.empty()) return;
  // A cell is new this pass when the table is cleared every pass, or when it has no history yet.
  const auto is_new = [&](uint64_t c) { return !history_ || !(history_->at(c).weight > 0.f); };
  std::vector<std::pair<uint64_t, uint32_t>> assigned;  // (cell, winning key) for cells that change hands
  for (auto& [window, keys] : failed_keys) {
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    std::vector<std::pair<uint32_t, uint64_t>> holders;  // (key, cell) of the window's new cells
    for (uint64_t c = window * kWindow; c < (window + 1) * kWindow; ++c)
      if (view.fingerprints[c] != kEmptyFingerprint && is_new(c)) holders.push_back({view.fingerprints[c] & view.key_mask, c});
    // The winners: the smallest keys among holders and failed keys, as many as there are new cells.
    std::vector<uint32_t> all = keys;
    for (const auto& h : holders) all.push_back(h.first);
    std::sort(all.begin(), all.end());
    all.resize(std::min(all.size(), holders.size()));
    std::vector<uint64_t> freed;
    for (const auto& [key, cell] : holders)
      if (!std::binary_search(all.begin(), all.end(), key)) freed.push_back(cell);
    size_t next = 0;
    for (const uint32_t key : keys)
      if (std::binary_search(all.begin(), all.end(), key) && next < freed.size()) assigned.push_back({freed[next++], key});
  }
  if (assigned.empty()) return;
  std::map<uint32_t, uint64_t> cell_of_key;
  for (const auto& [cell, key] : assigned) cell_of_key[key] = cell;
  for (const auto& [cell, key] : assigned) {
    view.fingerprints[cell] = key;
    view.cells[cell] = VoxelCell{};
  }
  // The losers' vertices fall back to their own contributions ...
  std::vector<uint8_t> reassigned(size_t(table_.cells()), 0);
  for (const auto& a : assigned) reassigned[a.first] = 1;
  std::atomic<uint64_t> lost{0};
  parallel_for(b.paths(), 2048, [&](size_t begin, size_t end) {
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
  for (const auto& [i, key] : failed) {
    const auto it = cell_of_key.find(key);
    if (it == cell_of_key.end()) continue;
    uint64_t fixed[3];
    if (!to_fixed_point(b.contribution[i], fixed)) continue;  // not accumulated (never the case for a failure)
    view.add(it->second, fixed);
    slots_[i] = int32_t(it->second);
    ++won;
  }
  stats_.probe_failures = stats_.probe_failures + lost.load() - won;
  ++stats_.settled_windows;
}

}  // namespace pathspace
