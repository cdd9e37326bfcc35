// The two integrators that gather light at a shrinking radius, SPPM and PCLT, agree with BPT on every
// built-in Cornell variant (e_c, e_p, bs_c, gbs_c, glm_c, gbs_p, gbs_b, gbs_s), 24x24, by the
// per-pixel z-test with a binomial allowed-failure count and the image-mean test (support/
// statistics.h image_z_test, alpha_pixel 1e-3, alpha_image 0.01 Sidak over the 16 comparisons).
// PCLT renders wall pixels by projection (ED paths, unbiased) and glossy-surface pixels through its
// pixel cache (ES+D, radius bias like SPPM's); the default specular emission (ES+L from eye paths)
// makes its image complete (docs/pclt.md), so the same mask and allowance apply.
// BPT is the reference because, unlike PT, it samples caustics (light -> mirror/glass -> diffuse)
// from area, point, directional and environment lights with light-tracing strategies, and it has
// no radius bias. SPPM and PCLT are consistent but biased at any finite radius wherever the gathered light is
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
#include <vector>

#include "pathspace/accel/accel.h"
#include "pathspace/io/image_io.h"
#include "pathspace/scene/builtin_scenes.h"
#include "support/integrator_comparison.h"
#include "support/statistics.h"
#include "support/test_names.h"

namespace pathspace {
namespace {

using testing::compact_pixels;
using testing::Rendered;

constexpr int kComparisons = 16;  // 8 variants x {sppm, pclt}
const double kAlphaImage = testing::sidak(0.01, kComparisons);
constexpr int kSize = 24;

struct Case {
  const char* integrator;  // "sppm" or "pclt"
  const char* scene;
  uint64_t light_paths;  // photons (SPPM) or light paths (PCLT) per iteration
  uint32_t iterations;
  uint32_t bpt_passes;
};

// gtest prints the parameter in test listings (ctest names).
void PrintTo(const Case& c, std::ostream* os) { *os << c.integrator << " " << c.scene; }

class GatheringAgreesWithBpt : public ::testing::TestWithParam<Case> {};

constexpr float kInitialRadius = 0.04f;  // box side 2.56; ~0.017 after 128 iterations (alpha 2/3)

TEST_P(GatheringAgreesWithBpt, OnSmoothPixels) {
  const Case c = GetParam();
  const Scene scene = make_builtin_scene(c.scene, kSize, kSize);
  const Accel accel(scene);
  RenderConfig gather;
  if (std::string(c.integrator) == "sppm") {
    SppmSettings sppm;
    sppm.photons = c.light_paths;
    sppm.initial_radius = kInitialRadius;
    gather = make_render_config("sppm", sppm, testing::test_seed(31));
  } else {
    PcltSettings pclt;
    pclt.light_paths = c.light_paths;
    pclt.initial_radius = kInitialRadius;
    gather = make_render_config("pclt", pclt, testing::test_seed(31));
  }
  const Rendered a = testing::render_integrator(scene, accel, gather, c.iterations);
  const Rendered b = testing::render_integrator(scene, accel, make_render_config("bpt", BptSettings{}, testing::test_seed(32)), c.bpt_passes);
  const std::vector<bool> keep = testing::smooth_pixels(scene, accel, 3.f * kInitialRadius, false);
  const size_t kept = size_t(std::count(keep.begin(), keep.end(), true));
  EXPECT_GT(kept, keep.size() / 3) << "the mask should keep most wall and floor pixels";
  const testing::ImageZTest z = testing::image_z_test(compact_pixels(a.mean, keep), compact_pixels(a.variance, keep),
                                                      compact_pixels(b.mean, keep), compact_pixels(b.variance, keep), 1e-3,
                                                      kAlphaImage);
  std::printf("%s %s: kept %zu of %zu pixels; %zu failed (allowed %zu); means %.5f vs %.5f (z = %.2f)\n", c.integrator, c.scene, kept,
              keep.size(), z.failed, z.allowed, z.mean_a, z.mean_b, z.mean_z);
  EXPECT_TRUE(z.passed()) << c.integrator << " " << c.scene << ": " << z.failed << " of " << z.pixels << " pixels differ (at most " << z.allowed
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
  const std::string stem = dir + "/" + c.integrator + "-vs-bpt-" + c.scene;
  write_image(stem + "-" + c.integrator + ".exr", a.mean);
  write_image(stem + "-bpt.exr", b.mean);
}

// 10^5 light paths per iteration (10^6 for gbs_b, whose light reaches the box only through a small
// opening), 128 iterations; BPT 512 passes.
std::vector<Case> cases() {
  std::vector<Case> all;
  for (const char* integrator : {"sppm", "pclt"})
    for (const char* scene : {"e_c", "e_p", "bs_c", "gbs_c", "glm_c", "gbs_p", "gbs_b", "gbs_s"})
      all.push_back(Case{integrator, scene, std::string(scene) == "gbs_b" ? 1000000u : 100000u, 128, 512});
  return all;
}

INSTANTIATE_TEST_SUITE_P(Cornell, GatheringAgreesWithBpt, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return testing::test_name(std::string(info.param.integrator) + "_" + info.param.scene); });

}  // namespace
}  // namespace pathspace
