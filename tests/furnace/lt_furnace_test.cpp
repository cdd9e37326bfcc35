// Furnace tests for light tracing: closed scenes with known radiance (support/test_scenes.h), with
// the box pixel filter, the wider tent / gaussian / mitchell pixel filters (the projection kernels of
// PCLT sec. 5.2, which must keep a constant image constant) and without the emitter splat; plus the emission weights of every
// light type integrating to the light's flux. Pixels of one LT pass share light paths (they are
// correlated), so the samples of each t-test are whole-pass image means (independent seeds), as in
// filter/hashed_filter_furnace_test.cpp. alpha = 0.01, Sidak-corrected over the tests in this file.
#include <gtest/gtest.h>

#include <cmath>

#include "pathspace/accel/accel.h"
#include "pathspace/camera/pixel_filter_table.h"
#include "pathspace/integrators/lt/lt_integrator.h"
#include "support/statistics.h"
#include "support/test_scenes.h"

namespace pathspace {
namespace {

constexpr int kTestsInFile = 13;
const double kAlpha = testing::sidak(0.01, kTestsInFile);

// Image means (red channel; the scenes are grey) of `passes` independent LT passes.
void expect_pass_means(const Scene& scene, const LtSettings& settings, int passes, uint64_t seed, double expected) {
  const Accel accel(scene);
  const SceneView view = scene.view();
  SplatFilm splats(scene.camera.width, scene.camera.height);
  double sum = 0, sum_sq = 0;
  for (int p = 0; p < passes; ++p) {
    Film film(scene.camera.width, scene.camera.height);
    PathCounters counters;
    lt_render_pass(view, accel, settings, seed, uint32_t(p), splats, film, counters);
    EXPECT_EQ(counters.dropped, 0u);
    const Image img = film.mean();
    double m = 0;
    for (const Rgb& px : img.pixels) {
      EXPECT_EQ(px.r, px.g);
      EXPECT_EQ(px.r, px.b);
      m += px.r;
    }
    m /= double(img.size());
    sum += m;
    sum_sq += m * m;
  }
  const testing::MeanTest t = testing::t_test_mean(sum, sum_sq, passes, expected);
  EXPECT_GT(t.p, kAlpha) << "mean " << t.mean << " +- " << t.std_error << " (expected " << expected << ", t = " << t.t << ")";
}

LtSettings many_paths() {
  LtSettings s;
  s.light_paths = 8192;
  return s;
}

TEST(LtFurnace, ClosedBoxEmissionOverOneMinusAlbedo) {
  const float le = 0.8f, albedo = 0.6f;
  expect_pass_means(testing::make_furnace_box(le, albedo), many_paths(), 40, 1, le / (1.0 - albedo));
}

TEST(LtFurnace, ClosedBoxTruncatedAtThreeSegments) {
  const float le = 1.f, albedo = 0.5f;
  LtSettings s = many_paths();
  s.max_segments = 3;
  s.roulette_start = -1;
  expect_pass_means(testing::make_furnace_box(le, albedo), s, 40, 2, le * (1.0 + albedo + albedo * albedo));
}

// Without the emitter splat (SmallVCM's LT) the directly seen emission Le is missing.
TEST(LtFurnace, ClosedBoxWithoutEmitterSplat) {
  const float le = 0.8f, albedo = 0.6f;
  LtSettings s = many_paths();
  s.skip_emitter = true;
  expect_pass_means(testing::make_furnace_box(le, albedo), s, 40, 3, le / (1.0 - albedo) - le);
}

Scene with_filter(Scene scene, const PixelFilter& filter) {
  scene.camera.filter = filter;
  return scene;
}

TEST(LtFurnace, ClosedBoxTentFilter) {
  const float le = 0.8f, albedo = 0.6f;
  const Scene scene = with_filter(testing::make_furnace_box(le, albedo), make_pixel_filter(PixelFilterKind::tent, 1.5f));
  expect_pass_means(scene, many_paths(), 40, 4, le / (1.0 - albedo));
}

TEST(LtFurnace, ClosedBoxGaussianFilter) {
  const float le = 0.8f, albedo = 0.6f;
  const Scene scene = with_filter(testing::make_furnace_box(le, albedo), make_pixel_filter(PixelFilterKind::gaussian, 2.f, 2.f / 3.f));
  expect_pass_means(scene, many_paths(), 40, 5, le / (1.0 - albedo));
}

TEST(LtFurnace, ClosedBoxMitchellFilter) {
  const float le = 0.8f, albedo = 0.6f;
  const Scene scene = with_filter(testing::make_furnace_box(le, albedo), make_pixel_filter(PixelFilterKind::mitchell, 2.f));
  expect_pass_means(scene, many_paths(), 40, 13, le / (1.0 - albedo));
}

TEST(LtFurnace, SphereWithPointLight) {
  const float radius = 1.5f, albedo = 0.5f, intensity = 3.f;
  const double expected = albedo / kPi * intensity / (radius * radius) / (1.0 - albedo);
  expect_pass_means(testing::make_sphere_with_point_light(radius, albedo, intensity), many_paths(), 40, 6, expected);
}

TEST(LtFurnace, EmissiveSphere) {
  const float le = 1.5f, albedo = 0.7f;
  expect_pass_means(testing::make_emissive_sphere(2.f, le, albedo), many_paths(), 40, 7, le / (1.0 - albedo));
}

// E[weight] over emission samples is the light's total flux: pi A Le (one-sided area lights),
// 4 pi I (point), E pi R^2 (directional, through the bounding-sphere disk), L 4 pi pi R^2
// (environment); weight must be le |cos| / (pdf_a pdf_w) sample by sample.
void expect_flux(const Scene& scene, double expected) {
  const SceneView view = scene.view();
  const Light& light = view.lights[0];
  double sum = 0, sum_sq = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const Sampler s(11, uint64_t(i), 0);
    EmissionSample e;
    double w = 0;
    if (sample_emission(view, light, 0.f, {s.at(0), s.at(1)}, {s.at(2), s.at(3)}, &e)) {
      w = e.weight.r;
      const float c = e.delta_position || e.infinite ? 1.f : fabsf(dot(e.n, e.d));
      EXPECT_NEAR(e.weight.r, e.le.r * c / (e.pdf_a * e.pdf_w), 1e-4f * e.weight.r);
      float pdf_a, pdf_w;
      emission_pdf(view, light, e.p, e.ng, e.d, 0.f, &pdf_a, &pdf_w);
      EXPECT_NEAR(pdf_a, e.pdf_a, 1e-5f * pdf_a);
      EXPECT_NEAR(pdf_w, e.pdf_w, 1e-5f * pdf_w + 1e-6f);
    }
    sum += w;
    sum_sq += w * w;
  }
  const testing::MeanTest t = testing::t_test_mean(sum, sum_sq, n, expected);
  // Area-light and directional weights are (nearly) constant: then float rounding, not noise, is
  // what separates the mean from the flux.
  if (std::fabs(t.mean - expected) <= 1e-6 * expected) return;
  EXPECT_GT(t.p, kAlpha) << "flux " << t.mean << " +- " << t.std_error << " (expected " << expected << ")";
}

Scene finalized(Scene s) {
  s.camera = make_perspective_camera(Vec3(0, -5, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), 45.f, 8, 8);
  s.finalize();
  return s;
}

TEST(LtEmission, TriangleFluxTwoSided) {
  Scene s;
  const uint32_t m = s.add_material(make_diffuse(Rgb(0.5f)));
  s.add_triangle(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 1, 0), m, Rgb(3.f), /*two_sided=*/true);
  expect_flux(finalized(std::move(s)), 2.0 * kPi * 1.0 * 3.0);
}

