// The per-vertex steps of the hashed filter (Binder et al. 2021, sec. 3.2-3.3) as PS_HD functions
// over VoxelHashTableView: the CPU filter (HashedFilter), its tests and the GPU filter
// (filters/hashed/cuda_hashed_filter.cu) run the same code. Accumulation: key -> hash -> fixed point ->
// find_or_insert -> integer atomic adds, and the coarser level with multi-level (3.3.2). Lookup: the
// cell average, and for low-count cells the 26 neighbours (3.3.1) or the coarser cell (3.3.2).
// Integer sums make the cells independent of the order of the adds, so every schedule (threads,
// warps, warp aggregation) gives the same cells bit for bit.
#pragma once

#include <cstddef>
#include <cstdint>

#include "pathspace/filters/hashed/hashed_filter_keys.h"
#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/filters/hashed/voxel_hash_table_view.h"

namespace pathspace {

// A record slot's cell: >= 0 a table cell, kSlotProbeFailed when the probe window was full (the
// vertex keeps its own contribution, sec. 3.2.2), kSlotNotAccumulated for NaN, Inf, negative or
// huge contributions.
inline constexpr int32_t kSlotProbeFailed = -1;
inline constexpr int32_t kSlotNotAccumulated = -2;

// What the per-vertex steps need of HashedFilterSettings (plain data: a kernel argument).
struct HashedStepSettings {
  VoxelKeySettings key;           // with the camera's pixel_angle
  uint64_t min_count = 4;         // sec. 3.3
  bool neighbour_search = false;  // sec. 3.3.1
  bool multi_level = false;       // sec. 3.3.2
  float max_luminance = 0.f;      // --psf-clamp: largest luminance a vertex adds to a voxel (0: no clamp)
};

// From the filter's settings, whose key.pixel_angle the filter has set from its camera.
inline HashedStepSettings step_settings(const HashedFilterSettings& f) {
  HashedStepSettings s;
  s.key = f.key;
  s.min_count = uint64_t(f.min_count > 0 ? f.min_count : 0);
  s.neighbour_search = f.neighbour_search;
  s.multi_level = f.multi_level;
  s.max_luminance = f.max_luminance;
  return s;
}

// What a vertex adds to its voxel: its contribution, scaled down (hue kept) to a luminance of at
// most max_luminance when that is set. An anti-firefly clamp as SHaRC's: one rare bright path (a
// caustic found by BSDF sampling) no longer sets a whole voxel's average, at the price of a bias
// towards darker voxels (docs/hashed-filter.md, "Robust averages").
PS_INLINE Rgb accumulated_value(const HashedStepSettings& s, const Rgb& c) {
  if (!(s.max_luminance > 0.f)) return c;
  const float y = luminance(c);
  return y > s.max_luminance ? c * (s.max_luminance / y) : c;
}

// The fixed-point value a vertex adds to its voxel (false: not representable, it is not accumulated).
PS_INLINE bool accumulated_fixed_point(const HashedStepSettings& s, const Rgb& c, uint64_t out[3]) {
  return to_fixed_point(accumulated_value(s, c), out);
}

// Adds `count` vertices whose fixed-point values sum to `sum` into the cell of h (sec. 3.2).
PS_INLINE void add_to_cell(const VoxelHashTableView& t, uint64_t slot, const uint64_t sum[3], uint64_t count) {
  VoxelCell& c = t.cells[slot];
  for (int i = 0; i < 3; ++i) atomic_fetch_add(&c.sum[i], sum[i]);
  atomic_fetch_add(&c.count, count);
}

// find_or_insert, then the adds when a cell was found or claimed (slot < 0: window full).
PS_INLINE ProbeResult insert_and_add(const VoxelHashTableView& t, const VoxelHash& h, const uint64_t sum[3], uint64_t count) {
  const ProbeResult r = t.find_or_insert(h);
  if (r.slot >= 0) add_to_cell(t, uint64_t(r.slot), sum, count);
  return r;
}

// The accumulation inputs of record slot i: its key, the key's hash and its fixed-point value.
struct PreparedVertex {
  VoxelKey key;
  VoxelHash hash;
  uint64_t fixed[3] = {0, 0, 0};
  bool accumulated = false;  // false: not representable in fixed point, keeps its own contribution
};

PS_INLINE PreparedVertex prepare_vertex(const HashedStepSettings& s, const VertexBufferView& b, size_t i, uint64_t pass_hash) {
  PreparedVertex v;
  v.accumulated = accumulated_fixed_point(s, b.contribution[i], v.fixed);
  v.key = key_for_pass(s.key, b, i, pass_hash);
  v.hash = hash_voxel_key(v.key, s.key.normal);
  return v;
}

// The hash of the coarser level's key (sec. 3.3.2).
PS_INLINE VoxelHash coarse_hash(const HashedStepSettings& s, const VoxelKey& key) {
  return hash_voxel_key(coarser_key(key), s.key.normal);
}

struct AccumulatedVertex {
  int32_t slot = kSlotNotAccumulated;
  int32_t coarse_slot = kSlotProbeFailed;  // multi-level only
  int probes = 0;                          // cells inspected by the insertion (0: not inserted)
};

// The accumulation of one vertex, as HashedFilter::accumulate does it without local combining.
PS_INLINE AccumulatedVertex accumulate_vertex(const HashedStepSettings& s, const VertexBufferView& b, size_t i,
                                              uint64_t pass_hash, const VoxelHashTableView& table,
                                              const VoxelHashTableView& coarse) {
  AccumulatedVertex out;
  const PreparedVertex v = prepare_vertex(s, b, i, pass_hash);
  if (!v.accumulated) return out;
  if (s.multi_level) out.coarse_slot = int32_t(insert_and_add(coarse, coarse_hash(s, v.key), v.fixed, 1).slot);
  const ProbeResult r = insert_and_add(table, v.hash, v.fixed, 1);
  out.slot = int32_t(r.slot);
  out.probes = r.probes;
  return out;
}

struct LookupCounters {
  uint64_t low_count = 0, neighbour_lookups = 0, multi_level_used = 0;
};

// Sec. 3.3.1: the voxel's sums plus those of its 26 neighbours at the same level.
PS_INLINE Rgb neighbourhood_average(const VoxelHashTableView& t, NormalKeyMode normal, const VoxelKey& key,
                                    const VoxelCell& own, uint64_t* lookups) {
  uint64_t sum[3] = {own.sum[0], own.sum[1], own.sum[2]};
  uint64_t count = own.count;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0 && dz == 0) continue;
        VoxelKey n = key;
        n.cell[0] += dx;
        n.cell[1] += dy;
        n.cell[2] += dz;
        ++*lookups;
        const ProbeResult r = t.find(hash_voxel_key(n, normal));
        if (r.slot < 0) continue;
        const VoxelCell& c = t.cells[r.slot];
        for (int ch = 0; ch < 3; ++ch) sum[ch] += c.sum[ch];
        count += c.count;
      }
  return from_fixed_point(sum, count);
}

