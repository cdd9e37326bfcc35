// Uniform grid cells for the hash grids (PCLT sec. 4, Hachisuka & Jensen 2010): quantising a
// position to integer cell coordinates, packing them into a 64-bit cell key, and the range of
// cells a query ball can touch. With cell size 2r that range is the 2x2x2 block picked by which
// half of its cell the query point lies in (fewer cells when the ball stays inside one cell).
#pragma once

#include <cstdint>

#include "pathspace/math/vec3.h"
#include "pathspace/sampling/hash.h"

namespace pathspace {

// 21 bits per axis, wrapped modulo 2^21: cells 2^21 apart share a key, which only costs a longer
// chain (queries test distances), never a wrong answer. Keys use 63 bits, so ~0 stays free.
inline constexpr int kCellBits = 21;
inline constexpr uint32_t kCellMask = (1u << kCellBits) - 1u;
inline constexpr uint64_t kEmptyCellKey = ~uint64_t(0);

struct CellCoord {
  int32_t x = 0, y = 0, z = 0;
};

PS_INLINE uint64_t pack_cell_key(int32_t x, int32_t y, int32_t z) {
  return (uint64_t(uint32_t(x) & kCellMask) << (2 * kCellBits)) | (uint64_t(uint32_t(y) & kCellMask) << kCellBits) |
         uint64_t(uint32_t(z) & kCellMask);
}

PS_INLINE uint64_t hash_cell_key(uint64_t key) { return mix64(key); }

// A Morton code: the low 21 bits of x, y and z interleaved, so cells close in space get close codes
// (an order of visiting cells in which neighbours stay in cache).
PS_INLINE uint64_t spread21(uint32_t v) {
  uint64_t x = v & kCellMask;
  x = (x | x << 32) & 0x1f00000000ffffull;
  x = (x | x << 16) & 0x1f0000ff0000ffull;
  x = (x | x << 8) & 0x100f00f00f00f00full;
  x = (x | x << 4) & 0x10c30c30c30c30c3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}
PS_INLINE uint64_t morton_cell_order(const CellCoord& c) {
  return spread21(uint32_t(c.x)) | spread21(uint32_t(c.y)) << 1 | spread21(uint32_t(c.z)) << 2;
}

struct GridGeometry {
  float cell_size = 1.f;
  float inv_cell_size = 1.f;

  PS_HD static GridGeometry for_radius(float radius) { return {2.f * radius, 1.f / (2.f * radius)}; }

  // floor(v / cell) as an integer. Float multiply, floor and clamp are monotone, which is what
  // makes the query range below conservative. fminf/fmaxf keep the int conversion defined for huge
  // inputs and send NaN to a valid cell (a NaN query then simply finds nothing).
  PS_HD int32_t coord(float v) const {
    return int32_t(fminf(fmaxf(floorf(v * inv_cell_size), -536870912.f), 536870912.f));
  }
  PS_HD CellCoord cell_of(const Vec3& p) const { return {coord(p.x), coord(p.y), coord(p.z)}; }
  PS_HD uint64_t key_of(const Vec3& p) const { return pack_cell_key(coord(p.x), coord(p.y), coord(p.z)); }

  // Cells [lo, hi] (inclusive per axis) holding every point x whose float distance test
  // distance_squared(x, p) <= r*r passes. That test accepts points up to ~r(1 + 2^-22) away, so the
  // ball is widened by r * 2^-20: without it a point at distance r across a cell border can be
  // missed (e.g. x = -1e-30, p = r: the test passes, p - r rounds onto the border 0). Rounding of
  // p - r itself needs no margin: rounding is monotone and x is a float. (Valid while r*r is a
  // normal float, r > ~1e-19.)
  PS_HD void cell_range(const Vec3& p, float radius, CellCoord* lo, CellCoord* hi) const {
    const float r = radius * (1.f + 0x1p-20f);
    *lo = {coord(p.x - r), coord(p.y - r), coord(p.z - r)};
    *hi = {coord(p.x + r), coord(p.y + r), coord(p.z + r)};
    // Never walk more than one full wrap of the key space: that would visit a cell twice.
    const int32_t span = int32_t(kCellMask);
    if (hi->x - lo->x > span) hi->x = lo->x + span;
    if (hi->y - lo->y > span) hi->y = lo->y + span;
    if (hi->z - lo->z > span) hi->z = lo->z + span;
  }
};

enum class Probing : uint32_t { quadratic, linear };

// i-th slot of the probe sequence from `home`. Quadratic probing uses triangular numbers i(i+1)/2,
// which visit every slot of a power-of-two table exactly once; PCLT found it much faster than
// linear probing (sec. 4, after Alcantara 2011).
PS_INLINE uint32_t probe_slot(uint32_t home, uint32_t i, Probing probing, uint32_t mask) {
  const uint32_t step = probing == Probing::quadratic ? i * (i + 1u) / 2u : i;
  return (home + step) & mask;
}

// Status bits accumulated by device-side inserts and checked on the host (docs/architecture.md §4).
enum GridStatusBits : uint32_t {
  kGridOk = 0,
  kGridProbeLimit = 1u << 0,       // a cell found no slot within max_probes: its record is not linked
  kGridFull = 1u << 1,             // the record buffer was full: record dropped
  kGridInvalidPosition = 1u << 2,  // non-finite position: record dropped
};

}  // namespace pathspace
