// Furnace tests for path tracing: closed scenes with known radiance (support/test_scenes.h), for
// MIS, NEE only and BSDF sampling only. Each is a one-sample t-test of the per-path estimator
// against the closed form, alpha = 0.01 Sidak-corrected over the tests in this file.
#include <gtest/gtest.h>

#include <tuple>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/pt/pt_kernel.h"
#include "pathspace/parallel/parallel_for.h"
#include "support/statistics.h"
#include "support/test_names.h"
#include "support/test_scenes.h"

namespace pathspace {
namespace {

constexpr int kTestsInFile = 14;
const double kAlpha = testing::sidak(0.01, kTestsInFile);

struct Moments {
  double sum = 0, sum_sq = 0, n = 0;
};

// Traces n camera paths (pixel = path index modulo the pixel count) and returns the moments of
// the red channel (the scenes are grey: all channels must be equal).
Moments trace_paths(const Scene& scene, const PtSettings& settings, uint64_t n, uint64_t seed) {
  const Accel accel(scene);
  const SceneView view = scene.view();
  const size_t chunks = 64;
  std::vector<Moments> partial(chunks);
  parallel_for(chunks, 1, [&](size_t begin, size_t end) {
    for (size_t c = begin; c < end; ++c) {
      PathCounters counters;
      for (uint64_t i = c; i < n; i += chunks) {
        const Sampler sampler(seed, i, 0);
        const int w = view.camera.width, h = view.camera.height;
        const uint64_t pixel = i % uint64_t(w * h);
        const Ray ray = view.camera.generate_ray(float(pixel % w) + sampler.at(dims::kPixelX),
                                                 float(pixel / w) + sampler.at(dims::kPixelY));
        const Rgb L = pt_trace_path(view, accel, sampler, ray, settings, &counters);
        EXPECT_EQ(L.r, L.g);
        EXPECT_EQ(L.r, L.b);
        partial[c].sum += L.r;
        partial[c].sum_sq += double(L.r) * L.r;
        partial[c].n += 1;
      }
    }
  });
  Moments m;
  for (const Moments& p : partial) {
    m.sum += p.sum;
    m.sum_sq += p.sum_sq;
    m.n += p.n;
  }
  return m;
}

PtSettings mode_settings(const std::string& mode) {
  PtSettings s;
  s.nee = mode != "bsdf";
  s.bsdf_sampling = mode != "nee";
  return s;
}

void expect_mean(const Moments& m, double expected) {
  const testing::MeanTest t = testing::t_test_mean(m.sum, m.sum_sq, m.n, expected);
  EXPECT_GT(t.p, kAlpha) << "mean " << t.mean << " +- " << t.std_error << " (expected " << expected << ", t = " << t.t
                         << ", n = " << m.n << ")";
}

class ClosedBox : public ::testing::TestWithParam<std::string> {};

TEST_P(ClosedBox, EmissionOverOneMinusAlbedo) {
  const float le = 0.8f, albedo = 0.6f;
  const Scene scene = testing::make_furnace_box(le, albedo);
  expect_mean(trace_paths(scene, mode_settings(GetParam()), 300000, 1), le / (1.0 - albedo));
}

// With a path limit of D segments and no Russian roulette the answer is the truncated series.
TEST_P(ClosedBox, TruncatedAtThreeSegments) {
  const float le = 1.f, albedo = 0.5f;
  const Scene scene = testing::make_furnace_box(le, albedo);
  PtSettings s = mode_settings(GetParam());
  s.max_segments = 3;
  s.roulette_start = -1;
  expect_mean(trace_paths(scene, s, 200000, 2), le * (1.0 + albedo + albedo * albedo));
}

class EmissiveSphere : public ::testing::TestWithParam<std::string> {};

TEST_P(EmissiveSphere, EmissionOverOneMinusAlbedo) {
  const float le = 1.5f, albedo = 0.7f;
  const Scene scene = testing::make_emissive_sphere(2.f, le, albedo);
  expect_mean(trace_paths(scene, mode_settings(GetParam()), 300000, 3), le / (1.0 - albedo));
}

class PlaneUnderSky : public ::testing::TestWithParam<std::string> {};

TEST_P(PlaneUnderSky, AlbedoTimesSky) {
  const float albedo = 0.5f, sky = 2.f;
  const Scene scene = testing::make_plane_under_sky(albedo, sky);
  expect_mean(trace_paths(scene, mode_settings(GetParam()), 200000, 5), albedo * sky);
}

INSTANTIATE_TEST_SUITE_P(Pt, PlaneUnderSky, ::testing::Values("mis", "nee", "bsdf"), testing::StringParamName());
INSTANTIATE_TEST_SUITE_P(Pt, ClosedBox, ::testing::Values("mis", "nee", "bsdf"), testing::StringParamName());
INSTANTIATE_TEST_SUITE_P(Pt, EmissiveSphere, ::testing::Values("mis", "nee", "bsdf"), testing::StringParamName());

// A point light cannot be hit by BSDF sampling, so only MIS and NEE-only apply.
class SphereWithPointLight : public ::testing::TestWithParam<std::string> {};

TEST_P(SphereWithPointLight, KnownRadiance) {
  const float radius = 1.5f, albedo = 0.5f, intensity = 3.f;
  const Scene scene = testing::make_sphere_with_point_light(radius, albedo, intensity);
  const double expected = albedo / kPi * intensity / (radius * radius) / (1.0 - albedo);
  expect_mean(trace_paths(scene, mode_settings(GetParam()), 200000, 4), expected);
}

INSTANTIATE_TEST_SUITE_P(Pt, SphereWithPointLight, ::testing::Values("mis", "nee"), testing::StringParamName());

}  // namespace
}  // namespace pathspace
