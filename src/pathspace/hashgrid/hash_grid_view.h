// Device-safe chained hash grid (PCLT sec. 4, listing 1): an append buffer of records and an
// open-addressing map from 64-bit cell keys to the head of each cell's record list. A cell is
// claimed by CAS on its key, a record is pushed by exchanging the head (lock-free, one pass).
// The owning host class is HashGrid (hash_grid.h); this view is what kernels receive.
#pragma once

#include <cstddef>
#include <cstdint>

#include "pathspace/hashgrid/grid_cell.h"
#include "pathspace/parallel/atomics.h"

namespace pathspace {

inline constexpr uint32_t kNoRecord = ~0u;

// One stored point: the caller's payload index (into its own arrays) and the list link.
struct GridRecord {
  Vec3 position;
  uint32_t payload = 0;
  uint32_t next = kNoRecord;
};

// Key and list head side by side: a probe that finds its key has the head in the same line.
struct GridSlot {
  uint64_t key = kEmptyCellKey;
  uint32_t head = kNoRecord;
  uint32_t count = 0;  // after HashGrid::compact(): the cell's records, [head, head + count); else 0
};

// Written atomically by inserts, read by the host after the build (never a silent failure).
struct GridCounters {
  uint32_t status = kGridOk;   // GridStatusBits
  uint32_t appended = 0;       // records taken from the append buffer (may exceed capacity: see full)
  uint32_t probe_failures = 0; // records whose cell found no slot
  uint32_t dropped = 0;        // records not stored at all (full buffer, non-finite position)
};

// An optional bitmap with one bit per hashed cell key, set for every occupied cell: a query for an
// empty cell then reads one word of a table small enough for the L1/L2 cache instead of probing the
// slot table (a cache miss when the table is large and the queries scattered). Exact: a clear bit
// means an empty cell; a set bit only sends the query on to the table.
struct CellOccupancy {
  const uint64_t* words = nullptr;  // null: no bitmap, every query probes
  uint32_t bit_mask = 0;            // bits - 1 (power of two)

  PS_HD static uint32_t bit_of(uint64_t key_hash, uint32_t bit_mask) { return uint32_t(key_hash >> 32) & bit_mask; }
  PS_HD size_t word_count() const { return size_t(bit_mask) / 64 + 1; }
  PS_HD bool may_hold(uint64_t key_hash) const {
    if (!words) return true;
    const uint32_t bit = bit_of(key_hash, bit_mask);
    return (words[bit >> 6] >> (bit & 63u)) & 1u;
  }
};

struct HashGridView {
  GridSlot* slots = nullptr;
  uint32_t slot_mask = 0;  // table size - 1 (power of two)
  GridRecord* records = nullptr;
  uint32_t record_capacity = 0;
  GridCounters* counters = nullptr;
  GridGeometry geometry;
  Probing probing = Probing::quadratic;
  uint32_t max_probes = 64;
  CellOccupancy occupancy;  // set by HashGrid after a build when configured (HashGridConfig)

  // Links the already written record `index` into its cell's list. On a probe failure the record
  // stays in the buffer unlinked and the failure is counted.
  PS_HD bool link(uint32_t index) const {
    GridRecord& rec = records[index];
    const uint64_t key = geometry.key_of(rec.position);
    const uint32_t home = uint32_t(hash_cell_key(key)) & slot_mask;
    for (uint32_t i = 0; i < max_probes; ++i) {
      GridSlot& slot = slots[probe_slot(home, i, probing, slot_mask)];
      // Keys never change during a build, so a plain read that already shows our key (the common
      // case when many records share a cell) saves the locked CAS.
      uint64_t seen = atomic_load_relaxed(&slot.key);
      if (seen == kEmptyCellKey) seen = atomic_cas(&slot.key, kEmptyCellKey, key);
      if (seen == kEmptyCellKey || seen == key) {
        rec.next = atomic_exchange(&slot.head, index);
        return true;
      }
    }
    rec.next = kNoRecord;
    atomic_fetch_or(&counters->status, kGridProbeLimit);
    atomic_fetch_add(&counters->probe_failures, 1u);
    return false;
  }

