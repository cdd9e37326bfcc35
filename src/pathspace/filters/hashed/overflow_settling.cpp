#include "pathspace/filters/hashed/overflow_settling.h"

#include <algorithm>

#include "pathspace/filters/hashed/voxel_hash_table_view.h"

namespace pathspace {

OverflowDecision decide_overflows(std::map<uint64_t, std::vector<uint32_t>> failed_keys, uint32_t key_mask,
                                  const std::function<uint32_t(uint64_t)>& fingerprint,
                                  const std::function<bool(uint64_t)>& is_new) {
  constexpr uint64_t kWindow = kFingerprintsPerLine;
  OverflowDecision d;
  for (auto& [window, keys] : failed_keys) {
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    std::vector<std::pair<uint32_t, uint64_t>> holders;  // (key, cell) of the window's new cells
    for (uint64_t c = window * kWindow; c < (window + 1) * kWindow; ++c) {
      const uint32_t f = fingerprint(c);
      if (f != kEmptyFingerprint && is_new(c)) holders.push_back({f & key_mask, c});
    }
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
      if (std::binary_search(all.begin(), all.end(), key) && next < freed.size()) d.assigned.push_back({freed[next++], key});
  }
  for (const auto& [cell, key] : d.assigned) d.cell_of_key[key] = cell;
  return d;
}

}  // namespace pathspace
