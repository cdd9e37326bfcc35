// PCG32 (O'Neill 2014, pcg-random.org): small, fast, statistically strong generator for tests,
// light path seeding and anywhere a sequential stream is natural.
#pragma once

#include <cstdint>

#include "pathspace/sampling/hash.h"

namespace pathspace {

class Pcg32 {
 public:
  PS_HD Pcg32() { seed(0x853c49e6748fea9bull, 0xda3e39cb94b95bdbull); }
  PS_HD Pcg32(uint64_t init_state, uint64_t init_seq) { seed(init_state, init_seq); }

  PS_HD void seed(uint64_t init_state, uint64_t init_seq) {
    state_ = 0u;
    inc_ = (init_seq << 1u) | 1u;
    next_u32();
    state_ += init_state;
    next_u32();
  }

  PS_HD uint32_t next_u32() {
    const uint64_t old = state_;
    state_ = old * kMultiplier + inc_;
    const uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    const uint32_t rot = uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31u));
  }

  // Uniform in [0, 1), 24 significant bits (never returns 1).
  PS_HD float next_float() { return float(next_u32() >> 8) * 0x1p-24f; }
  PS_HD double next_double() {
    const uint64_t hi = next_u32(), lo = next_u32();
    return double(((hi << 32) | lo) >> 11) * 0x1p-53;
  }
  // Unbiased integer in [0, bound).
  PS_HD uint32_t next_bounded(uint32_t bound) {
    const uint32_t threshold = (~bound + 1u) % bound;
    for (;;) {
      const uint32_t r = next_u32();
      if (r >= threshold) return r % bound;
    }
  }

  // Jump ahead by delta steps in O(log delta) (Brown, "Random number generation with arbitrary strides").
  PS_HD void advance(uint64_t delta) {
    uint64_t cur_mult = kMultiplier, cur_plus = inc_, acc_mult = 1u, acc_plus = 0u;
    while (delta > 0) {
      if (delta & 1) {
        acc_mult *= cur_mult;
        acc_plus = acc_plus * cur_mult + cur_plus;
      }
      cur_plus = (cur_mult + 1) * cur_plus;
      cur_mult *= cur_mult;
      delta /= 2;
    }
    state_ = acc_mult * state_ + acc_plus;
  }

 private:
  static constexpr uint64_t kMultiplier = 0x5851f42d4c957f2dull;
  uint64_t state_ = 0, inc_ = 0;
};

}  // namespace pathspace