TEST(LtEmission, SphereFlux) {
  Scene s;
  const uint32_t m = s.add_material(make_diffuse(Rgb(0.5f)));
  s.add_sphere(Vec3(0, 0, 0), 0.5f, m, Rgb(2.f));
  expect_flux(finalized(std::move(s)), kPi * (kFourPi * 0.25) * 2.0);
}

TEST(LtEmission, PointFlux) {
  Scene s;
  s.add_sphere(Vec3(0, 0, 0), 1.f, s.add_material(make_diffuse(Rgb(0.5f))));
  s.add_point_light(Vec3(0.1f, 0, 0), Rgb(1.5f));
  expect_flux(finalized(std::move(s)), kFourPi * 1.5);
}

TEST(LtEmission, DirectionalAndEnvironmentFlux) {
  Scene s;
  s.add_sphere(Vec3(0, 0, 0), 1.f, s.add_material(make_diffuse(Rgb(0.5f))));
  s.add_directional_light(normalize(Vec3(1, 2, -1)), Rgb(4.f));
  const Scene sun = finalized(std::move(s));
  const double r = sun.bounds().radius;
  expect_flux(sun, 4.0 * kPi * r * r);
  Scene e;
  e.add_sphere(Vec3(0, 0, 0), 1.f, e.add_material(make_diffuse(Rgb(0.5f))));
  e.add_environment_light(Rgb(0.5f));
  const Scene env = finalized(std::move(e));
  expect_flux(env, 0.5 * kFourPi * kPi * r * r);
}

}  // namespace
}  // namespace pathspace
