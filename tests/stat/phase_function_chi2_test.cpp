// Chi-square tests of the Henyey-Greenstein phase function's sampling (media/henyey_greenstein.h)
// against its density, for isotropic, forward, backward and strongly peaked lobes around a tilted
// travel direction; and its normalisation (the density integrates to 1 over the sphere).
// Significance: alpha = 0.01 for the file, Sidak-corrected over its kChi2Tests tests.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "pathspace/media/henyey_greenstein.h"
#include "support/chi2.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

const float kGs[] = {0.f, 0.3f, -0.5f, 0.85f, -0.95f};
constexpr int kChi2Tests = 5;
const double kAlpha = testing::sidak(0.01, kChi2Tests);

class HenyeyGreenstein : public ::testing::TestWithParam<int> {};

TEST_P(HenyeyGreenstein, SamplingMatchesDensity) {
  const float g = kGs[GetParam()];
  const Vec3 travel = normalize(Vec3(0.3f, -0.5f, 0.8f));
  testing::Chi2Options o;
  o.name = "hg_" + std::to_string(GetParam());
  o.seed = 17 + uint64_t(GetParam());
  o.alpha = kAlpha;
  testing::SphereBins bins;
  bins.axis = travel;  // bins around the lobe's axis resolve strongly peaked lobes
  const auto r = testing::direction_chi2(
      bins, [&](Pcg32& rng) { return testing::Outcome{0, 0, 0, hg_sample(travel, g, {rng.next_float(), rng.next_float()})}; },
      [&](const Vec3& w) { return double(hg_phase(dot(travel, w), g)); }, o);
  std::printf("g %.2f: chi2 %.1f dof %.0f p %.4f\n", g, r.statistic, r.dof, r.p_value);
  EXPECT_TRUE(r.passed(kAlpha)) << "g " << g << ": chi2 " << r.statistic << " dof " << r.dof << " p " << r.p_value << " "
                                << r.error << "; evidence: " << r.evidence;
}

TEST_P(HenyeyGreenstein, DensityIntegratesToOne) {
  const float g = kGs[GetParam()];
  // The density depends on the cosine alone: 2 pi times its integral over cos in [-1, 1] (midpoint rule).
  constexpr int n = 200000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += hg_phase(-1.f + 2.f * (float(i) + 0.5f) / float(n), g);
  EXPECT_NEAR(2.0 * M_PI * sum * 2.0 / n, 1.0, 2e-3) << "g " << g;
}

INSTANTIATE_TEST_SUITE_P(Lobes, HenyeyGreenstein, ::testing::Range(0, 5));

}  // namespace
}  // namespace pathspace
