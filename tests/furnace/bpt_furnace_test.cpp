// Furnace tests for bidirectional path tracing: closed scenes with known radiance
// (support/test_scenes.h) under both MIS heuristics, a hard path length limit, a point light (delta
// position: no s = 0), an emissive sphere (cone-sampled NEE against uniform-area emission) and a
// constant environment (infinite light: t = 1 from the bounding-sphere disk). Pixels of one pass
// share splats, so each t-test runs over whole-pass image means. alpha = 0.01, Sidak over the file.
// Also: the per-strategy images (s, t) sum to the image.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/bpt/bpt_integrator.h"
#include "support/statistics.h"
#include "support/test_scenes.h"

namespace pathspace {
namespace {

constexpr int kTestsInFile = 7;
const double kAlpha = testing::sidak(0.01, kTestsInFile);

// Image means (red channel; the scenes are grey) of `passes` independent BPT passes.
void expect_pass_means(const Scene& scene, const BptSettings& settings, int passes, uint64_t seed, double expected) {
  const Accel accel(scene);
  const SceneView view = scene.view();
  BptBuffers buffers(scene.camera.width, scene.camera.height, settings, bpt_max_segments(settings, view));
  double sum = 0, sum_sq = 0;
  for (int p = 0; p < passes; ++p) {
    Film film(scene.camera.width, scene.camera.height);
    PathCounters counters;
    bpt_render_pass(view, accel, settings, seed, uint32_t(p), buffers, film, counters);
    EXPECT_EQ(counters.dropped, 0u);
    const Image img = film.mean();
    double m = 0;
    for (const Rgb& px : img.pixels) m += px.r;
    m /= double(img.size());
    sum += m;
    sum_sq += m * m;
  }
  const testing::MeanTest t = testing::t_test_mean(sum, sum_sq, passes, expected);
  std::printf("bpt furnace: mean %.5f +- %.5f expected %.5f\n", t.mean, t.std_error, expected);
  EXPECT_GT(t.p, kAlpha) << "mean " << t.mean << " +- " << t.std_error << " (expected " << expected << ", t = " << t.t << ")";
}

TEST(BptFurnace, ClosedBoxPowerHeuristic) {
  const float le = 0.8f, albedo = 0.6f;
  expect_pass_means(testing::make_furnace_box(le, albedo), BptSettings{}, 100, 1, le / (1.0 - albedo));
}

TEST(BptFurnace, ClosedBoxBalanceHeuristic) {
  const float le = 0.8f, albedo = 0.6f;
  BptSettings s;
  s.mis = MisHeuristic::balance;
  expect_pass_means(testing::make_furnace_box(le, albedo), s, 100, 2, le / (1.0 - albedo));
}

// Every path length up to the limit must be complete, and nothing beyond it may leak in.
TEST(BptFurnace, ClosedBoxTruncatedAtThreeSegments) {
  const float le = 1.f, albedo = 0.5f;
  BptSettings s;
  s.max_segments = 3;
  s.roulette_start = -1;
  expect_pass_means(testing::make_furnace_box(le, albedo), s, 100, 3, le * (1.0 + albedo + albedo * albedo));
}

TEST(BptFurnace, SphereWithPointLight) {
  const float radius = 1.5f, albedo = 0.5f, intensity = 3.f;
  const double expected = albedo / kPi * intensity / (radius * radius) / (1.0 - albedo);
  expect_pass_means(testing::make_sphere_with_point_light(radius, albedo, intensity), BptSettings{}, 100, 4, expected);
}

TEST(BptFurnace, EmissiveSphere) {
  const float le = 1.5f, albedo = 0.7f;
  expect_pass_means(testing::make_emissive_sphere(2.f, le, albedo), BptSettings{}, 100, 5, le / (1.0 - albedo));
}

TEST(BptFurnace, PlaneUnderSky) {
  const float albedo = 0.5f, sky = 2.f;
  expect_pass_means(testing::make_plane_under_sky(albedo, sky), BptSettings{}, 100, 6, albedo * sky);
}

// The strategy images partition the image: their sum equals the film mean up to fixed-point rounding.
TEST(BptStrategyImages, SumToTheImage) {
  Scene scene = testing::make_furnace_box(0.8f, 0.6f);
  const Accel accel(scene);
  BptSettings settings;
  settings.max_segments = 4;
  settings.strategy_images = 4;
  BptIntegrator bpt(scene, accel, settings, 0);
  Film film(scene.camera.width, scene.camera.height);
  PathCounters counters;
  for (uint32_t pass = 0; pass < 4; ++pass) bpt.render_pass(pass, film, counters);
  const std::vector<NamedImage> aovs = bpt.aovs();
  ASSERT_EQ(aovs.size(), size_t(bpt_strategy_count(4)));
  EXPECT_EQ(aovs.front().name, "bpt-s0-t2");
  const Image mean = film.mean();
  for (const NamedImage& a : aovs) {  // a furnace box exercises every strategy
    double total = 0;
    for (const Rgb& px : a.image.pixels) total += px.r;
    EXPECT_GT(total, 0.0) << a.name;
  }
  for (size_t i = 0; i < mean.size(); ++i) {
    double sum = 0;
    for (const NamedImage& a : aovs) sum += a.image.pixels[i].r;
    EXPECT_NEAR(sum, mean.pixels[i].r, 1e-4 * mean.pixels[i].r) << "pixel " << i;
  }
}

}  // namespace
}  // namespace pathspace
