// Which keys get an overflowing probe window's new cells (docs/hashed-filter.md, "Determinism";
// sec. 3.2.2's bounded probing): among all keys that wanted a new cell in the window this pass, the
// smallest stored fingerprints. The decision alone, on host data, so that the CPU filter
// (hashed_filter_overflow.cpp) and the GPU filter (filters/hashed/cuda_hashed_filter.cu) settle alike. Plain
// C++ without TBB or fmt (the standalone GPU benchmark compiles it).
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <utility>
#include <vector>

namespace pathspace {

struct OverflowDecision {
  std::vector<std::pair<uint64_t, uint32_t>> assigned;  // (cell, winning key): cells that change hands
  std::map<uint32_t, uint64_t> cell_of_key;              // each winning key's new cell
};

// failed_keys: per window (cell / kFingerprintsPerLine), the stored fingerprints of the keys whose
// insertion failed (any order, repeats allowed). fingerprint(c): the word in cell c; is_new(c):
// whether cell c's key arrived this pass (always, for a table cleared every pass).
OverflowDecision decide_overflows(std::map<uint64_t, std::vector<uint32_t>> failed_keys, uint32_t key_mask,
                                  const std::function<uint32_t(uint64_t)>& fingerprint,
                                  const std::function<bool(uint64_t)>& is_new);

}  // namespace pathspace
