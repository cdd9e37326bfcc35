// Per-thread combining of vertices that fall into the same voxel before they reach the shared
// table (Binder et al. 2021, sec. 3.2 accumulates every vertex with atomics; on a CPU those atomics
// dominate once the keys are cheap). A direct-mapped cache of open voxels holds each one's partial
// sums; an entry is added to its table cell with one set of atomics when it is evicted or at the
// end of the pass. Integer (fixed-point) sums make the result identical to adding one by one.
// Evicted sums wait in a short queue while their table cell is prefetched: a locked add on a cell
// that is not in cache stalls the core for the whole memory latency (locked instructions do not
// overlap with other loads), which made evictions the main cost for incoherent vertices.
#pragma once

#include <cstdint>
#include <memory>

#include "pathspace/filters/hashed/voxel_hash_table_view.h"

namespace pathspace {

struct LocalVoxelCache {
  // Direct mapped, 32-byte entries (two per cache line, none straddling one): 32768 of them
  // (1 MiB, this CPU's L2) hold the voxels a thread touches in one pass of a 1080p frame (10-25
  // thousand in the filter benchmark) with few conflicts. 40-byte entries straddled a line half of
  // the time, and the second line was a second miss per access.
  static constexpr int kEntries = 32768;
  struct alignas(32) Entry {
    // Low 48 bits: the partial fixed-point sums. High 16 bits: the vertex count (word 0) and the
    // low and high halves of the table slot (words 1 and 2). An entry goes to the table once it
    // holds kMaxCount vertices, so that its sums stay below 2^48 (one value is at most 2^40).
    uint64_t word[3] = {0, 0, 0};
    uint32_t fingerprint = kEmptyFingerprint;
    // Low half of the table index: with the fingerprint it names the table cell, since equal
    // (home cell, fingerprint) always probe to the same cell and tables have at most 2^31 cells.
    uint32_t index_low = 0;
  };
  static_assert(sizeof(Entry) == 32);
  static constexpr uint64_t kSumMask = (uint64_t(1) << 48) - 1;
  static constexpr uint64_t kCountOne = uint64_t(1) << 48;
  static constexpr uint32_t kMaxCount = 255;
  static_assert(uint64_t(kMaxCount) * (uint64_t(1) << 40) <= kSumMask, "sums must not reach the count bits");
  std::unique_ptr<Entry[]> entries{new Entry[kEntries]};

  static constexpr int kPending = 16;  // evictions in flight (prefetch distance)
  struct Pending {
    uint64_t slot = 0;
    uint64_t sum[3] = {0, 0, 0};
    uint64_t count = 0;
  };
  Pending pending[kPending];
  int pending_next = 0;

  Entry& entry_for(const VoxelHash& h) { return entries[(h.index ^ (h.index >> 17)) & (kEntries - 1)]; }
  void prefetch(const VoxelHash& h) { __builtin_prefetch(&entry_for(h), 1, 3); }
  static bool holds(const Entry& e, const VoxelHash& h) {
    return e.fingerprint == h.fingerprint && e.index_low == uint32_t(h.index) && e.fingerprint != kEmptyFingerprint;
  }
  static uint32_t count(const Entry& e) { return uint32_t(e.word[0] >> 48); }
  static uint32_t slot(const Entry& e) { return uint32_t(e.word[1] >> 48) | uint32_t(e.word[2] >> 48) << 16; }
  static void open(Entry& e, const VoxelHash& h, uint64_t slot) {
    e.word[0] = 0;
    e.word[1] = (slot & 0xffffu) << 48;
    e.word[2] = (slot >> 16) << 48;
    e.fingerprint = h.fingerprint;
    e.index_low = uint32_t(h.index);
  }
  // Adds one vertex's fixed-point value (each channel at most 2^40, to_fixed_point()).
  void add(const VoxelHashTableView& table, Entry& e, const uint64_t fixed[3]) {
    e.word[0] += fixed[0] + kCountOne;
    e.word[1] += fixed[1];
    e.word[2] += fixed[2];
    if (count(e) == kMaxCount) {  // rare: only voxels with hundreds of vertices
      const VoxelHash h{e.index_low, e.fingerprint};
      const uint32_t s = slot(e);
      evict(table, e);
      open(e, h, s);
    }
  }
  // Empties e; its sums reach the table kPending evictions later (or in flush_all).
  void evict(const VoxelHashTableView& table, Entry& e) {
    if (count(e) > 0) {
      Pending& p = pending[pending_next];
      add_to_table(table, p);
      p.slot = slot(e);
      for (int c = 0; c < 3; ++c) p.sum[c] = e.word[c] & kSumMask;
      p.count = count(e);
      __builtin_prefetch(&table.cells[p.slot], 1, 3);
      pending_next = (pending_next + 1) % kPending;
    }
    e = Entry{};
  }
  // Adds everything still held to the table (end of the pass).
  void flush_all(const VoxelHashTableView& table) {
    for (int i = 0; i < kEntries; ++i) evict(table, entries[i]);
    for (Pending& p : pending) add_to_table(table, p);
  }

 private:
  static void add_to_table(const VoxelHashTableView& table, Pending& p) {
    if (p.count == 0) return;
    VoxelCell& c = table.cells[p.slot];
    for (int i = 0; i < 3; ++i) atomic_fetch_add(&c.sum[i], p.sum[i]);
    atomic_fetch_add(&c.count, p.count);
    p = Pending{};
  }
};

}  // namespace pathspace
