// Acceptance test of the Mitsuba loader on Bitterli's Cornell box: scene_v3.xml (Mitsuba 3) and
// scene-v4.pbrt (pbrt-v4) load to the same scene and render the same image (per-pixel z-test of two
// independent path-traced renders), and the Mitsuba form matches Tungsten's reference on the
// diffuse walls as PbrtCornellBox does for the pbrt form. Fails without the shared scenes
// (support/shared_data.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "pathspace/io/image_io.h"
#include "pathspace/io/scene_loader.h"
#include "support/integrator_comparison.h"
#include "support/reference_regions.h"
#include "support/shared_data.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

#ifndef PATHSPACE_SHARED_SCENES_DIR
#define PATHSPACE_SHARED_SCENES_DIR ""
#endif

std::string cornell_dir() { return std::string(PATHSPACE_SHARED_SCENES_DIR) + "/bitterli/cornell-box"; }

#define REQUIRE_CORNELL_FORMS()                                \
  PATHSPACE_REQUIRE_SHARED_DATA(cornell_dir() + "/scene_v3.xml"); \
  PATHSPACE_REQUIRE_SHARED_DATA(cornell_dir() + "/scene-v4.pbrt")

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
  EXPECT_TRUE(warnings.empty()) << ::testing::PrintToString(warnings);
  EXPECT_EQ(m.camera.filter.kind, PixelFilterKind::tent);  // Tungsten's tent of radius 1, as the pbrt form's triangle
  EXPECT_EQ(m.camera.filter.radius, p.camera.filter.radius);
  EXPECT_EQ(m.camera.filter.kind, p.camera.filter.kind);
}

TEST(MitsubaCornellBox, SameImageAsThePbrtForm) {
  REQUIRE_CORNELL_FORMS();
  constexpr int kRes = 64;
  constexpr uint32_t kPasses = 256;
  const Scene m = load_at("scene_v3.xml", kRes), p = load_at("scene-v4.pbrt", kRes);
  // Independent seeds: the z-test assumes independent estimates.
  const testing::Rendered rm = testing::render_integrator(m, make_render_config("pt", PtSettings{}, testing::test_seed(11)), kPasses);
  const testing::Rendered rp = testing::render_integrator(p, make_render_config("pt", PtSettings{}, testing::test_seed(12)), kPasses);
  const testing::ImageZTest z = testing::image_z_test(rm.mean, rm.variance, rp.mean, rp.variance, 1e-3, 1e-3);
  std::printf("xml vs pbrt, %dx%d, %u spp each: %zu of %zu pixels fail at alpha 1e-3 (%zu allowed); image means %.5f vs %.5f, z %.2f\n",
              kRes, kRes, kPasses, z.failed, z.pixels, z.allowed, z.mean_a, z.mean_b, z.mean_z);
  testing::expect_same_image(rm, rp, "mitsuba-vs-pbrt-cornell", 1e-3, "xml", "pbrt");
}

// The regions and allowance of PbrtCornellBox.RenderMatchesTungstenOnDiffuseWalls.
TEST(MitsubaCornellBox, RenderMatchesTungstenOnDiffuseWalls) {
  REQUIRE_CORNELL_FORMS();
  PATHSPACE_REQUIRE_SHARED_DATA(cornell_dir() + "/TungstenRender.exr");
  constexpr int kRes = 128;
  const Scene scene = load_at("scene_v3.xml", kRes);
  const testing::Rendered r = testing::render_integrator(scene, make_render_config("pt", PtSettings{}, testing::test_seed(7)), 32);
  for (const Rgb& c : r.mean.pixels) ASSERT_TRUE(all_finite(c));
  testing::expect_regions_match_reference(r, read_image(cornell_dir() + "/TungstenRender.exr"),
                                          testing::kCornellDiffuseWalls, 0.02, 1e-3);
}

}  // namespace
}  // namespace pathspace
