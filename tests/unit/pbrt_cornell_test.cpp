// The real pbrt-v4 Cornell box (Bitterli's, outside the repository: docs/testing.md): it loads with the expected
// geometry, lights and camera, and renders without NaN to diffuse-wall brightnesses that agree with
// Bitterli's Tungsten reference (TungstenRender.exr) in a per-region z-test. Fails when the shared
// scenes folder is absent (support/shared_data.h).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "pathspace/io/image_io.h"
#include "pathspace/io/scene_loader.h"
#include "support/integrator_comparison.h"
#include "support/reference_regions.h"
#include "support/shared_data.h"

namespace pathspace {
namespace {

#ifndef PATHSPACE_SHARED_SCENES_DIR
#define PATHSPACE_SHARED_SCENES_DIR ""
#endif

std::string cornell_dir() { return std::string(PATHSPACE_SHARED_SCENES_DIR) + "/bitterli/cornell-box"; }

#define REQUIRE_CORNELL() PATHSPACE_REQUIRE_SHARED_DATA(cornell_dir() + "/scene-v4.pbrt")

TEST(PbrtCornellBox, GeometryLightsCamera) {
  REQUIRE_CORNELL();
  std::vector<std::string> warnings;
  SceneFileSettings settings;
  const Scene s = load_scene(cornell_dir() + "/scene-v4.pbrt", {}, &warnings, &settings);
  EXPECT_EQ(s.triangles.size(), 36u);  // 5 walls x 2 + 2 boxes x 12 + light x 2
  EXPECT_EQ(s.spheres.size(), 0u);
  ASSERT_EQ(s.lights.size(), 2u);
  for (const Light& l : s.lights) {
    EXPECT_EQ(l.type, LightType::area_triangle);
    EXPECT_EQ(l.value, Rgb(17, 12, 4));
    const Triangle& t = s.triangles[l.shape];
    EXPECT_NEAR(triangle_normal(s.positions[t.v[0]], s.positions[t.v[1]], s.positions[t.v[2]]).y, -1.f, 1e-5f);  // emits down
  }
  EXPECT_EQ(s.camera.width, 1024);
  EXPECT_EQ(s.camera.height, 1024);
  EXPECT_NEAR(distance(s.camera.position, Vec3(0, 1, 6.8f)), 0.f, 1e-6f);
  EXPECT_NEAR(s.camera.forward.z, -1.f, 1e-6f);
  EXPECT_NEAR(s.camera.right.x, 1.f, 1e-6f);  // the red wall (x = -1) is on the left
  EXPECT_NEAR(s.camera.tan_x, std::tan(19.5 * M_PI / 360.0), 1e-6);
  EXPECT_EQ(s.max_path_segments, 66);  // maxdepth 65 bounces
  EXPECT_EQ(settings.spp, 64);
  EXPECT_EQ(settings.image_name, "cornell-box.png");
  EXPECT_TRUE(warnings.empty()) << ::testing::PrintToString(warnings);
  EXPECT_EQ(s.camera.filter.kind, PixelFilterKind::tent);  // PixelFilter "triangle", radius 1 (Tungsten's tent)
  EXPECT_EQ(s.camera.filter.radius, 1.f);
}

TEST(PbrtCornellBox, RenderMatchesTungstenOnDiffuseWalls) {
  REQUIRE_CORNELL();
  PATHSPACE_REQUIRE_SHARED_DATA(cornell_dir() + "/TungstenRender.exr");
  constexpr int kRes = 128;
  SceneLoadOptions o;
  o.width = o.height = kRes;
  const Scene scene = load_scene(cornell_dir() + "/scene-v4.pbrt", o, nullptr);
  const testing::Rendered r = testing::render_integrator(scene, make_render_config("pt", PtSettings{}, 7), 32);
  for (const Rgb& c : r.mean.pixels) ASSERT_TRUE(all_finite(c));
  // Our noise plus a 2% allowance for what differs by design: Tungsten's tent filter and
  // spectral-vs-RGB details, and the reference's own noise.
  testing::expect_regions_match_reference(r, read_image(cornell_dir() + "/TungstenRender.exr"), testing::kCornellDiffuseWalls, 0.02, 1e-3);
}

}  // namespace
}  // namespace pathspace
