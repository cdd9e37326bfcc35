// Voxel keys of hashed path space filtering (Binder, Fricke, Keller 2021, sec. 3.1 and algorithm 1).
// A key quantises a vertex descriptor: its position at a level of detail chosen from the distance
// along the path (voxel edge ~ psf_scale projected pixels, sec. 3.1.1 and 4), optionally its normal
// (sec. 3.1.2, either in the main key or only in the fingerprint so that probing separates normals,
// sec. 3.2.2), the incident direction on glossy layers and the material layer id (sec. 3.1.2).
// The position is jittered in the tangent plane before quantisation, and the level recomputed at
// the jittered point (sec. 3.1.4, algorithm 1).
#pragma once

#include <cstdint>
#include <cstring>

#include "pathspace/math/frame.h"
#include "pathspace/sampling/hash.h"

namespace pathspace {

enum class NormalKeyMode : uint8_t { off, key, fingerprint };

struct VoxelKeySettings {
  float psf_scale = 12.f;         // voxel edge in projected pixels at the path distance (docs/benchmarks.md: relMSE study)
  float pixel_angle = 1e-3f;      // projected size of one pixel at distance 1 (camera)
  bool jitter = true;             // sec. 3.1.4; off reproduces the block artefacts of fig. 6c
  NormalKeyMode normal = NormalKeyMode::key;
  int normal_bins = 5;            // octahedral bins per axis (odd: axis-aligned normals sit mid-bin)
  int direction_bins = 6;         // octahedral bins per axis for the incident direction on glossy layers
  float glossy_roughness = 0.5f;  // layers smoother than this add their incident direction to the key
};

// A quantised key; `cell` at level `level` has edge 2^level world units.
struct VoxelKey {
  int32_t cell[3] = {0, 0, 0};
  int16_t level = 0;
  uint16_t normal_bin = 0;     // 0 when normals are not used
  uint16_t direction_bin = 0;  // 0 on diffuse layers
  uint8_t layer = 0;
  // Index of the vertex among its path's selected vertices: with several selected vertices per path
  // the last one owns the whole tail of the path and the others one segment each, so their
  // contributions estimate different quantities and must not share an average.
  uint8_t selected = 0;
};

// The two hashes of algorithm 1: the table index and a 32-bit fingerprint (0 is the empty sentinel).
inline constexpr uint32_t kEmptyFingerprintValue = 0;
struct VoxelHash {
  uint64_t index = 0;
  uint32_t fingerprint = 0;
};

// Octahedral map of a unit vector to [0,1]^2, quantised to bins x bins.
PS_INLINE uint16_t octahedral_bin(const Vec3& v, int bins) {
  const float l1 = fabsf(v.x) + fabsf(v.y) + fabsf(v.z);
  float u = v.x / l1, w = v.y / l1;
  if (v.z < 0.f) {
    const float uu = (1.f - fabsf(w)) * (u >= 0.f ? 1.f : -1.f);
    w = (1.f - fabsf(u)) * (w >= 0.f ? 1.f : -1.f);
    u = uu;
  }
  const int iu = min_int(bins - 1, max_int(0, int((u * 0.5f + 0.5f) * float(bins))));
  const int iw = min_int(bins - 1, max_int(0, int((w * 0.5f + 0.5f) * float(bins))));
  return uint16_t(1 + iu * bins + iw);
}

// Level of detail: the power-of-two voxel edge nearest to psf_scale projected pixels at distance d,
// i.e. round(log2(target)) = floor(log2(target * sqrt 2)), read off the float's exponent bits (this
// runs for every vertex; log2f was a visible part of the filter's cost).
PS_INLINE int level_of_detail(const VoxelKeySettings& s, float distance) {
  const float target = s.psf_scale * s.pixel_angle * fmaxf(distance, 1e-6f) * 1.41421356f;
  uint32_t bits;
  memcpy(&bits, &target, sizeof bits);
  return max_int(-60, min_int(60, int((bits >> 23) & 0xffu) - 127));
}

// 2^level for |level| <= 126, built from the exponent bits.
PS_INLINE float power_of_two(int level) {
  const uint32_t bits = uint32_t(127 + level) << 23;
  float f;
  memcpy(&f, &bits, sizeof f);
  return f;
}

PS_INLINE float level_edge(int level) { return power_of_two(level); }

PS_INLINE int32_t quantize(float x, int level) { return int32_t(floorf(x * power_of_two(-level))); }

struct VoxelKeyInput {
  Vec3 p, ng, ns, wo, prev_p;
  float prefix_distance;
  float roughness;
  uint8_t layer;
  uint8_t selected;
};

// Algorithm 1. `jitter_u` are two uniform numbers in [0,1) (a pure function of the vertex's path).
PS_INLINE VoxelKey make_voxel_key(const VoxelKeySettings& s, const VoxelKeyInput& v, float jitter_u0, float jitter_u1) {
  VoxelKey k;
  const int l = level_of_detail(s, v.prefix_distance + length(v.p - v.prev_p));
  Vec3 x = v.p;
  int lj = l;
  if (s.jitter) {
    const Frame tangent(v.ng);
    const float edge = level_edge(l);
    x = v.p + tangent.s * ((jitter_u0 - 0.5f) * edge) + tangent.t * ((jitter_u1 - 0.5f) * edge);
    lj = level_of_detail(s, v.prefix_distance + length(x - v.prev_p));
  }
  k.level = int16_t(lj);
  k.cell[0] = quantize(x.x, lj);
  k.cell[1] = quantize(x.y, lj);
  k.cell[2] = quantize(x.z, lj);
  if (s.normal != NormalKeyMode::off) k.normal_bin = octahedral_bin(v.ns, s.normal_bins);
  if (v.roughness < s.glossy_roughness) k.direction_bin = octahedral_bin(v.wo, s.direction_bins);
  k.layer = v.layer;
  k.selected = v.selected;
  return k;
}

// The same key one level coarser (multi-level accumulation, sec. 3.3.2).
PS_INLINE VoxelKey coarser_key(VoxelKey k) {
  for (int i = 0; i < 3; ++i) k.cell[i] >>= 1;  // arithmetic shift = floor(c / 2)
  k.level = int16_t(k.level + 1);
  return k;
}

// The key packed into two words without loss: word 0 holds cell x and y, word 1 cell z, the level
// and the attributes (bins are limited to kMaxKeyBins per axis so they fit in 10 bits).
inline constexpr int kMaxKeyBins = 31;

PS_INLINE uint64_t key_position_word(const VoxelKey& k) { return (uint64_t(uint32_t(k.cell[0])) << 32) | uint32_t(k.cell[1]); }

PS_INLINE uint64_t key_attribute_word(const VoxelKey& k, bool with_normal) {
  return (uint64_t(uint32_t(k.cell[2])) << 32) | (uint64_t(uint8_t(k.level)) << 24) | (uint64_t(k.layer & 3u) << 22) |
         (uint64_t(k.selected & 3u) << 20) | (uint64_t(k.direction_bin & 1023u) << 10) |
         (with_normal ? uint64_t(k.normal_bin & 1023u) : 0u);
}

PS_INLINE VoxelHash hash_voxel_key(const VoxelKey& k, NormalKeyMode normal_mode) {
  const uint64_t position = key_position_word(k);
  VoxelHash h;
  // Table index: a fast mix of the key (with or without the normal, sec. 3.2.2).
  h.index = mix64(position ^ mix64(key_attribute_word(k, normal_mode == NormalKeyMode::key)));
  // Fingerprint: a second, different hash of the full key (sec. 3.2.1).
  const uint64_t f = mix64(mix64(key_attribute_word(k, true) ^ 0x5bd1e9955bd1e995ull) + position * 0x2545f4914f6cdd1dull);
  h.fingerprint = uint32_t(f >> 32);
  if (h.fingerprint == kEmptyFingerprintValue) h.fingerprint = 1;
  return h;
}

}  // namespace pathspace
