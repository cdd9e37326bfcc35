// The voxel hash table of the hashed filter (Binder et al. 2021, sec. 3.2): inserted keys are found
// again, concurrent accumulation gives exact sums and counts, and a full table or an exhausted probe
// window is reported (slot -1) instead of corrupting another key's cell.
#include <atomic>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "pathspace/filters/hashed/voxel_hash_table.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace {
namespace {

VoxelKey key_number(int i) {
  VoxelKey k;
  k.cell[0] = i % 97 - 48;
  k.cell[1] = (i / 97) % 89 - 44;
  k.cell[2] = i / (97 * 89);
  k.level = int16_t(i % 3 - 1);
  k.normal_bin = uint16_t(1 + i % 5);
  k.layer = uint8_t(i % 2);
  return k;
}

TEST(VoxelHashTable, EveryInsertedKeyIsFoundAgain) {
  VoxelHashTable table(1 << 14, 16);
  const VoxelHashTableView view = table.view();
  constexpr int kKeys = 4000;  // 24% occupancy
  std::vector<int64_t> slot(kKeys);
  for (int i = 0; i < kKeys; ++i) {
    slot[i] = view.find_or_insert(hash_voxel_key(key_number(i), NormalKeyMode::key)).slot;
    ASSERT_GE(slot[i], 0) << i;
  }
  std::set<int64_t> distinct(slot.begin(), slot.end());
  EXPECT_EQ(distinct.size(), size_t(kKeys)) << "two keys share a cell (fingerprint collision?)";
  for (int i = 0; i < kKeys; ++i) {
    EXPECT_EQ(view.find(hash_voxel_key(key_number(i), NormalKeyMode::key)).slot, slot[i]);
    EXPECT_EQ(view.find_or_insert(hash_voxel_key(key_number(i), NormalKeyMode::key)).slot, slot[i]);
  }
  EXPECT_EQ(table.occupancy().occupied, uint64_t(kKeys));
  VoxelKey absent = key_number(kKeys + 17);
  absent.cell[2] = 1 << 20;
  EXPECT_LT(view.find(hash_voxel_key(absent, NormalKeyMode::key)).slot, 0);
}

TEST(VoxelHashTable, ConcurrentAccumulationIsExact) {
  VoxelHashTable table(1 << 12, 16);
  const VoxelHashTableView view = table.view();
  constexpr int kKeys = 300, kAddsPerKey = 1000;
  std::atomic<int> failures{0};
  // Many threads insert the same keys in interleaved order and add value (key + 1) / 8 each time.
  parallel_for(size_t(kKeys) * kAddsPerKey, 64, [&](size_t begin, size_t end) {
    for (size_t n = begin; n < end; ++n) {
      const int k = int((n * 7919) % kKeys);
      const ProbeResult r = view.find_or_insert(hash_voxel_key(key_number(k), NormalKeyMode::key));
      if (r.slot < 0) {
        ++failures;
        continue;
      }
      uint64_t fixed[3];
      ASSERT_TRUE(to_fixed_point(Rgb(float(k + 1) / 8.f, 1.f, 0.f), fixed));
      view.add(uint64_t(r.slot), fixed);
    }
  });
  EXPECT_EQ(failures.load(), 0);
  for (int k = 0; k < kKeys; ++k) {
    const ProbeResult r = view.find(hash_voxel_key(key_number(k), NormalKeyMode::key));
    ASSERT_GE(r.slot, 0);
    const VoxelCell& c = view.cells[r.slot];
    EXPECT_EQ(c.count, uint64_t(kAddsPerKey));
    const Rgb mean = from_fixed_point(c.sum, c.count);
    EXPECT_EQ(mean.r, float(k + 1) / 8.f);  // exactly representable: fixed point is exact
    EXPECT_EQ(mean.g, 1.f);
    EXPECT_EQ(mean.b, 0.f);
  }
}

TEST(VoxelHashTable, ProbeLimitFailsCleanlyInsideOneCacheLine) {
  VoxelHashTable table(64, 4);  // four lines of 16 fingerprints, at most 4 probes
  const VoxelHashTableView view = table.view();
  // Fill one home line's window: keys whose home index falls into line 0 at offset 0.
  std::vector<VoxelHash> same_home;
  for (int i = 0; same_home.size() < 6; ++i) {
    VoxelHash h = hash_voxel_key(key_number(i), NormalKeyMode::key);
    if ((h.index & 63) == 0) same_home.push_back(h);
  }
  for (int i = 0; i < 4; ++i) {
    const ProbeResult r = view.find_or_insert(same_home[i]);
    EXPECT_EQ(r.slot, i) << "linear probing from the home slot";
    EXPECT_EQ(r.probes, i + 1);
  }
  const ProbeResult full = view.find_or_insert(same_home[4]);
  EXPECT_EQ(full.slot, -1);
  EXPECT_EQ(full.probes, 4);
  EXPECT_EQ(view.find(same_home[5]).slot, -1);
  // The failed key did not take over another key's cell.
  for (int i = 0; i < 4; ++i) EXPECT_EQ(view.find(same_home[i]).slot, i);
}

TEST(VoxelHashTable, ProbingWrapsInsideTheHomeCacheLine) {
  VoxelHashTable table(64, 16);
  const VoxelHashTableView view = table.view();
  for (int j = 0; j < 16; ++j) EXPECT_EQ(view.probe_slot(16 + 14, j), 16 + (14 + j) % 16) << j;
  VoxelHashTable linear(64, 20);  // beyond a line: plain linear probing modulo the table
  for (int j = 0; j < 20; ++j) EXPECT_EQ(linear.view().probe_slot(60, j), (60 + j) % 64) << j;
}

TEST(VoxelHashTable, FullTableReportsFailureForEveryNewKey) {
  VoxelHashTable table(16, 16);
  const VoxelHashTableView view = table.view();
  int inserted = 0, failed = 0;
  for (int i = 0; i < 40; ++i) (view.find_or_insert(hash_voxel_key(key_number(i), NormalKeyMode::key)).slot >= 0 ? inserted : failed)++;
  EXPECT_EQ(inserted, 16);
  EXPECT_EQ(failed, 24);
  EXPECT_EQ(table.occupancy().occupied, 16u);
  table.clear();
  EXPECT_EQ(table.occupancy().occupied, 0u);
}

TEST(VoxelHashTable, FixedPointRejectsWhatItCannotSum) {
  uint64_t f[3];
  EXPECT_FALSE(to_fixed_point(Rgb(-1e-3f, 0.f, 0.f), f));
  EXPECT_FALSE(to_fixed_point(Rgb(NAN, 0.f, 0.f), f));
  EXPECT_FALSE(to_fixed_point(Rgb(INFINITY, 0.f, 0.f), f));
  EXPECT_FALSE(to_fixed_point(Rgb(kMaxAccumulatedValue * 2.f, 0.f, 0.f), f));
  EXPECT_TRUE(to_fixed_point(Rgb(kMaxAccumulatedValue, 0.f, 1.f), f));
}

}  // namespace
}  // namespace pathspace
