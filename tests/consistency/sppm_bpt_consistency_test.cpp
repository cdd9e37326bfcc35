// SPPM agrees with BPT on every built-in Cornell variant (e_c, e_p, bs_c, gbs_c, glm_c, gbs_p, gbs_b,
// gbs_s), 24x24, by the per-pixel z-test with a binomial allowed-failure count and the image-mean test
// (support/statistics.h image_z_test, alpha_pixel 1e-3, alpha_image 0.01 Sidak over the 8 variants).
// BPT is the reference because, unlike PT, it samples caustics (light -> mirror/glass -> diffuse)
// from area, point, directional and environment lights with light-tracing strategies, and it has
// no radius bias. SPPM is consistent but biased at any finite radius wherever the gathered light is
// not smooth over the radius ball, so only "smooth pixels" are compared (support/
// integrator_comparison.h smooth_pixels, the mask of sppm_pt_consistency_test.cpp with reach 3 r_0):
// masked are pixels whose 4x4 sub-pixel camera rays do not all hit one plane of one non-delta,
// non-emitting material, or from whose hits 8 probe rays along the plane hit something within 3 r_0.
// That removes the box edges and corners (the ball reaches the adjacent wall), the light and the
// ceiling around it, the spheres (visible points behind delta bounces land anywhere) and the floor
// around the spheres' contact points. Unlike the PT comparison the ceiling stays in for the glossy
// scenes: BPT's light-tracing strategies sample its caustics without PT's heavy tail. What is left
// biased (shadow and caustic boundaries on walls and floor, at the final radius a fraction of a
// pixel) is what the binomial failure allowance absorbs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/render.h"
#include "pathspace/io/image_io.h"
#include "pathspace/scene/builtin_scenes.h"
#include "support/integrator_comparison.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

using testing::compact_pixels;
using testing::Rendered;

constexpr int kComparisons = 8;  // the variants below
const double kAlphaImage = testing::sidak(0.01, kComparisons);
constexpr int kSize = 24;

struct Case {
  const char* scene;
  uint64_t photons;  // per SPPM iteration
  uint32_t sppm_iterations;
  uint32_t bpt_passes;
};

// gtest prints the parameter in test listings (ctest names); the scene id says it all.
void PrintTo(const Case& c, std::ostream* os) { *os << c.scene; }

class SppmAgreesWithBpt : public ::testing::TestWithParam<Case> {};

TEST_P(SppmAgreesWithBpt, OnSmoothPixels) {
  const Case c = GetParam();
  const Scene scene = make_builtin_scene(c.scene, kSize, kSize);
  const Accel accel(scene);
  IntegratorSettings sppm, bpt;
  sppm.seed = testing::test_seed_base() + 31;
  sppm.sppm.photons = c.photons;
  sppm.sppm.initial_radius = 0.04f;  // box side 2.56; ~0.017 after 128 iterations (alpha 2/3)
  bpt.seed = testing::test_seed_base() + 32;
  const Rendered a = testing::render_integrator(scene, accel, "sppm", sppm, c.sppm_iterations, 0);
  const Rendered b = testing::render_integrator(scene, accel, "bpt", bpt, c.bpt_passes, 0);
  const std::vector<bool> keep = testing::smooth_pixels(scene, accel, 3.f * sppm.sppm.initial_radius, false);
  const size_t kept = size_t(std::count(keep.begin(), keep.end(), true));
  EXPECT_GT(kept, keep.size() / 3) << "the mask should keep most wall and floor pixels";
  const testing::ImageZTest z = testing::image_z_test(compact_pixels(a.mean, keep), compact_pixels(a.variance, keep),
                                                      compact_pixels(b.mean, keep), compact_pixels(b.variance, keep), 1e-3,
                                                      kAlphaImage);
  std::printf("%s: kept %zu of %zu pixels; %zu failed (allowed %zu); means %.5f vs %.5f (z = %.2f)\n", c.scene, kept,
              keep.size(), z.failed, z.allowed, z.mean_a, z.mean_b, z.mean_z);
  EXPECT_TRUE(z.passed()) << c.scene << ": " << z.failed << " of " << z.pixels << " pixels differ (at most " << z.allowed
                          << " allowed); image means " << z.mean_a << " vs " << z.mean_b << " (z = " << z.mean_z << ")";
  if (z.passed()) return;
  for (size_t i = 0; i < keep.size(); ++i) {
    if (!keep[i]) continue;
    const double d = average(a.mean.pixels[i]) - average(b.mean.pixels[i]);
    const double sd = std::sqrt(average(a.variance.pixels[i]) + average(b.variance.pixels[i]) + 1e-8);
    if (std::fabs(d / sd) > 3.29)
      ADD_FAILURE() << "pixel (" << i % kSize << ", " << i / kSize << "): " << average(a.mean.pixels[i]) << " vs "
                    << average(b.mean.pixels[i]) << " (z " << d / sd << ")";
  }
  const std::string dir = testing::evidence_dir();
  write_image(dir + "/sppm-vs-bpt-" + c.scene + "-sppm.exr", a.mean);
  write_image(dir + "/sppm-vs-bpt-" + c.scene + "-bpt.exr", b.mean);
}

INSTANTIATE_TEST_SUITE_P(Cornell, SppmAgreesWithBpt,
                         ::testing::Values(Case{"e_c", 100000, 128, 512}, Case{"e_p", 100000, 128, 512},
                                           Case{"bs_c", 100000, 128, 512}, Case{"gbs_c", 100000, 128, 512},
                                           Case{"glm_c", 100000, 128, 512}, Case{"gbs_p", 100000, 128, 512},
                                           Case{"gbs_b", 1000000, 128, 512}, Case{"gbs_s", 100000, 128, 512}),
                         [](const auto& info) { return std::string(info.param.scene); });

}  // namespace
}  // namespace pathspace
