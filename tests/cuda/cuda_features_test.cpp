// The GPU renders the materials, lights and surfaces added after its first run through the same
// PS_HD code as the CPU: one Cornell box holds them all (layered walls, coateddiffuse and
// coatedconductor; a cutout with an opacity texture, seen directly and casting a shadow; a projector
// with a slide, a textured spot and a point light, with the ceiling light, selected by the light
// tree; an emitter on the floor whose emission map is sampled by its cells, lights/emission_cells.h).
// The GPU's image must agree with the CPU's by the per-pixel z-test (gpu_comparison.h;
// alpha = 0.01, Sidak-corrected over this file's comparisons), plain and with the hashed filter, and
// the wavefront must equal the megakernel bit for bit. A Cornell box whose light slides and whose
// floor rises during the shutter checks motion blur the same way, as do a moving camera and moving
// point-like lights, and PT's --texture-footprint.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pathspace/scene/builtin_scenes.h"
#include "gpu_comparison.h"
#include "support/integrator_comparison.h"
#include "support/statistics.h"
#include "support/test_scenes.h"

namespace pathspace {
namespace {

constexpr int kComparisons = 6;
const double kAlphaImage = testing::sidak(0.01, kComparisons);

ImageTexture four_by_four(const char* name, bool monochrome) {
  ImageTexture t;
  t.name = name;
  t.width = t.height = 4;
  for (int i = 0; i < 16; ++i) {
    const float v = float((i * 7) % 16) / 15.f;
    t.texels.push_back(monochrome ? Rgb(v) : Rgb(0.2f + 0.05f * float(i), 1.f - 0.06f * float(i), v));
  }
  return t;
}

Scene features_box() {
  Scene s = testing::make_coated_cornell_box(48, false);
  // A horizontal cutout (normal +z) under the ceiling light, its opacity a 4x4 texture.
  Material cutout = make_diffuse(Rgb(0.7f, 0.6f, 0.3f));
  cutout.opacity_texture = int32_t(s.add_texture(four_by_four("opacity", true)));
  const uint32_t cutout_material = s.add_material(cutout);
  s.uvs.resize(s.positions.size());  // the box's own vertices have no uvs
  s.add_quad(Vec3(-0.6f, -0.5f, 0.3f), Vec3(0.6f, -0.5f, 0.3f), Vec3(0.6f, 0.7f, 0.3f), Vec3(-0.6f, 0.7f, 0.3f), cutout_material);
  s.uvs.insert(s.uvs.end(), {Point2{0, 0}, Point2{1, 0}, Point2{1, 1}, Point2{1, 1}, Point2{0, 1}, Point2{0, 0}});
  // Lights beside the ceiling's: a projector and a textured spot looking down, and a point light.
  const int32_t slide = int32_t(s.add_texture(four_by_four("slide", false)));
  const Frame down(Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0, -1));
  s.add_projector_light(Vec3(0.6f, 0.4f, 1.1f), down, Rgb(2.f), slide, -1.f, 1.25f, true);
  s.add_spot_light(Vec3(-0.6f, -0.3f, 1.1f), down.n, Rgb(3.f), std::cos(0.45f), std::cos(0.25f));
  Light& spot = s.lights.back();
  spot.falloff = SpotFalloff::linear_angle;
  spot.texture = slide;
  spot.axis_u = down.s;
  spot.axis_v = down.t;
  spot.uv_scale_u = 0.5f / std::tan(0.45f);
  spot.uv_scale_v = -spot.uv_scale_u;
  s.add_point_light(Vec3(0.8f, -0.6f, -0.4f), Rgb(0.4f, 0.3f, 0.2f));
  // A mapped emitter on the floor, facing up: 8 x 8 texels with one bright one (4 x 4 cells).
  ImageTexture map;
  map.name = "emission map";
  map.width = map.height = 8;
  for (int i = 0; i < 64; ++i) map.texels.push_back(i == 19 ? Rgb(6.f, 5.f, 3.f) : Rgb(0.1f + 0.01f * float(i % 8), 0.2f, 0.1f));
  const int32_t emission_map = int32_t(s.add_texture(std::move(map)));
  const size_t first_light = s.lights.size();
  s.add_quad(Vec3(-1.f, 0.3f, -1.26f), Vec3(-0.5f, 0.3f, -1.26f), Vec3(-0.5f, 0.8f, -1.26f), Vec3(-1.f, 0.8f, -1.26f),
             s.add_material(make_diffuse(Rgb(0.f))), Rgb(1.f));
  s.uvs.insert(s.uvs.end(), {Point2{0, 0}, Point2{1, 0}, Point2{1, 1}, Point2{1, 1}, Point2{0, 1}, Point2{0, 0}});
  for (size_t i = first_light; i < s.lights.size(); ++i) s.lights[i].texture = emission_map;
  s.light_selection = LightSelection::bvh;  // the box alone selects uniformly, as SmallVCM does
  s.finalize();
  return s;
}

// Runs everywhere (no GPU needed): the scene holds what the GPU tests are meant to exercise, and the
// CPU renders it to a finite, non-black image.
TEST(CudaFeatures, SceneHoldsEveryFeature) {
  const Scene scene = features_box();
  const SceneView v = scene.view();
  EXPECT_TRUE(v.has_cutouts);
  EXPECT_TRUE(v.light_tree.active);
  auto has_material = [&](MaterialType type) {
    return std::any_of(scene.materials.begin(), scene.materials.end(), [&](const Material& m) { return m.type == type; });
  };
  EXPECT_TRUE(has_material(MaterialType::coated_diffuse));
  EXPECT_TRUE(has_material(MaterialType::coated_conductor));
  EXPECT_TRUE(std::any_of(scene.lights.begin(), scene.lights.end(), [](const Light& l) { return l.type == LightType::projector; }));
  EXPECT_TRUE(std::any_of(scene.lights.begin(), scene.lights.end(), [](const Light& l) { return l.type == LightType::spot && l.texture >= 0; }));
  EXPECT_TRUE(std::any_of(scene.lights.begin(), scene.lights.end(), [](const Light& l) { return l.emission_grid > 0; }));
  const testing::Rendered r = testing::render_integrator(scene, testing::default_config("pt", testing::test_seed(10)), 2);
  double sum = 0.0;
  for (const Rgb& p : r.mean.pixels) sum += double(p.r) + double(p.g) + double(p.b);
  EXPECT_TRUE(std::isfinite(sum));
  EXPECT_GT(sum, 0.0);
}

TEST(CudaFeatures, LayeredCutoutProjectorSceneMatchesCpu) {
  PATHSPACE_REQUIRE_GPU();
  const Scene scene = features_box();
  testing::expect_gpu_matches_cpu(scene, testing::default_config("pt", testing::test_seed(11)), 256, "features pt cuda vs cpu",
                                  kAlphaImage);
  const RenderConfig hashed = with_filter(testing::default_config("pt", testing::test_seed(12)), "hashed", HashedFilterSettings{});
  testing::expect_gpu_matches_cpu(scene, hashed, 256, "features pt + hashed cuda vs cpu", kAlphaImage);
}

TEST(CudaFeatures, WavefrontEqualsMegakernelBitForBit) {
  PATHSPACE_REQUIRE_GPU();
  testing::expect_pipelines_agree(features_box(), FilterChoice{});
}

// Motion blur (scene/motion.h): the Cornell box's light box slides and its floor rises while the
// shutter is open, so camera rays, shadow rays and light samples all depend on the path's time.
Scene moving_cornell_box() {
  Scene s = make_builtin_scene("cornell-box", 48, 48);
  s.positions_end = s.positions;
  for (int t = 0; t < 2; ++t)
    for (uint32_t v : s.triangles[size_t(t)].v) s.positions_end[v].z += 0.3f;
  for (size_t t = s.triangles.size() - kLightBoxTriangles; t < s.triangles.size(); ++t)
    for (uint32_t v : s.triangles[t].v) s.positions_end[v] = s.positions[v] + Vec3(0.7f, 0.f, 0.f);
  s.finalize();
  return s;
}

TEST(CudaFeatures, MotionBlurMatchesCpu) {
  PATHSPACE_REQUIRE_GPU();
  const Scene scene = moving_cornell_box();
  ASSERT_NE(scene.view().positions_end, nullptr);
  testing::expect_gpu_matches_cpu(scene, testing::default_config("pt", testing::test_seed(13)), 256, "moving cornell-box pt cuda vs cpu",
                                  kAlphaImage);
  testing::expect_pipelines_agree(scene, FilterChoice{});
}

// Camera motion blur (scene/motion.h, camera_at): the camera slides and turns a little while the
// shutter is open; the device builds each camera ray from the camera at the path's time.
TEST(CudaFeatures, CameraMotionBlurMatchesCpu) {
  PATHSPACE_REQUIRE_GPU();
  Scene scene = make_builtin_scene("cornell-box", 48, 48);
  PerspectiveCamera end = make_perspective_camera(scene.camera.position + scene.camera.right * 0.4f,
                                                  scene.camera.forward + scene.camera.right * 0.1f, scene.camera.up, 40.f, 48, 48);
  scene.camera_moves = true;
  scene.camera_end = end.pose();
  scene.finalize();
  ASSERT_TRUE(scene.view().camera_moves);
  testing::expect_gpu_matches_cpu(scene, testing::default_config("pt", testing::test_seed(14)), 256, "moving camera pt cuda vs cpu",
                                  kAlphaImage);
  testing::expect_pipelines_agree(scene, FilterChoice{});
}

// Moving point-like lights (lights/light.h, light_position): the features box's projector, spot and
// point light slide while the shutter is open; the device samples, bounds and probes each at the
// path's time.
TEST(CudaFeatures, MovingPointLightsMatchCpu) {
  PATHSPACE_REQUIRE_GPU();
  Scene scene = features_box();
  int moving = 0;
  for (Light& l : scene.lights) {
    if (l.type != LightType::point && l.type != LightType::spot && l.type != LightType::projector) continue;
    l.moves = true;
    l.position_end = l.position + Vec3(-0.5f, 0.3f, -0.2f);
    ++moving;
  }
  ASSERT_EQ(moving, 3);
  scene.finalize();
  ASSERT_TRUE(scene.view().lights_move);
  testing::expect_gpu_matches_cpu(scene, testing::default_config("pt", testing::test_seed(15)), 256, "moving lights pt cuda vs cpu",
                                  kAlphaImage);
  testing::expect_pipelines_agree(scene, FilterChoice{});
}

// --texture-footprint (scene/texture_footprint.h): the cutout also carries a diffuse texture eight
// times repeated, about two texels per pixel, so the device averages it over each camera hit's pixel.
TEST(CudaFeatures, TextureFootprintMatchesCpu) {
  PATHSPACE_REQUIRE_GPU();
  Scene scene = features_box();
  ImageTexture fine = four_by_four("fine", false);
  fine.uscale = fine.vscale = 8.f;
  const int32_t texture = int32_t(scene.add_texture(fine));
  int textured = 0;
  for (Material& m : scene.materials)
    if (m.opacity_texture >= 0) {
      m.diffuse_texture = texture;
      ++textured;
    }
  ASSERT_EQ(textured, 1);
  scene.finalize();
  PtSettings pt;
  pt.texture_footprint = true;
  testing::expect_gpu_matches_cpu(scene, make_render_config("pt", pt, testing::test_seed(16)), 256, "texture footprint pt cuda vs cpu",
                                  kAlphaImage);
}

}  // namespace
}  // namespace pathspace