  // Listing 1 in full: take a record from the append buffer, store it, link it.
  PS_HD bool insert(const Vec3& position, uint32_t payload) const {
    if (!all_finite(position)) return drop(kGridInvalidPosition);
    const uint32_t index = atomic_fetch_add(&counters->appended, 1u);
    if (index >= record_capacity) return drop(kGridFull);
    records[index].position = position;
    records[index].payload = payload;
    return link(index);
  }

  PS_HD bool drop(uint32_t bit) const {
    atomic_fetch_or(&counters->status, bit);
    atomic_fetch_add(&counters->dropped, 1u);
    return false;
  }

  // Head of the list of the cell with this key, kNoRecord if the cell holds nothing. Stopping at
  // the first empty slot is exact: there are no deletions, so every slot before a key's own slot in
  // its probe sequence was occupied when that key was inserted and still is.
  PS_HD uint32_t find_head(uint64_t key) const {
    const uint64_t hash = hash_cell_key(key);
    if (!occupancy.may_hold(hash)) return kNoRecord;
    const uint32_t home = uint32_t(hash) & slot_mask;
    for (uint32_t i = 0; i < max_probes; ++i) {
      const GridSlot& slot = slots[probe_slot(home, i, probing, slot_mask)];
      if (slot.key == key) return slot.head;
      if (slot.key == kEmptyCellKey) return kNoRecord;
    }
    return kNoRecord;
  }

  // After HashGrid::compact(): the records of the cell with this key are [*begin, *end) (empty if
  // none), from the slot alone.
  PS_HD void find_cell(uint64_t key, uint32_t* begin, uint32_t* end) const {
    *begin = *end = 0;
    const uint64_t hash = hash_cell_key(key);
    if (!occupancy.may_hold(hash)) return;
    const uint32_t home = uint32_t(hash) & slot_mask;
    for (uint32_t i = 0; i < max_probes; ++i) {
      const GridSlot& slot = slots[probe_slot(home, i, probing, slot_mask)];
      if (slot.key == key) {
        *begin = slot.head;
        *end = slot.head + slot.count;
        return;
      }
      if (slot.key == kEmptyCellKey) break;
    }
  }

  // f(key) for every cell a ball of `radius` around p can touch, x outermost, z innermost.
  template <typename F>
  PS_HD void for_each_cell_key(const Vec3& p, float radius, F&& f) const {
    CellCoord lo, hi;
    geometry.cell_range(p, radius, &lo, &hi);
    for (int32_t x = lo.x; x <= hi.x; ++x)
      for (int32_t y = lo.y; y <= hi.y; ++y)
        for (int32_t z = lo.z; z <= hi.z; ++z) f(pack_cell_key(x, y, z));
  }

  // Every record in the cells a ball of `radius` around p can touch, without a distance test (for
  // callers with per-record radii, e.g. SPPM hit points built with the largest radius).
  template <typename F>
  PS_HD void for_each_candidate(const Vec3& p, float radius, F&& f) const {
    for_each_cell_key(p, radius, [&](uint64_t key) {
      for (uint32_t r = find_head(key); r != kNoRecord; r = records[r].next) f(records[r]);
    });
  }

  // After HashGrid::compact(): f(begin, end), the record range of every non-empty cell a ball of
  // `radius` around p can touch, in for_each_candidate's order. For callers that keep their payloads
  // in record order: they read their own array only, not the records as well.
  template <typename F>
  PS_HD void for_each_cell_range(const Vec3& p, float radius, F&& f) const {
    for_each_cell_key(p, radius, [&](uint64_t key) {
      uint32_t begin, end;
      find_cell(key, &begin, &end);
      if (begin != end) f(begin, end);
    });
  }

  // f(const GridRecord&, float distance_squared) for every record with |x - p| <= radius.
  // radius <= geometry.cell_size / 2 visits at most the 8 cells around p; larger radii stay
  // correct and visit more cells.
  template <typename F>
  PS_HD void for_each_in_radius(const Vec3& p, float radius, F&& f) const {
    const float r2 = radius * radius;
    for_each_candidate(p, radius, [&](const GridRecord& rec) {
      const float d2 = distance_squared(rec.position, p);
      if (d2 <= r2) f(rec, d2);
    });
  }
};

}  // namespace pathspace
