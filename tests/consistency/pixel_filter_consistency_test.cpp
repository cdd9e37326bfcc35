// Consistency of the pixel filters across the integrators (camera/pixel_filter.h): camera paths
// sample their raster offset from the filter, light paths splat through it, so every integrator must
// estimate the same filtered image. Scene: the diffuse Cornell box with the ceiling light (mask 1,
// "e_c"), 24x24, where a wide filter blurs the light's edge and the box corners over several pixels.
// (Not the glossy floor: PT's heavy-tailed E-D-G-L caustics there fail 5 of 576 pixels for some
// seeds with the box filter too, measured over seeds 0-5.)
//  - PT (filter importance sampling only) and BPT (importance sampling for t >= 2, splats for t = 1)
//    agree with a gaussian of radius 1.5;
//  - LT (splats only) agrees with BPT with a tent of radius 2 and with Mitchell's positive part;
//  - power: the box-filtered image of the same scene is rejected against the gaussian one.
// Per-pixel z-test with binomial failure allowance and image-mean test (support/statistics.h),
// alpha_pixel 1e-3, alpha_image 0.01 Sidak over the 3 comparisons of this file.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "pathspace/accel/accel.h"
#include "pathspace/camera/pixel_filter_table.h"
#include "pathspace/scene/builtin_scenes.h"
#include "support/integrator_comparison.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

using testing::Rendered;

constexpr int kComparisons = 3;
const double kAlphaImage = testing::sidak(0.01, kComparisons);
constexpr int kSize = 24;

Scene make_filtered_cornell(const PixelFilter& filter) {
  Scene scene = make_cornell_box(kLightCeiling, kSize, kSize);
  scene.camera.filter = filter;
  return scene;
}

Rendered bpt_reference(const Scene& scene, const Accel& accel, uint64_t seed) {
  return testing::render_integrator(scene, accel, testing::default_config("bpt", testing::test_seed(seed)), 512);
}

TEST(PixelFilterAgree, PtAndBptWithGaussian) {
  const Scene scene = make_filtered_cornell(make_pixel_filter(PixelFilterKind::gaussian, 1.5f, 0.5f));
  const Accel accel(scene);
  const Rendered pt = testing::render_integrator(scene, accel, testing::default_config("pt", testing::test_seed(501)), 2048);
  const Rendered bpt = bpt_reference(scene, accel, 502);
  testing::expect_same_image(pt, bpt, "pixel-filter-pt-vs-bpt", kAlphaImage, "pt", "bpt");

  // The comparison can see the filter: the box-filtered render of the same scene is rejected.
  const Scene box = make_filtered_cornell(PixelFilter{});
  const Rendered sharp = testing::render_integrator(box, accel, testing::default_config("bpt", testing::test_seed(503)), 512);
  const testing::ImageZTest z = testing::image_z_test(sharp.mean, sharp.variance, bpt.mean, bpt.variance, 1e-3, kAlphaImage);
  std::printf("box vs gaussian: %zu of %zu pixels differ (allowed %zu)\n", z.failed, z.pixels, z.allowed);
  EXPECT_FALSE(z.passed()) << "the box-filtered image should differ from the gaussian one";
}

void expect_lt_agrees(const PixelFilter& filter, const std::string& what, uint64_t seed) {
  const Scene scene = make_filtered_cornell(filter);
  const Accel accel(scene);
  LtSettings lt;
  lt.light_paths = 8192;
  const Rendered a = testing::render_integrator(scene, accel, make_render_config("lt", lt, testing::test_seed(seed)), 256);
  const Rendered b = bpt_reference(scene, accel, seed + 1);
  testing::expect_same_image(a, b, what, kAlphaImage, "lt", "bpt");
}

TEST(PixelFilterAgree, LtAndBptWithTent) { expect_lt_agrees(make_pixel_filter(PixelFilterKind::tent, 2.f), "pixel-filter-lt-vs-bpt-tent", 511); }

TEST(PixelFilterAgree, LtAndBptWithMitchell) {
  expect_lt_agrees(make_pixel_filter(PixelFilterKind::mitchell, 2.f), "pixel-filter-lt-vs-bpt-mitchell", 521);
}

}  // namespace
}  // namespace pathspace
