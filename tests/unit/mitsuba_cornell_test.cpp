// Acceptance test of the Mitsuba loader on Bitterli's Cornell box: scene_v3.xml (Mitsuba 3) and
// scene-v4.pbrt (pbrt-v4) load to the same scene and render the same image (per-pixel z-test of two
// independent path-traced renders), and the Mitsuba form matches Tungsten's reference on the
// diffuse walls as PbrtCornellBox does for the pbrt form. Skipped without the shared scenes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "pathspace/io/image_io.h"
#include "pathspace/io/scene_loader.h"
#include "support/integrator_comparison.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

#ifndef PATHSPACE_SHARED_SCENES_DIR
#define PATHSPACE_SHARED_SCENES_DIR ""
#endif

std::string cornell_dir() { return std::string(PATHSPACE_SHARED_SCENES_DIR) + "/bitterli/cornell-box"; }

#define REQUIRE_CORNELL_FORMS()                                                                                  \
  if (!std::filesystem::exists(cornell_dir() + "/scene_v3.xml") || !std::filesystem::exists(cornell_dir() + "/scene-v4.pbrt")) \
  GTEST_SKIP() << "no " << cornell_dir()

Scene load_at(const std::string& file, int res, std::vector<std::string>* warnings = nullptr) {
  SceneLoadOptions o;
  o.width = o.height = res;
  return load_scene(cornell_dir() + "/" + file, o, warnings);
}

TEST(MitsubaCornellBox, LoadsLikeThePbrtForm) {
  REQUIRE_CORNELL_FORMS();
  std::vector<std::string> warnings;
  SceneFileSettings settings;
  const Scene m = load_scene(cornell_dir() + "/scene_v3.xml", {}, &warnings, &settings);
  const Scene p = load_scene(cornell_dir() + "/scene-v4.pbrt", {}, nullptr);
  EXPECT_EQ(m.triangles.size(), p.triangles.size());  // 5 walls x 2 + 2 boxes x 12 + light x 2
  ASSERT_EQ(m.lights.size(), 2u);
  for (const Light& l : m.lights) {
    EXPECT_EQ(l.value, Rgb(17, 12, 4));
    const Triangle& t = m.triangles[l.shape];
    EXPECT_NEAR(triangle_normal(m.positions[t.v[0]], m.positions[t.v[1]], m.positions[t.v[2]]).y, -1.f, 1e-5f);  // emits down
  }
  const Bounds3 bm = m.geometry_bounds(), bp = p.geometry_bounds();
  EXPECT_LT(distance(bm.lo, bp.lo) + distance(bm.hi, bp.hi), 1e-5f);
  EXPECT_NEAR(distance(m.camera.position, p.camera.position), 0.f, 1e-6f);
  EXPECT_NEAR(distance(m.camera.forward, p.camera.forward), 0.f, 1e-6f);
  EXPECT_NEAR(distance(m.camera.right, p.camera.right), 0.f, 1e-6f);
  EXPECT_NEAR(distance(m.camera.up, p.camera.up), 0.f, 1e-6f);
  EXPECT_FLOAT_EQ(m.camera.tan_x, p.camera.tan_x);
  EXPECT_EQ(m.camera.width, 1024);
  EXPECT_EQ(settings.spp, 64);
  EXPECT_EQ(m.max_path_segments, 65);  // Mitsuba's max_depth 65 counts segments; pbrt's maxdepth 65 bounces -> 66
  ASSERT_EQ(warnings.size(), 1u) << ::testing::PrintToString(warnings);  // only the tent filter is unsupported
  EXPECT_NE(warnings[0].find("scene_v3.xml:23:4: warning: reconstruction filter 'tent'"), std::string::npos) << warnings[0];
}

