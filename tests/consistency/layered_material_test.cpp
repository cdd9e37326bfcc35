// Layered materials (materials/layered_bsdf.h) in whole renders: the empty Cornell box (SmallVCM
// e_c) with its walls replaced by coated materials (a Lambertian base under a smooth or rough coat,
// one with a scattering slab, and a rough conductor under a coat) renders the same image with PT,
// BPT and LT (per-pixel z-tests, alpha = 0.01 Sidak-corrected over kComparisons). BPT weights its
// strategies with the layered BSDF's forward and reverse pdfs, and LT connects to the camera
// through eval in importance mode, so agreement checks that eval, pdf and sample fit together in
// both transport modes. LT cannot see a smooth coat's mirror lobe directly, so LT compares against
// PT with rough coats only. SPPM and PCLT (photons and light paths scattered by the layered BSDF;
// SPPM gathers at coated visible points, PCLT's eye paths scatter through them to the white walls'
// pixel cache) agree with BPT on the smooth pixels, as in gathering_bpt_consistency_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "pathspace/integrators/bpt/bpt_settings.h"
#include "pathspace/integrators/lt/lt_settings.h"
#include "pathspace/integrators/pclt/pclt_settings.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/integrators/sppm/sppm_settings.h"
#include "pathspace/scene/builtin_scenes.h"
#include "support/integrator_comparison.h"
#include "support/statistics.h"
#include "support/test_scenes.h"

namespace pathspace {
namespace {

constexpr int kComparisons = 4;
const double kAlphaImage = testing::sidak(0.01, kComparisons);

TEST(LayeredMaterial, BidirectionalPathTracingAgreesWithPathTracing) {
  const Scene scene = testing::make_coated_cornell_box(16, true);
  const testing::Rendered bpt =
      testing::render_integrator(scene, make_render_config("bpt", BptSettings{}, testing::test_seed(501)), 256);
  const testing::Rendered pt =
      testing::render_integrator(scene, make_render_config("pt", PtSettings{}, testing::test_seed(502)), 1024);
  testing::expect_same_image(bpt, pt, "layered-bpt-vs-pt", kAlphaImage, "bpt", "pt");
}

TEST(LayeredMaterial, LightTracingAgreesWithPathTracing) {
  const Scene scene = testing::make_coated_cornell_box(16, false);
  LtSettings lt;
  lt.light_paths = 4096;
  const testing::Rendered a = testing::render_integrator(scene, make_render_config("lt", lt, testing::test_seed(503)), 256);
  const testing::Rendered b =
      testing::render_integrator(scene, make_render_config("pt", PtSettings{}, testing::test_seed(504)), 1024);
  testing::expect_same_image(a, b, "layered-lt-vs-pt", kAlphaImage, "lt", "pt");
}

TEST(LayeredMaterial, GatheringAgreesWithBidirectionalPathTracing) {
  const Scene scene = testing::make_coated_cornell_box(16, false, true);
  const Accel accel(scene);
  constexpr float kRadius = 0.04f;  // box side 2.56; ~0.017 after 128 iterations (alpha 2/3)
  SppmSettings sppm;
  sppm.photons = 20000;
  sppm.initial_radius = kRadius;
  PcltSettings pclt;
  pclt.light_paths = 20000;
  pclt.initial_radius = kRadius;
  const testing::Rendered bpt = testing::render_integrator(scene, accel, make_render_config("bpt", BptSettings{}, testing::test_seed(505)), 512);
  // The smooth pixels that see a Lambertian wall (lit through the coated ones). On the coated walls
  // themselves SPPM's radius blurs the coat's highlights of the light (measured: 4 of their pixels
  // fail), and PCLT's eye paths continue through them by BSDF sampling alone, whose rare hits of the
  // small light leave heavy tails (21 fail), while both image means agree with BPT's.
  std::vector<bool> keep = testing::smooth_pixels(scene, accel, 3.f * kRadius, false);
  const SceneView view = scene.view();
  for (int y = 0; y < scene.camera.height; ++y)
    for (int x = 0; x < scene.camera.width; ++x) {
      SurfaceHit hit;
      const size_t i = size_t(y) * size_t(scene.camera.width) + size_t(x);
      if (!accel.intersect(scene.camera.generate_ray(float(x) + 0.5f, float(y) + 0.5f), &hit) ||
          view.materials[hit.material].type != MaterialType::standard)
        keep[i] = false;
    }
  EXPECT_GT(size_t(std::count(keep.begin(), keep.end(), true)), keep.size() / 5);
  for (const RenderConfig& gather :
       {make_render_config("sppm", sppm, testing::test_seed(506)), make_render_config("pclt", pclt, testing::test_seed(507))}) {
    const testing::Rendered a = testing::render_integrator(scene, accel, gather, 128);
    const testing::ImageZTest z =
        testing::image_z_test(testing::compact_pixels(a.mean, keep), testing::compact_pixels(a.variance, keep),
                              testing::compact_pixels(bpt.mean, keep), testing::compact_pixels(bpt.variance, keep), 1e-3, kAlphaImage);
    std::printf("%s vs bpt on the Lambertian walls beside coated ones: %zu of %zu pixels failed (allowed %zu); means %.5f vs %.5f\n", gather.integrator.c_str(),
                z.failed, z.pixels, z.allowed, z.mean_a, z.mean_b);
    EXPECT_TRUE(z.passed()) << gather.integrator << ": " << z.failed << " of " << z.pixels << " pixels differ (at most " << z.allowed
                            << "); means " << z.mean_a << " vs " << z.mean_b << ", p " << z.mean_p;
  }
}

}  // namespace
}  // namespace pathspace
