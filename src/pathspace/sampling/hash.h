// 64-bit integer mixing (SplitMix64 finaliser, Steele et al. 2014). The deterministic sampler and
// per-path seeds are built from it so that every random number is a pure function of its indices.
#pragma once

#include <cstdint>

#include "pathspace/base/platform.h"

namespace pathspace {

PS_INLINE uint64_t mix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

inline constexpr uint64_t kGoldenGamma = 0x9e3779b97f4a7c15ull;

PS_INLINE uint64_t hash_combine(uint64_t seed, uint64_t value) { return mix64(seed ^ mix64(value + kGoldenGamma)); }

// The bits of a float (for hashing values: -0 and +0 differ, as do NaN payloads).
PS_INLINE uint64_t float_bits(float x) {
  union {
    float f;
    uint32_t u;
  } v{x};
  return uint64_t(v.u);
}

// Top 24 bits -> float in [0, 1): exactly representable, never 1.
PS_INLINE float bits_to_unit_float(uint64_t bits) { return float(bits >> 40) * 0x1p-24f; }

}  // namespace pathspace