TEST(MitsubaCornellBox, SameImageAsThePbrtForm) {
  REQUIRE_CORNELL_FORMS();
  constexpr int kRes = 64;
  constexpr uint32_t kPasses = 256;
  const Scene m = load_at("scene_v3.xml", kRes), p = load_at("scene-v4.pbrt", kRes);
  IntegratorSettings a, b;  // independent seeds: the z-test assumes independent estimates
  a.seed = testing::test_seed_base() + 11;
  b.seed = testing::test_seed_base() + 12;
  const testing::Rendered rm = testing::render_integrator(m, "pt", a, kPasses);
  const testing::Rendered rp = testing::render_integrator(p, "pt", b, kPasses);
  const testing::ImageZTest z = testing::image_z_test(rm.mean, rm.variance, rp.mean, rp.variance, 1e-3, 1e-3);
  std::printf("xml vs pbrt, %dx%d, %u spp each: %zu of %zu pixels fail at alpha 1e-3 (%zu allowed); image means %.5f vs %.5f, z %.2f\n",
              kRes, kRes, kPasses, z.failed, z.pixels, z.allowed, z.mean_a, z.mean_b, z.mean_z);
  testing::expect_same_image(rm, rp, "mitsuba-vs-pbrt-cornell", 1e-3, "xml", "pbrt");
}

struct Region {
  const char* name;
  float x0, y0, x1, y1;  // fractions of the image
};

// The regions and allowance of PbrtCornellBox.RenderMatchesTungstenOnDiffuseWalls.
TEST(MitsubaCornellBox, RenderMatchesTungstenOnDiffuseWalls) {
  REQUIRE_CORNELL_FORMS();
  if (!std::filesystem::exists(cornell_dir() + "/TungstenRender.exr")) GTEST_SKIP() << "no Tungsten reference";
  constexpr int kRes = 128;
  const Scene scene = load_at("scene_v3.xml", kRes);
  IntegratorSettings settings;
  settings.seed = testing::test_seed_base() + 7;
  const testing::Rendered r = testing::render_integrator(scene, "pt", settings, 32);
  for (const Rgb& c : r.mean.pixels) ASSERT_TRUE(all_finite(c));

  const Image ref = read_image(cornell_dir() + "/TungstenRender.exr");
  ASSERT_EQ(ref.width % kRes, 0);
  const int k = ref.width / kRes;  // box-downsample the reference to our pixel grid
  const Region regions[] = {{"back wall", 0.55f, 0.25f, 0.75f, 0.45f},
                            {"back wall upper left", 0.2f, 0.15f, 0.4f, 0.3f},
                            {"red wall", 0.03f, 0.3f, 0.12f, 0.6f},
                            {"green wall", 0.89f, 0.3f, 0.97f, 0.6f}};
  const double alpha = testing::sidak(1e-3, 12);  // 4 regions x 3 channels
  double lo = 0.0, hi = 10.0;                     // two-sided critical z
  for (int i = 0; i < 100; ++i) ((testing::normal_two_sided_p(0.5 * (lo + hi)) > alpha) ? lo : hi) = 0.5 * (lo + hi);
  const double z_crit = lo;
  for (const Region& g : regions) {
    const int x0 = int(g.x0 * kRes), x1 = int(g.x1 * kRes), y0 = int(g.y0 * kRes), y1 = int(g.y1 * kRes);
    double sum[3] = {0, 0, 0}, var_sum[3] = {0, 0, 0}, ref_sum[3] = {0, 0, 0};
    const double n = double((x1 - x0) * (y1 - y0));
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x)
        for (int c = 0; c < 3; ++c) {
          sum[c] += r.mean.at(x, y)[c];
          var_sum[c] += r.variance.at(x, y)[c];
          for (int yy = y * k; yy < (y + 1) * k; ++yy)
            for (int xx = x * k; xx < (x + 1) * k; ++xx) ref_sum[c] += ref.at(xx, yy)[c] / double(k * k);
        }
    for (int c = 0; c < 3; ++c) {
      const double mean = sum[c] / n, rm = ref_sum[c] / n;
      // Our noise plus a 2% allowance for what differs by design (Tungsten's tent filter,
      // spectral-vs-RGB details, the reference's own noise), as for the pbrt form.
      const double sigma = std::sqrt(var_sum[c] / (n * n) + (0.02 * rm) * (0.02 * rm));
      const double z = (mean - rm) / sigma;
      EXPECT_LT(std::fabs(z), z_crit) << g.name << " channel " << c << ": ours " << mean << ", Tungsten " << rm;
      std::printf("%-22s ch%d ours %.4f tungsten %.4f rel %+.3f%% z %+.2f\n", g.name, c, mean, rm, 100.0 * (mean - rm) / rm, z);
    }
  }
}

}  // namespace
}  // namespace pathspace
