// Camera-side branches (VertexSelection::camera_splits; pt_kernel.h, pt_continue_path): a path that
// follows both the reflection and the refraction at smooth glass, or both the scattering and the
// passing way through fog (media/free_flight.h), before its first selected vertex is the same
// estimator as one that picks at random.
// The path values (prefix + records, as resolved without a filter) are compared per pixel.
#include <gtest/gtest.h>

#include <cstring>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/common/camera_sample.h"
#include "pathspace/integrators/pt/pt_kernel.h"
#include "pathspace/scene/builtin_scenes.h"
#include "support/integrator_comparison.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

constexpr int kSize = 32;
constexpr uint32_t kPasses = 512;
// The file's two image comparisons, at alpha = 0.01 together.
const double kAlphaImage = testing::sidak(0.01, 2);

struct PathStatistics {
  Image mean, variance;  // the variance of the mean
  Image records;         // records per path, averaged (channel 0)
};

PathStatistics trace(const Scene& scene, const Accel& accel, int camera_splits, uint64_t seed, uint32_t passes = kPasses) {
  const SceneView view = scene.view();
  PtSettings settings;
  settings.selection.camera_splits = camera_splits;
  PathStatistics out{Image(kSize, kSize), Image(kSize, kSize), Image(kSize, kSize)};
  PathSample sample;
  for (uint32_t pixel = 0; pixel < uint32_t(kSize * kSize); ++pixel) {
    Rgb sum, sum_sq;
    double records = 0.0;
    for (uint32_t pass = 0; pass < passes; ++pass) {
      const Sampler sampler(seed, pixel, pass);
      const Ray ray = sample_camera_ray(view.camera, sampler, pixel, 0.f);
      PathCounters counters;
      pt_trace_path(view, accel, sampler, ray, settings, &counters, &sample);
      const Rgb v = sample.value();
      sum += v;
      sum_sq += v * v;
      records += sample.count;
    }
    const Rgb mean = sum / float(passes);
    out.mean.pixels[pixel] = mean;
    out.variance.pixels[pixel] = (sum_sq / float(passes) - mean * mean) / float(passes - 1);
    out.records.pixels[pixel] = Rgb(float(records / passes), 0.f, 0.f);
  }
  return out;
}

TEST(CameraBranches, SameEstimateAndBranchesOnGlass) {
  const Scene scene = make_builtin_scene("cornell-box", kSize, kSize);
  const Accel accel(scene);
  const PathStatistics split = trace(scene, accel, 2, testing::test_seed(11));
  const PathStatistics single = trace(scene, accel, 0, testing::test_seed(12));
  const testing::ImageZTest z = testing::image_z_test(split.mean, split.variance, single.mean, single.variance, 1e-3, kAlphaImage);
  EXPECT_TRUE(z.passed()) << z.failed << " pixels failed (allowed " << z.allowed << "), image means " << z.mean_a << " vs "
                          << z.mean_b << " (p " << z.mean_p << ")";

  // Pixels that see the glass sphere hold more than one branch's records. Their values are hardly
  // less noisy without a filter (measured: 25% less variance; the branches share their sampler
  // dimensions): the gain is the filter's, which averages each branch's vertex instead of a pick
  // between reflection and refraction (docs/results/one-path-per-pixel.md).
  int branched = 0;
  for (size_t i = 0; i < split.mean.size(); ++i) branched += split.records.pixels[i][0] > single.records.pixels[i][0] + 1.f ? 1 : 0;
  EXPECT_GT(branched, 20) << "the glass sphere covers about 5% of the image";
}

// In the fog box every camera ray starts in the fog: each path splits there into a vertex in the fog
// and one on the surface behind it (with the transmittance as its weight).
TEST(CameraBranches, SameEstimateAndBranchesInFog) {
  const Scene scene = make_builtin_scene("cornell-fog", kSize, kSize);
  const Accel accel(scene);
  const PathStatistics split = trace(scene, accel, 2, testing::test_seed(13), kPasses / 2);
  const PathStatistics single = trace(scene, accel, 0, testing::test_seed(14), kPasses / 2);
  const testing::ImageZTest z = testing::image_z_test(split.mean, split.variance, single.mean, single.variance, 1e-3, kAlphaImage);
  EXPECT_TRUE(z.passed()) << z.failed << " pixels failed (allowed " << z.allowed << "), image means " << z.mean_a << " vs "
                          << z.mean_b << " (p " << z.mean_p << ")";
  int branched = 0;
  for (size_t i = 0; i < split.mean.size(); ++i) branched += split.records.pixels[i][0] > single.records.pixels[i][0] + 0.5f ? 1 : 0;
  EXPECT_GT(branched, int(split.mean.size()) * 9 / 10) << "every pixel looks through fog";
}

TEST(CameraBranches, OnlyWithAFilterAndDeterministic) {
  const Scene scene = make_builtin_scene("cornell-box", kSize, kSize);
  const Accel accel(scene);
  const SceneView view = scene.view();
  PtSettings plain;  // without a filter no path is split, so no branch is traced
  plain.selection.mode = VertexSelectionMode::none;
  PtSettings unbranched = plain;
  unbranched.selection.camera_splits = 0;
  // Each pixel's path traced with settings x and y from the same sampler, handed to check.
  const auto trace_pairs = [&](const PtSettings& x, const PtSettings& y, const auto& check) {
    PathSample a, b;
    for (uint32_t pixel = 0; pixel < uint32_t(kSize * kSize); ++pixel) {
      const Sampler sampler(5, pixel, 0);
      const Ray ray = sample_camera_ray(view.camera, sampler, pixel, 0.f);
      PathCounters ca, cb;
      pt_trace_path(view, accel, sampler, ray, x, &ca, &a);
      pt_trace_path(view, accel, sampler, ray, y, &cb, &b);
      check(pixel, a, b, ca.rays == cb.rays);
    }
  };
  trace_pairs(plain, unbranched, [](uint32_t pixel, const PathSample& a, const PathSample& b, bool same_rays) {
    ASSERT_TRUE(same_rays) << "pixel " << pixel;
    const Rgb va = a.value(), vb = b.value();
    ASSERT_EQ(std::memcmp(&va, &vb, sizeof va), 0) << "pixel " << pixel;
  });
  // With branches, the same path twice gives the same records in the same order.
  const PtSettings branched;
  trace_pairs(branched, branched, [](uint32_t pixel, const PathSample& a, const PathSample& b, bool same_rays) {
    ASSERT_TRUE(same_rays) << "pixel " << pixel;
    ASSERT_EQ(a.count, b.count) << "pixel " << pixel;
    for (int r = 0; r < a.count; ++r)
      ASSERT_EQ(std::memcmp(&a.records[r].contribution, &b.records[r].contribution, sizeof(Rgb)), 0) << "pixel " << pixel;
  });
}

}  // namespace
}  // namespace pathspace
