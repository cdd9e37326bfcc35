// Discrete distribution over N items by a CDF table, for light selection (uniform or by power).
// The owning class is host-side; DiscreteView is the device-safe read-only view kernels use.
#pragma once

#include <cstdint>
#include <vector>

#include "pathspace/base/platform.h"

namespace pathspace {

struct DiscreteView {
  const float* cdf = nullptr;  // cdf[0] = 0, cdf[n] = 1; n + 1 entries
  const float* pmf = nullptr;
  uint32_t n = 0;

  // Sample an index with u in [0,1); returns the index and writes its probability.
  PS_HD uint32_t sample(float u, float* prob) const {
    uint32_t lo = 0, hi = n;  // find largest i with cdf[i] <= u
    while (lo + 1 < hi) {
      const uint32_t mid = (lo + hi) / 2;
      if (cdf[mid] <= u) lo = mid;
      else hi = mid;
    }
    while (pmf[lo] == 0.f && lo + 1 < n) ++lo;  // never return a zero-probability item
    *prob = pmf[lo];
    return lo;
  }
  PS_HD float probability(uint32_t i) const { return i < n ? pmf[i] : 0.f; }
};

class DiscreteDistribution {
 public:
  DiscreteDistribution() = default;
  explicit DiscreteDistribution(const std::vector<float>& weights) { build(weights); }

  void build(const std::vector<float>& weights) {
    const size_t n = weights.size();
    pmf_.assign(n, 0.f);
    cdf_.assign(n + 1, 0.f);
    double total = 0.0;
    for (float w : weights) total += (w > 0.f ? w : 0.f);
    double acc = 0.0;
    for (size_t i = 0; i < n; ++i) {
      const double w = weights[i] > 0.f ? weights[i] : 0.f;
      pmf_[i] = total > 0.0 ? float(w / total) : 1.f / float(n);
      acc += total > 0.0 ? w / total : 1.0 / double(n);
      cdf_[i + 1] = float(acc);
    }
    if (n > 0) cdf_[n] = 1.f;
  }

  DiscreteView view() const { return {cdf_.data(), pmf_.data(), uint32_t(pmf_.size())}; }
  size_t size() const { return pmf_.size(); }

 private:
  std::vector<float> cdf_, pmf_;
};

}  // namespace pathspace
