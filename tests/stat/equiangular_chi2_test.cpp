// Chi-square tests of equiangular distance sampling (media/equiangular.h) against its density, for a
// point beside a finite segment, one whose projection lies before the segment, one close to the ray
// (a sharp peak), and a segment to infinity (t mapped to x = t / (1 + t)); and its normalisation
// (the density integrates to 1 over the segment, by quadrature).
// Significance: alpha = 0.01 for the file, Sidak-corrected over its kChi2Tests tests.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "pathspace/media/equiangular.h"
#include "support/chi2.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

struct Case {
  const char* name;
  Vec3 point;
  float t0, t1;
};
const Case kCases[] = {
    {"beside", Vec3(0.4f, 1.2f, 0.3f), 0.2f, 3.f},
    {"behind", Vec3(-1.5f, 0.5f, 0.f), 0.5f, 4.f},
    {"close", Vec3(0.01f, 1.f, 2.f), 0.f, 5.f},
    {"to_infinity", Vec3(0.3f, -0.8f, 1.f), 0.1f, INFINITY},
};
constexpr int kChi2Tests = 4;
const double kAlpha = testing::sidak(0.01, kChi2Tests);
const Vec3 kOrigin(0.f, 0.f, 0.f);
const Vec3 kDirection = normalize(Vec3(0.f, 0.6f, 0.8f));

class Equiangular : public ::testing::TestWithParam<int> {};

// x in [0, 1): t0 + x (t1 - t0), or t = x / (1 - x) for the infinite segment.
double to_t(const Case& c, double x) { return std::isinf(c.t1) ? x / (1.0 - x) : c.t0 + x * (c.t1 - c.t0); }
double dt_dx(const Case& c, double x) { return std::isinf(c.t1) ? 1.0 / ((1.0 - x) * (1.0 - x)) : c.t1 - c.t0; }

TEST_P(Equiangular, SamplingMatchesDensity) {
  const Case& c = kCases[GetParam()];
  const EquiangularFrame f = equiangular_frame(kOrigin, kDirection, c.t0, c.t1, c.point);
  ASSERT_TRUE(f.valid());
  testing::Chi2Options o;
  o.name = std::string("equiangular_") + c.name;
  o.seed = 31 + uint64_t(GetParam());
  o.alpha = kAlpha;
  testing::Grid2 grid;
  grid.nx = 400;
  grid.ny = 1;
  int bad = 0;
  const auto r = testing::grid_chi2(
      grid,
      [&](Pcg32& rng) {
        float pdf;
        const float t = sample_equiangular(f, rng.next_float(), c.t0, c.t1, &pdf);
        if (!(std::fabs(pdf - equiangular_pdf(f, t)) <= 1e-5f * pdf)) ++bad;
        const double x = std::isinf(c.t1) ? double(t) / (1.0 + t) : (double(t) - c.t0) / (double(c.t1) - c.t0);
        return testing::Outcome{0, x, 0.5, {}};
      },
      [&](double x, double) {
        const double t = to_t(c, x);
        return t < c.t0 ? 0.0 : double(equiangular_pdf(f, float(t))) * dt_dx(c, x);
      },
      o);
  std::printf("%s: chi2 %.1f dof %.0f p %.4f\n", c.name, r.statistic, r.dof, r.p_value);
  EXPECT_TRUE(r.passed(kAlpha)) << c.name << ": chi2 " << r.statistic << " dof " << r.dof << " p " << r.p_value << " " << r.error
                                << "; evidence: " << r.evidence;
  EXPECT_EQ(bad, 0) << "the returned density must be equiangular_pdf at the sample";
}

TEST_P(Equiangular, DensityIntegratesToOne) {
  const Case& c = kCases[GetParam()];
  const EquiangularFrame f = equiangular_frame(kOrigin, kDirection, c.t0, c.t1, c.point);
  constexpr int n = 400000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = (double(i) + 0.5) / n, t = to_t(c, x);
    if (t >= c.t0) sum += double(equiangular_pdf(f, float(t))) * dt_dx(c, x) / n;
  }
  EXPECT_NEAR(sum, 1.0, 2e-3) << c.name;
}

INSTANTIATE_TEST_SUITE_P(Segments, Equiangular, ::testing::Range(0, 4));

}  // namespace
}  // namespace pathspace
