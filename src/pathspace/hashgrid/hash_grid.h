// Host owner of the chained hash grid (PCLT sec. 4, listing 1): storage that grows but is never
// shrunk, so the per-iteration rebuild of SPPM / PCLT / the consistent filter allocates nothing;
// an O(table) clear; a parallel build over the caller's points; statistics for reports.
// Kernels use HashGridView (hash_grid_view.h).
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <span>
#include <vector>

#include "pathspace/base/check.h"
#include "pathspace/hashgrid/hash_grid_view.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace {

struct HashGridConfig {
  Probing probing = Probing::quadratic;
  uint32_t max_probes = 64;
  // Table slots per record when table_slots == 0 (rounded up to a power of two). A cell holds one
  // or more records, so 2 keeps the load factor at most 1/2.
  float slots_per_record = 2.f;
  uint32_t table_slots = 0;  // fixed table size (power of two) instead, e.g. to bound memory
  // After build(): store each cell's records contiguously, in ascending payload order. Queries then
  // read consecutive memory instead of chasing links scattered in insertion order, and the order
  // within a cell (hence float sums over neighbours) no longer depends on thread timing.
  bool compact = true;
  // After build(): a CellOccupancy bitmap with this many bits per table slot (rounded to a power of
  // two; 0: none). Worth it where most queries find empty cells, e.g. caustic photon gathers.
  uint32_t occupancy_bits_per_slot = 0;
};

struct HashGridStats {
  size_t records = 0;          // stored records (linked or not)
  size_t occupied_cells = 0;   // claimed slots
  size_t table_slots = 0;
  double mean_probe = 0.0;     // probes to reach a cell's slot, averaged over occupied cells (1 = home)
  uint32_t max_probe = 0;
  size_t probe_failures = 0;   // records left unlinked because their cell found no slot
  size_t dropped = 0;          // records not stored (full buffer, non-finite position)
  size_t bytes = 0;            // allocated table + record buffer
  uint32_t status = kGridOk;   // GridStatusBits
};

class HashGrid {
 public:
  explicit HashGrid(HashGridConfig config = {}) : config_(config) {}

  // Makes room for max_records (grows only) and clears; radius is the largest query radius, so the
  // cells are 2 * radius wide. Use this before inserting from a kernel through view().insert().
  void prepare(size_t max_records, float radius) {
    PS_CHECK(radius > 0.f && isfinite(radius));
    PS_CHECK(max_records < size_t(kNoRecord));
    const size_t wanted = config_.table_slots
                              ? size_t(config_.table_slots)
                              : std::bit_ceil(std::max<size_t>(16, size_t(double(max_records) * config_.slots_per_record)));
    PS_CHECK(std::has_single_bit(wanted) && wanted <= (size_t(1) << 31));
    if (slots_.size() != wanted) slots_.assign(wanted, GridSlot{});
    if (records_.size() < max_records) records_.resize(max_records);
    geometry_ = GridGeometry::for_radius(radius);
    clear();
  }

  // O(table): empties every slot and the append buffer; records are simply overwritten later.
  void clear() {
    parallel_for(slots_.size(), size_t(1) << 14, [&](size_t b, size_t e) { std::fill(&slots_[b], &slots_[e], GridSlot{}); });
    counters_ = GridCounters{};
    occupancy_ready_ = false;  // stale until a build() ends
  }

  // Record i holds position_of(i) with payload i, then is linked into its cell; all in parallel.
  // Filling records by index (not through the append counter) keeps their placement independent
  // of the thread count, as PCLT notes the counter can be replaced by per-thread ranges.
  template <typename PositionOf>
  void build(size_t n, float radius, const PositionOf& position_of) {
    prepare(n, radius);
    const HashGridView v = view();
    parallel_for(n, 1024, [&](size_t b, size_t e) {
      for (size_t i = b; i < e; ++i) {
        const Vec3 p = position_of(i);
        v.records[i] = GridRecord{p, uint32_t(i), kNoRecord};
        if (all_finite(p)) v.link(uint32_t(i));
        else v.drop(kGridInvalidPosition);
      }
    });
    counters_.appended = uint32_t(n);
    if (config_.compact) compact();
    if (config_.occupancy_bits_per_slot) mark_occupancy();
  }
  void build(std::span<const Vec3> positions, float radius) {
    build(positions.size(), radius, [&](size_t i) { return positions[i]; });
  }

  // A view is a handle like a device pointer: the owner's constness does not travel with it.
  HashGridView view() const {
    auto* self = const_cast<HashGrid*>(this);
    const CellOccupancy occupancy = occupancy_ready_ ? CellOccupancy{occupancy_.data(), occupancy_bit_mask_} : CellOccupancy{};
    return HashGridView{self->slots_.data(), uint32_t(slots_.size() - 1), self->records_.data(),
                        uint32_t(records_.size()), &self->counters_, geometry_, config_.probing, config_.max_probes,
                        occupancy};
  }
  template <typename F>
  void for_each_in_radius(const Vec3& p, float radius, F&& f) const {
    view().for_each_in_radius(p, radius, f);
  }

