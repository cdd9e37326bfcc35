// Device-safe view of the voxel hash table of hashed path space filtering (Binder et al. 2021,
// sec. 3.2): open addressing over a fingerprint array (32-bit fingerprints, 0 = empty, sec. 3.2.1)
// with bounded linear probing that by default stays inside one 64-byte cache line of fingerprints,
// cells claimed by compare-and-swap, and accumulation by atomic integer adds into a parallel array
// of cells. Sums are fixed point, so the result does not depend on the order of the adds
// (float atomics would make renders differ between runs and thread counts).
#pragma once

#include <cstdint>

#include "pathspace/filters/hashed/voxel_key.h"
#include "pathspace/math/rgb.h"
#include "pathspace/parallel/atomics.h"

namespace pathspace {

inline constexpr uint32_t kEmptyFingerprint = kEmptyFingerprintValue;
inline constexpr int kFingerprintsPerLine = 16;  // 64-byte line / 4-byte fingerprint
// Fixed point: 2^-22 resolution; values above 2^18 are not accumulated (the vertex keeps its own
// contribution) so that 2^22 vertices can never overflow a 64-bit sum.
inline constexpr float kFixedPointScale = 4194304.f;
inline constexpr float kMaxAccumulatedValue = 262144.f;

struct alignas(32) VoxelCell {
  uint64_t sum[3];
  uint64_t count;
};

struct ProbeResult {
  int64_t slot = -1;  // -1: not found / probe limit reached
  int probes = 0;     // cells inspected
};

PS_INLINE bool to_fixed_point(const Rgb& v, uint64_t out[3]) {
  for (int c = 0; c < 3; ++c) {
    if (!(v[c] >= 0.f && v[c] <= kMaxAccumulatedValue)) return false;  // also rejects NaN
    // Through int64 (values stay below 2^41): float -> uint64 has no single x86 instruction.
    out[c] = uint64_t(int64_t(v[c] * kFixedPointScale + 0.5f));
  }
  return true;
}

PS_INLINE Rgb from_fixed_point(const uint64_t sum[3], uint64_t count) {
  const double scale = 1.0 / (double(kFixedPointScale) * double(count));
  return {float(double(sum[0]) * scale), float(double(sum[1]) * scale), float(double(sum[2]) * scale)};
}

// A table kept across frames (2021 paper sec. 3.4.3) stores a priority in the top bits of each
// fingerprint word, so keys are compared on the bits below kPriorityShift only.
inline constexpr int kPriorityShift = 24;
inline constexpr uint32_t kKeyBitsMask = (uint32_t(1) << kPriorityShift) - 1;

struct VoxelHashTableView {
  uint32_t* fingerprints = nullptr;
  VoxelCell* cells = nullptr;
  uint64_t mask = 0;   // cells - 1 (a power of two, at least kFingerprintsPerLine)
  int max_probes = kFingerprintsPerLine;
  // ~0: the whole word is the fingerprint (a table cleared every pass). kKeyBitsMask: a table kept
  // across frames, whose words carry priorities and whose evictions leave empty cells inside probe
  // sequences, so a key is looked for in the whole window before an empty cell is claimed.
  uint32_t key_mask = ~uint32_t(0);

  // The word a key's cell holds (without priority): never the empty sentinel.
  PS_HD uint32_t stored_fingerprint(const VoxelHash& h) const {
    const uint32_t f = h.fingerprint & key_mask;
    return f == kEmptyFingerprint ? 1u : f;
  }
  PS_HD bool kept_across_frames() const { return key_mask != ~uint32_t(0); }

  // The j-th cell of the probe sequence: wraps inside the home cache line when the limit fits in it.
  PS_HD uint64_t probe_slot(uint64_t home, int j) const {
    if (max_probes <= kFingerprintsPerLine)
      return (home & ~uint64_t(kFingerprintsPerLine - 1)) | ((home + uint64_t(j)) & uint64_t(kFingerprintsPerLine - 1));
    return (home + uint64_t(j)) & mask;
  }

  // Finds the cell of h or claims an empty one.
  PS_HD ProbeResult find_or_insert(const VoxelHash& h) const {
    const uint64_t home = h.index & mask;
    const uint32_t fp = stored_fingerprint(h);
    ProbeResult r;
    if (kept_across_frames()) {  // an earlier frame may have left the key behind an evicted (empty) cell
      for (int j = 0; j < max_probes; ++j) {
        const uint64_t slot = probe_slot(home, j);
        if ((atomic_load_relaxed(&fingerprints[slot]) & key_mask) == fp) {
          r.slot = int64_t(slot);
          r.probes = j + 1;
          return r;
        }
      }
    }
    for (int j = 0; j < max_probes; ++j) {
      const uint64_t slot = probe_slot(home, j);
      r.probes = j + 1;
      uint32_t seen = atomic_load_relaxed(&fingerprints[slot]);
      if (seen == kEmptyFingerprint) seen = atomic_cas(&fingerprints[slot], kEmptyFingerprint, fp);
      if (seen == kEmptyFingerprint || (seen & key_mask) == fp) {
        r.slot = int64_t(slot);
        return r;
      }
    }
    return r;
  }

  // Read-only lookup (after accumulation has finished).
  PS_HD ProbeResult find(const VoxelHash& h) const {
    const uint64_t home = h.index & mask;
    const uint32_t fp = stored_fingerprint(h);
    ProbeResult r;
    for (int j = 0; j < max_probes; ++j) {
      const uint64_t slot = probe_slot(home, j);
      r.probes = j + 1;
      const uint32_t seen = fingerprints[slot];
      if ((seen & key_mask) == fp) {
        r.slot = int64_t(slot);
        return r;
      }
      if (seen == kEmptyFingerprint && !kept_across_frames()) return r;
    }
    return r;
  }

  PS_HD void add(uint64_t slot, const uint64_t fixed[3]) const {
    VoxelCell& c = cells[slot];
    for (int i = 0; i < 3; ++i) atomic_fetch_add(&c.sum[i], fixed[i]);
    atomic_fetch_add(&c.count, uint64_t(1));
  }
};

}  // namespace pathspace
