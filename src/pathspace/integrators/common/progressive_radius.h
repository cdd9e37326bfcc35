// The global radius of progressive photon mapping with the Knaus-Zwicker update (Knaus and Zwicker
// 2011; PCLT paper eq. 1): pass 0 (0-based) has r0, and r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1) with
// the 1-based iteration number i. One recurrence for SPPM, PCLT and the path tracer's caustic
// photons. The value of a pass is cached, so consecutive passes cost one step each; the cache is
// part of a checkpoint, under its owner's keys.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>

#include "pathspace/base/state_archive.h"

namespace pathspace {

class ProgressiveRadius {
 public:
  ProgressiveRadius() = default;
  ProgressiveRadius(float r0, double alpha) : r0_(r0), alpha_(alpha), cached_r2_(double(r0) * double(r0)) {}

  float initial() const { return r0_; }
  float at(uint32_t pass) {
    if (pass < cached_pass_) {
      cached_pass_ = 0;
      cached_r2_ = double(r0_) * double(r0_);
    }
    for (; cached_pass_ < pass; ++cached_pass_) {
      const double i = double(cached_pass_) + 1.0;
      cached_r2_ *= (i + alpha_) / (i + 1.0);
    }
    return float(std::sqrt(cached_r2_));
  }

  // "<owner>.cached_pass" and "<owner>.cached_r2".
  void save_state(StateWriter& out, const std::string& owner) const {
    out.put(owner + ".cached_pass", cached_pass_);
    out.put(owner + ".cached_r2", cached_r2_);
  }
  void load_state(StateReader& in, const std::string& owner) {
    in.get(owner + ".cached_pass", &cached_pass_);
    in.get(owner + ".cached_r2", &cached_r2_);
  }

 private:
  float r0_ = 0.f;
  double alpha_ = 0.0;
  uint32_t cached_pass_ = 0;  // the pass whose r^2 is cached_r2_
  double cached_r2_ = 0.0;
};

}  // namespace pathspace
