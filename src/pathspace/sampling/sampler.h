// Deterministic sampler: sample(seed, pixel, sample_index, dimension) is a pure function, so a
// render is bit-identical for every thread count and schedule (docs/architecture.md §5).
// Dimensions are consumed in a fixed layout per path (see integrators/common/dimensions.h).
#pragma once

#include <cstdint>

#include "pathspace/sampling/hash.h"

namespace pathspace {

class Sampler {
 public:
  PS_HD Sampler(uint64_t seed, uint64_t pixel_or_path, uint64_t sample_index)
      : base_(hash_combine(hash_combine(mix64(seed), pixel_or_path), sample_index)) {}

  // The value of one dimension (random access).
  PS_HD float at(uint32_t dimension) const { return bits_to_unit_float(mix64(base_ + (uint64_t(dimension) + 1) * kGoldenGamma)); }

  // 64 random bits of one dimension (seeds a Pcg32 stream where a path needs an unbounded count of
  // numbers, as delta tracking does); independent of at(dimension) for practical purposes.
  PS_HD uint64_t bits(uint32_t dimension) const { return mix64(~base_ + (uint64_t(dimension) + 1) * kGoldenGamma); }

  // Sequential access from a cursor; set_dimension jumps to a fixed offset.
  PS_HD float next_1d() { return at(dimension_++); }
  PS_HD void set_dimension(uint32_t d) { dimension_ = d; }
  PS_HD uint32_t dimension() const { return dimension_; }

 private:
  uint64_t base_;
  uint32_t dimension_ = 0;
};

}  // namespace pathspace
