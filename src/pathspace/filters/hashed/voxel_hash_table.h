// The owning voxel hash table (host side): storage aligned to cache lines, clearing, and the
// occupancy/probing statistics the filter reports (Binder et al. 2021, sec. 3.2; 2019 fig. 7).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>
#include <memory>

#include "pathspace/base/error.h"
#include "pathspace/filters/hashed/voxel_hash_table_view.h"

namespace pathspace {

struct VoxelTableOccupancy {
  uint64_t cells = 0, occupied = 0;
  // Expected number of pairs of different keys sharing a fingerprint within one probe window:
  // sum over windows of C(n_w, 2) / 2^32 (sec. 3.2.1).
  double expected_fingerprint_collisions = 0.0;
  double occupancy() const { return cells ? double(occupied) / double(cells) : 0.0; }
};

class VoxelHashTable {
 public:
  // cells is rounded up to a power of two (at least one cache line of fingerprints).
  VoxelHashTable(uint64_t cells, int max_probes);

  VoxelHashTableView view() const { return view_; }
  uint64_t cells() const { return view_.mask + 1; }
  size_t bytes() const { return size_t(cells()) * (sizeof(uint32_t) + sizeof(VoxelCell)); }
  void clear();  // parallel
  // Zeroes the sums and counts only, keeping the keys (a table kept across frames).
  void clear_sums();  // parallel
  // clear() or clear_sums() where only the listed cells can hold keys or sums (serial).
  void clear_listed(const std::vector<uint32_t>& slots, bool keys);
  // Fingerprints of kPriorityShift bits, with room for a priority above them (sec. 3.4.3).
  void keep_across_frames() { view_.key_mask = kKeyBitsMask; }
  VoxelTableOccupancy occupancy() const;

 private:
  struct FreeDeleter {
    void operator()(void* p) const;
  };
  std::unique_ptr<uint32_t[], FreeDeleter> fingerprints_;
  std::unique_ptr<VoxelCell[], FreeDeleter> cells_;
  VoxelHashTableView view_;
};

inline uint64_t next_power_of_two(uint64_t x) {
  uint64_t p = 1;
  while (p < x) p <<= 1;
  return p;
}

// The size of a table asked for `requested` cells: a power of two, at least one cache line of
// fingerprints. Throws pathspace::Error beyond 2^31 cells (the filters keep each vertex's cell as a
// signed 32-bit index; negative: not in the table).
inline uint64_t voxel_table_cells(uint64_t requested) {
  const uint64_t n = next_power_of_two(requested < kFingerprintsPerLine ? kFingerprintsPerLine : requested);
  if (n > (uint64_t(1) << 31)) throw Error("the voxel hash table is limited to 2^31 cells");
  return n;
}

}  // namespace pathspace
