// Host owner of the stochastic hash map (Hachisuka & Jensen 2010; PCLT fig. 8): a table of fixed
// size chosen by memory budget, not by record count, an O(table) clear, the two parallel build
// passes (insert all, then resolve each slot's winner) and statistics. Kernels use
// StochasticHashMapView (stochastic_hash_map_view.h), which also documents the estimator.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <span>
#include <vector>

#include "pathspace/base/check.h"
#include "pathspace/hashgrid/stochastic_hash_map_view.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace {

struct StochasticHashMapStats {
  size_t records = 0;         // records inserted (sum of slot counts)
  size_t occupied_slots = 0;  // = records kept
  size_t table_slots = 0;
  uint32_t max_count = 0;     // most records competing for one slot
  size_t dropped = 0;         // non-finite positions
  size_t bytes = 0;
  uint32_t status = kGridOk;
};

class StochasticHashMap {
 public:
  // table_slots: a power of two; memory is table_slots * sizeof(StochasticSlot) (32 bytes).
  explicit StochasticHashMap(size_t table_slots) : slots_(table_slots) {
    PS_CHECK(std::has_single_bit(table_slots) && table_slots <= (size_t(1) << 31));
  }

  void clear() {
    parallel_for(slots_.size(), size_t(1) << 14,
                 [&](size_t b, size_t e) { std::fill(&slots_[b], &slots_[e], StochasticSlot{}); });
    counters_ = GridCounters{};
  }

  // Clears, then inserts position_of(i) with payload i for i < n and resolves the winners. The seed
  // picks which records win; the result does not depend on the thread count.
  template <typename PositionOf>
  void build(size_t n, float radius, uint64_t seed, const PositionOf& position_of) {
    PS_CHECK(radius > 0.f && isfinite(radius));
    PS_CHECK(n < size_t(kNoRecord));
    geometry_ = GridGeometry::for_radius(radius);
    seed_ = seed;
    clear();
    const StochasticHashMapView v = view();
    parallel_for(n, 1024, [&](size_t b, size_t e) {
      for (size_t i = b; i < e; ++i) v.insert(position_of(i), uint32_t(i));
    });
    counters_.appended = uint32_t(n);
    parallel_for(slots_.size(), size_t(1) << 12, [&](size_t b, size_t e) {
      for (size_t s = b; s < e; ++s) v.resolve(uint32_t(s), position_of);
    });
  }
  void build(std::span<const Vec3> positions, float radius, uint64_t seed) {
    build(positions.size(), radius, seed, [&](size_t i) { return positions[i]; });
  }

  // A view is a handle like a device pointer: the owner's constness does not travel with it.
  StochasticHashMapView view() const {
    auto* self = const_cast<StochasticHashMap*>(this);
    return StochasticHashMapView{self->slots_.data(), uint32_t(slots_.size() - 1), geometry_, seed_, &self->counters_};
  }
  template <typename F>
  void for_each_in_radius(const Vec3& p, float radius, F&& f) const {
    view().for_each_in_radius(p, radius, f);
  }

  uint32_t status() const { return counters_.status; }
  const GridGeometry& geometry() const { return geometry_; }
  const StochasticSlot& slot(size_t i) const { return slots_[i]; }

  StochasticHashMapStats stats() const {
    StochasticHashMapStats s;
    s.table_slots = slots_.size();
    s.dropped = counters_.dropped;
    s.status = counters_.status;
    s.bytes = slots_.capacity() * sizeof(StochasticSlot);
    for (const StochasticSlot& slot : slots_) {
      s.records += slot.count;
      s.occupied_slots += slot.count > 0;
      s.max_count = std::max(s.max_count, slot.count);
    }
    return s;
  }

 private:
  std::vector<StochasticSlot> slots_;
  GridCounters counters_;
  GridGeometry geometry_;
  uint64_t seed_ = 0;
};

}  // namespace pathspace
