// Device-safe stochastic hash map (Hachisuka & Jensen 2010, "Parallel progressive photon mapping
// on GPUs"; compared with the chained grid in PCLT fig. 8): a fixed-size table, one record per slot.
// Records whose cells hash to the same slot compete; the slot keeps a uniform choice among them and
// counts them, so memory is fixed and callers reweight by the count (estimator below).
#pragma once

#include <cstdint>

#include "pathspace/hashgrid/hash_grid_view.h"

namespace pathspace {

// How the uniform choice is made. The reservoir rule "the n-th arrival replaces the stored record
// with probability 1/n" is realised as: every record draws a priority u = hash(seed, payload), the
// slot keeps the smallest (atomic min on (u << 32 | payload)). In arrival order the n-th record
// becomes the minimum with probability exactly 1/n, so this *is* the reservoir rule, but its
// outcome does not depend on the order the threads arrive in. (A literal "fetch_add the counter,
// then store with probability 1/n" is not uniform under concurrency: a later ticket can write
// before an earlier one and be overwritten.) Ties of the 32-bit priority fall to the lower payload.
//
// Unbiased estimation: a slot holding record x_s out of count_s arrivals gives
//   E[count_s * g(x_s) * [|x_s - p| <= r]] = sum over its count_s records x of g(x) [|x - p| <= r],
// so sum over the *distinct* slots of the cells around p of count_s * g(x_s) [|x_s - p| <= r] is an
// unbiased estimate of sum_{|x - p| <= r} g(x). for_each_in_radius visits each distinct slot once
// (cells that collide in the table share a slot) and hands count_s to the callback.

inline constexpr uint64_t kNoChoice = ~uint64_t(0);

struct StochasticSlot {
  uint64_t choice = kNoChoice;  // (priority << 32) | payload of the current winner
  uint32_t count = 0;           // records that hashed here (exact)
  uint32_t payload = kNoRecord; // the winner, filled in by resolve()
  Vec3 position;                // the winner's position, filled in by resolve()
  uint32_t unused = 0;
};

struct StochasticHashMapView {
  StochasticSlot* slots = nullptr;
  uint32_t slot_mask = 0;  // table size - 1 (power of two)
  GridGeometry geometry;
  uint64_t seed = 0;       // change per iteration so different records win
  GridCounters* counters = nullptr;

  PS_HD uint32_t slot_of(uint64_t cell_key) const { return uint32_t(hash_cell_key(cell_key)) & slot_mask; }

  PS_HD uint64_t choice_of(uint32_t payload) const {
    return (hash_combine(seed, payload) & 0xffffffff00000000ull) | payload;
  }

  // Pass 1 (all records, any order, concurrently).
  PS_HD bool insert(const Vec3& position, uint32_t payload) const {
    if (!all_finite(position)) {
      atomic_fetch_or(&counters->status, kGridInvalidPosition);
      atomic_fetch_add(&counters->dropped, 1u);
      return false;
    }
    StochasticSlot& s = slots[slot_of(geometry.key_of(position))];
    atomic_fetch_add(&s.count, 1u);
    atomic_fetch_min(&s.choice, choice_of(payload));
    return true;
  }

  // Pass 2 (per slot, after pass 1): copy the winner's data into the slot so queries touch one line.
  template <typename PositionOf>
  PS_HD void resolve(uint32_t slot, const PositionOf& position_of) const {
    StochasticSlot& s = slots[slot];
    if (s.count == 0) return;
    s.payload = uint32_t(s.choice);
    s.position = position_of(s.payload);
  }

  // f(const StochasticSlot&, float distance_squared) once per distinct slot of the cells a ball of
  // `radius` around p touches, when its record lies within the ball; weight by slot.count.
  template <typename F>
  PS_HD void for_each_in_radius(const Vec3& p, float radius, F&& f) const {
    CellCoord lo, hi;
    geometry.cell_range(p, radius, &lo, &hi);
    const float r2 = radius * radius;
    // radius <= cell_size / 2 touches at most 3 cells per axis (2 unless p sits within a few ulps
    // of a border): the slots of the first 27 cells are remembered, later ones recomputed.
    constexpr int kRemembered = 27;
    uint32_t seen[kRemembered];
    int cell = 0;  // index of the current cell in loop order
    auto visited_before = [&](uint32_t slot) {
      for (int i = 0; i < cell && i < kRemembered; ++i)
        if (seen[i] == slot) return true;
      if (cell <= kRemembered) return false;
      int index = 0;
      for (int32_t x = lo.x; x <= hi.x; ++x)
        for (int32_t y = lo.y; y <= hi.y; ++y)
          for (int32_t z = lo.z; z <= hi.z && index < cell; ++z, ++index)
            if (index >= kRemembered && slot_of(pack_cell_key(x, y, z)) == slot) return true;
      return false;
    };
    for (int32_t x = lo.x; x <= hi.x; ++x)
      for (int32_t y = lo.y; y <= hi.y; ++y)
        for (int32_t z = lo.z; z <= hi.z; ++z, ++cell) {
          const uint32_t slot = slot_of(pack_cell_key(x, y, z));
          const bool duplicate = visited_before(slot);
          if (cell < kRemembered) seen[cell] = slot;
          if (duplicate) continue;
          const StochasticSlot& s = slots[slot];
          if (s.count == 0) continue;
          const float d2 = distance_squared(s.position, p);
          if (d2 <= r2) f(s, d2);
        }
  }
};

}  // namespace pathspace
