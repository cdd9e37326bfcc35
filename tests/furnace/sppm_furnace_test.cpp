// Furnace tests for SPPM (Hachisuka & Jensen 2009 with the Knaus-Zwicker radius update): closed
// scenes with known radiance (support/test_scenes.h). The pixels of one iteration share its photons
// and are correlated, so the sample is the image mean of each iteration (iterations are independent):
// a one-sample t-test against the closed form, alpha = 0.01 Sidak-corrected over this file.
//  - Inside of a diffuse sphere, point light at the centre: the irradiance is constant and the part
//    of a sphere within Euclidean distance r of a point on it has area exactly pi r^2 (Archimedes),
//    so the density estimate is unbiased for every radius.
//  - Closed emissive box: near an edge the ball also covers the adjacent wall, whose photons pass
//    the front-side test about half the time, so VPs within r of an edge overestimate the reflected
//    light by up to 25%. Averaged over a wall that is ~ (4 edges * 2 * r / 4) * 1/6 of the
//    reflected part (60% of L here); with r = 0.01 (box side 2) that is ~0.2% of L, below the test's
//    resolution (standard error ~0.4%; the camera sees edges in about the same proportion).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/sppm/sppm_integrator.h"
#include "pathspace/parallel/parallel_for.h"
#include "support/statistics.h"
#include "support/test_scenes.h"

namespace pathspace {
namespace {

constexpr int kTestsInFile = 3;
const double kAlpha = testing::sidak(0.01, kTestsInFile);

// Renders `iterations` SPPM iterations, each into its own film, and t-tests their image means.
void expect_iteration_means(const Scene& scene, const SppmSettings& sppm, int iterations, uint64_t seed, double expected) {
  const Accel accel(scene);
  const char* env = std::getenv("PATHSPACE_TEST_SEED");  // rerun with other seeds to check robustness
  SppmIntegrator integrator(scene, accel, sppm, seed + (env ? std::strtoull(env, nullptr, 10) * 1000 : 0));
  double sum = 0, sum_sq = 0;
  for (int i = 0; i < iterations; ++i) {
    Film film(scene.camera.width, scene.camera.height);
    PathCounters counters;
    integrator.render_pass(uint32_t(i), film, counters);
    ASSERT_EQ(counters.dropped, 0u);
    const Image mean = film.mean();
    double m = 0;
    for (const Rgb& p : mean.pixels) {
      ASSERT_EQ(p.r, p.g);
      ASSERT_EQ(p.r, p.b);
      m += p.r;
    }
    m /= double(mean.pixels.size());
    sum += m;
    sum_sq += m * m;
  }
  const testing::MeanTest t = testing::t_test_mean(sum, sum_sq, iterations, expected);
  EXPECT_GT(t.p, kAlpha) << "mean " << t.mean << " +- " << t.std_error << " (expected " << expected << ", t = " << t.t
                         << ", iterations " << iterations << ")";
  EXPECT_LT(t.std_error, 0.01 * expected);  // the test has the power to see a 3% bias
  Statistics details;
  integrator.statistics(details);
  std::printf("mean %.5f +- %.5f expected %.5f t %.2f\n%s", t.mean, t.std_error, expected, t.t, format_statistics(details).c_str());
}

TEST(SppmFurnace, SphereWithPointLight) {
  const float radius = 1.5f, albedo = 0.5f, intensity = 3.f;
  const Scene scene = testing::make_sphere_with_point_light(radius, albedo, intensity);
  SppmSettings s;
  s.photons = 4000;
  s.initial_radius = 0.3f;  // any radius is unbiased here; a large one keeps the noise low
  const double expected = albedo / kPi * intensity / (radius * radius) / (1.0 - albedo);
  expect_iteration_means(scene, s, 200, 1, expected);
}

// alpha = 1 keeps the radius constant: the estimator must not depend on the radius schedule.
TEST(SppmFurnace, SphereWithPointLightConstantRadius) {
  const float radius = 2.f, albedo = 0.7f, intensity = 5.f;
  const Scene scene = testing::make_sphere_with_point_light(radius, albedo, intensity);
  SppmSettings s;
  s.photons = 4000;
  s.initial_radius = 0.15f;
  s.alpha = 1.f;
  const double expected = albedo / kPi * intensity / (radius * radius) / (1.0 - albedo);
  expect_iteration_means(scene, s, 200, 2, expected);
}

TEST(SppmFurnace, ClosedBoxEmissionOverOneMinusAlbedo) {
  const float le = 0.8f, albedo = 0.6f;
  const Scene scene = testing::make_furnace_box(le, albedo);
  SppmSettings s;
  s.photons = 40000;
  s.initial_radius = 0.01f;
  s.alpha = 1.f;
  expect_iteration_means(scene, s, 200, 3, le / (1.0 - albedo));
}

}  // namespace
}  // namespace pathspace