// A low-count cell's estimate (sec. 3.3): `average` is the cell's own; `key` is read only with
// neighbour search, `coarse_slot` only with multi-level.
PS_INLINE Rgb low_count_average(const HashedStepSettings& s, const VoxelHashTableView& table,
                                const VoxelHashTableView& coarse, const VoxelCell& cell, const Rgb& average,
                                const VoxelKey& key, int32_t coarse_slot, LookupCounters* c) {
  ++c->low_count;
  if (s.neighbour_search) return neighbourhood_average(table, s.key.normal, key, cell, &c->neighbour_lookups);
  if (s.multi_level && coarse_slot >= 0) {
    const VoxelCell& cc = coarse.cells[coarse_slot];
    if (cc.count > cell.count) {
      ++c->multi_level_used;
      return from_fixed_point(cc.sum, cc.count);
    }
  }
  return average;
}

// Sec. 3.1.3, adaptive resolution. The coarse cells keep, beside their sums, the sum of their vertices'
// squared luminance in fixed point, so that the sums do not depend on the order of the adds either.
// The luminance is capped at kMaxSquaredLuminance for this sum alone (fireflies then count with less
// than their variance), which keeps 2^21 vertices of a cell from overflowing 64 bits.
inline constexpr float kMaxSquaredLuminance = 1024.f;
PS_INLINE uint64_t luminance_square_fixed(const Rgb& contribution) {
  const double l = double(min_of(luminance(contribution), kMaxSquaredLuminance));
  return uint64_t(l * l * double(kFixedPointScale) + 0.5);
}

// A voxel's identity across passes (its hash and fingerprint in one word), for choices that carry
// from pass to pass.
PS_INLINE uint64_t voxel_identity(const VoxelHash& h) { return h.index ^ (uint64_t(h.fingerprint) * 0x9e3779b97f4a7c15ull); }

// Whether a vertex takes its fine cell's average rather than that of the coarse cell one level up
// that contains it. The coarse average is off by about d = L_fine - L_coarse (the finite difference
// of the luminance averages across the two levels); the fine average's variance is larger by about
// V = sigma^2 (1/n_fine - 1/n_coarse), sigma^2 the variance of the luminance of the coarse cell's
// vertices (an upper estimate where the cell holds detail, so doubt favours the coarse cell). The
// fine cell has the lower expected squared error when d^2 > V; the estimated d^2 carries V itself
// once (E[d_est^2] = d^2 + V), hence the test d_est^2 > 2 V, with nothing to tune.
PS_INLINE bool prefer_fine_voxel(const VoxelCell& fine, const VoxelCell& coarse, uint64_t coarse_squares) {
  if (coarse.count <= fine.count) return true;  // the coarse cell adds no vertex
  const double nf = double(fine.count), nc = double(coarse.count), unit = 1.0 / double(kFixedPointScale);
  const auto luminance_average = [&](const VoxelCell& c, double n) {
    return luminance_of(double(c.sum[0]), double(c.sum[1]), double(c.sum[2])) * unit / n;
  };
  const double lf = luminance_average(fine, nf), lc = luminance_average(coarse, nc);
  const double mean_square = double(coarse_squares) * unit / nc;
  double variance = (mean_square - lc * lc) * nc / (nc - 1.0);
  variance = variance > 0.0 ? variance : 0.0;
  const double d = lf - lc;
  // Differences at the rounding level of the averages do not count (equal averages, no noise).
  return d * d > 2.0 * variance * (1.0 / nf - 1.0 / nc) + 1e-12 * lc * lc;
}

// The filtered contribution of record slot i after accumulation (one pass, no temporal history);
// the key is recomputed only when the neighbour search needs it.
PS_INLINE Rgb lookup_vertex(const HashedStepSettings& s, const VertexBufferView& b, size_t i, uint64_t pass_hash,
                            const VoxelHashTableView& table, const VoxelHashTableView& coarse, int32_t slot,
                            int32_t coarse_slot, LookupCounters* c) {
  if (slot < 0) return b.contribution[i];
  const VoxelCell& cell = table.cells[slot];
  const Rgb average = from_fixed_point(cell.sum, cell.count);
  if (cell.count >= s.min_count) return average;
  const VoxelKey key = s.neighbour_search ? key_for_pass(s.key, b, i, pass_hash) : VoxelKey{};
  return low_count_average(s, table, coarse, cell, average, key, coarse_slot, c);
}

}  // namespace pathspace
