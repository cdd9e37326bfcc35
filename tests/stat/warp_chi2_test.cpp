// Chi-square tests of every warp in sampling/warps.h against its density. Round trips through the
// inverses are covered by tests/unit/sampling_test.cpp (Warps.RoundTrips).
// Significance: alpha = 0.01 for the file, Sidak-corrected over its kChi2Tests chi-square tests.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "pathspace/sampling/warps.h"
#include "support/chi2.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

constexpr int kChi2Tests = 11;
const double kAlpha = testing::sidak(0.01, kChi2Tests);

Point2 next_point(Pcg32& rng) { return {rng.next_float(), rng.next_float()}; }

testing::Chi2Options options(const char* name, uint64_t seed) {
  testing::Chi2Options o;
  o.name = name;
  o.seed = seed;
  o.alpha = kAlpha;
  return o;
}

void expect_pass(const testing::Chi2Result& r) {
  std::printf("chi2 %.1f dof %.0f p %.4f\n", r.statistic, r.dof, r.p_value);
  EXPECT_TRUE(r.passed(kAlpha)) << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.p_value << " < "
                                << kAlpha << " " << r.error << "; evidence: " << r.evidence;
}

// Sphere-valued warps: sample with `warp`, compare against `pdf`.
template <class Warp, class Pdf>
void direction_test(const char* name, uint64_t seed, Warp warp, Pdf pdf) {
  const auto r = testing::direction_chi2(
      {}, [&](Pcg32& rng) { return testing::Outcome{0, 0, 0, warp(next_point(rng))}; },
      [&](const Vec3& w) { return double(pdf(w)); }, options(name, seed));
  expect_pass(r);
}

TEST(WarpChi2, DiskConcentric) {
  const testing::Grid2 grid{-1, 1, -1, 1, 51, 51};
  const auto r = testing::grid_chi2(
      grid,
      [](Pcg32& rng) {
        const Point2 p = square_to_disk_concentric(next_point(rng));
        return testing::Outcome{0, p.x, p.y, {}};
      },
      [](double x, double y) { return x * x + y * y < 1.0 ? 1.0 / M_PI : 0.0; }, options("warp_disk", 1));
  expect_pass(r);
}

TEST(WarpChi2, TriangleBarycentric) {
  const testing::Grid2 grid{0, 1, 0, 1, 51, 51};
  const auto r = testing::grid_chi2(
      grid,
      [](Pcg32& rng) {
        const Point2 b = square_to_triangle_barycentric(next_point(rng));
        return testing::Outcome{0, b.x, b.y, {}};
      },
      [](double x, double y) { return x + y <= 1.0 ? 2.0 : 0.0; }, options("warp_triangle", 2));
  expect_pass(r);
}

TEST(WarpChi2, CosineHemisphere) {
  direction_test("warp_cosine_hemisphere", 3, square_to_cosine_hemisphere, cosine_hemisphere_pdf);
}

TEST(WarpChi2, UniformSphere) {
  direction_test("warp_uniform_sphere", 4, square_to_uniform_sphere, [](const Vec3&) { return uniform_sphere_pdf(); });
}

TEST(WarpChi2, UniformHemisphere) {
  direction_test("warp_uniform_hemisphere", 5, square_to_uniform_hemisphere,
                 [](const Vec3& w) { return w.z >= 0.f ? uniform_hemisphere_pdf() : 0.f; });
}

TEST(WarpChi2, UniformCone) {
  for (const float cos_max : {0.7f, 0.995f, -0.3f}) {
    SCOPED_TRACE(cos_max);
    direction_test(
        "warp_uniform_cone", 6, [&](Point2 u) { return square_to_uniform_cone(u, cos_max); },
        [&](const Vec3& w) { return w.z >= cos_max ? uniform_cone_pdf(cos_max) : 0.f; });
  }
}

TEST(WarpChi2, PowerCosine) {
  for (const float n : {1.f, 10.f, 100.f}) {
    SCOPED_TRACE(n);
    direction_test(
        "warp_power_cosine", 7, [&](Point2 u) { return square_to_power_cosine(u, n); },
        [&](const Vec3& w) { return power_cosine_pdf(w, n); });
  }
}

}  // namespace
}  // namespace pathspace