  // Rewrites the records cell by cell (see HashGridConfig::compact); links stay valid, so views and
  // kernels are unchanged. Records left unlinked by a probe failure were unreachable and are gone.
  void compact() {
    const size_t table = slots_.size();
    cell_start_.assign(table + 1, 0);
    parallel_for(table, size_t(1) << 12, [&](size_t b, size_t e) {
      for (size_t s = b; s < e; ++s) {
        uint32_t count = 0;
        for (uint32_t r = slots_[s].head; r != kNoRecord; r = records_[r].next) ++count;
        cell_start_[s + 1] = count;
      }
    });
    for (size_t s = 0; s < table; ++s) cell_start_[s + 1] += cell_start_[s];  // exclusive prefix sum
    order_.resize(cell_start_[table]);
    compacted_.resize(records_.size());
    parallel_for(table, size_t(1) << 12, [&](size_t b, size_t e) {
      for (size_t s = b; s < e; ++s) {
        const uint32_t begin = cell_start_[s], end = cell_start_[s + 1];
        if (begin == end) continue;
        uint32_t k = begin;
        for (uint32_t r = slots_[s].head; r != kNoRecord; r = records_[r].next) order_[k++] = r;
        std::sort(order_.begin() + begin, order_.begin() + end);
        for (uint32_t i = begin; i < end; ++i) {
          compacted_[i] = records_[order_[i]];
          compacted_[i].next = i + 1 < end ? i + 1 : kNoRecord;
        }
        slots_[s].head = begin;
        slots_[s].count = end - begin;
      }
    });
    records_.swap(compacted_);
  }

  // Sets the CellOccupancy bit of every claimed slot's key (serial: a few microseconds per 10^4 slots).
  void mark_occupancy() {
    const size_t bits = slots_.size() * std::bit_ceil(size_t(config_.occupancy_bits_per_slot));
    PS_CHECK(bits <= (size_t(1) << 32));
    occupancy_bit_mask_ = uint32_t(bits - 1);
    occupancy_.assign(CellOccupancy{nullptr, occupancy_bit_mask_}.word_count(), 0);
    for (const GridSlot& slot : slots_) {
      if (slot.key == kEmptyCellKey) continue;
      const uint32_t bit = CellOccupancy::bit_of(hash_cell_key(slot.key), occupancy_bit_mask_);
      occupancy_[bit >> 6] |= uint64_t(1) << (bit & 63u);
    }
    occupancy_ready_ = true;
  }

  // Records in cell order after compact(): records [0, compacted_records()) are exactly the linked ones.
  size_t compacted_records() const { return cell_start_.empty() ? 0 : size_t(cell_start_.back()); }

  uint32_t status() const { return counters_.status; }
  size_t record_count() const { return std::min<size_t>(counters_.appended, records_.size()); }
  const GridGeometry& geometry() const { return geometry_; }
  const GridRecord& record(size_t i) const { return records_[i]; }

  HashGridStats stats() const {
    HashGridStats s;
    s.records = record_count();
    s.table_slots = slots_.size();
    s.probe_failures = counters_.probe_failures;
    s.dropped = counters_.dropped;
    s.status = counters_.status;
    s.bytes = slots_.capacity() * sizeof(GridSlot) + (records_.capacity() + compacted_.capacity()) * sizeof(GridRecord) +
              (cell_start_.capacity() + order_.capacity()) * sizeof(uint32_t) + occupancy_.capacity() * sizeof(uint64_t);
    const uint32_t mask = uint32_t(slots_.size() - 1);
    double probe_sum = 0.0;
    for (uint32_t slot = 0; slot < slots_.size(); ++slot) {
      const uint64_t key = slots_[slot].key;
      if (key == kEmptyCellKey) continue;
      ++s.occupied_cells;
      // Replay the key's probe sequence to learn how far from home it settled.
      const uint32_t home = uint32_t(hash_cell_key(key)) & mask;
      uint32_t probes = 1;
      while (probe_slot(home, probes - 1, config_.probing, mask) != slot) ++probes;
      probe_sum += probes;
      s.max_probe = std::max(s.max_probe, probes);
    }
    if (s.occupied_cells) s.mean_probe = probe_sum / double(s.occupied_cells);
    return s;
  }

 private:
  HashGridConfig config_;
  std::vector<GridSlot> slots_;
  std::vector<GridRecord> records_;
  GridCounters counters_;
  GridGeometry geometry_;
  std::vector<uint32_t> cell_start_, order_;  // compaction scratch, reused
  std::vector<uint64_t> occupancy_;           // CellOccupancy words, valid while occupancy_ready_
  uint32_t occupancy_bit_mask_ = 0;
  bool occupancy_ready_ = false;
  std::vector<GridRecord> compacted_;
};

}  // namespace pathspace
