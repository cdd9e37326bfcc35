// Light selection (issue 18, item 6; docs/conventions.md, "Light selection"):
//  - uniform, power and bvh estimate the same image, for plain PT, PT with the hashed filter, PT
//    with the consistent filter, and PCLT, in a Cornell box lit by its ceiling emitter, a point
//    light and a spot light. Per-pixel z-test (support/statistics.h) of each selection against
//    bvh, alpha 0.01 Sidak over all comparisons. A filter's voxel or ball averages are biased, but
//    by the same amount under every selection: each vertex's next event estimate is unbiased for
//    its own incident light whichever light it picks, so the filtered expectations agree.
//  - the light tree pays off where it should: next to a point light, an emitter of 30,000
//    triangles with ten times its power lights the floor from afar. At equal samples per pixel
//    the tree's relMSE is at most 0.25x uniform's and 0.7x power's (issue 18's acceptance).
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <cmath>

#include "pathspace/accel/accel.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/filters/consistent_filter_settings.h"
#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/integrators/pclt/pclt_settings.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/scene/builtin_scenes.h"
#include "support/integrator_comparison.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

Scene mixed_lights_box(LightSelection selection) {
  Scene scene = make_builtin_scene("cornell-box", 16, 16);
  const Bounds3 b = scene.geometry_bounds();
  const Vec3 c = b.center(), d = b.diagonal();
  scene.add_point_light(c + Vec3(-0.3f * d.x, 0.2f * d.y, 0.1f * d.z), Rgb(0.4f, 0.3f, 0.2f));
  const Vec3 spot = c + Vec3(0.3f * d.x, 0.35f * d.y, 0.f);
  scene.add_spot_light(spot, Vec3(0.f, -1.f, 0.3f), Rgb(1.f, 1.5f, 2.f), std::cos(0.5f), std::cos(0.3f));
  scene.light_selection = selection;
  scene.finalize();
  return scene;
}

struct Case {
  const char* name;
  RenderConfig config;
  uint32_t passes;
};

std::vector<Case> cases() {
  PcltSettings pclt;
  pclt.light_paths = 4096;
  return {
      {"pt", make_render_config("pt", PtSettings{}, testing::test_seed(71)), 512},
      {"pt-hashed", with_filter(make_render_config("pt", PtSettings{}, testing::test_seed(72)), "hashed", HashedFilterSettings{}), 512},
      {"pt-consistent", with_filter(make_render_config("pt", PtSettings{}, testing::test_seed(73)), "consistent", ConsistentFilterSettings{}), 256},
      {"pclt", make_render_config("pclt", pclt, testing::test_seed(74)), 256},
  };
}

TEST(LightSelection, EverySelectionEstimatesTheSameImage) {
  const std::vector<Case> all = cases();
  const double alpha = testing::sidak(0.01, 2 * int(all.size()));
  const Scene bvh = mixed_lights_box(LightSelection::bvh);
  const Accel accel(bvh);
  for (const Case& c : all) {
    const testing::Rendered reference = testing::render_integrator(bvh, accel, c.config, c.passes);
    for (LightSelection other : {LightSelection::uniform, LightSelection::power}) {
      const Scene scene = mixed_lights_box(other);
      RenderConfig config = c.config;
      config.seed += 1000;  // independent of the reference
      const testing::Rendered r = testing::render_integrator(scene, accel, config, c.passes);
      const std::string name = std::string(c.name) + "-" + light_selection_name(other);
      testing::expect_same_image(r, reference, name, alpha, light_selection_name(other), "bvh");
    }
  }
}

// A floor lit by a point light close above it, and from afar by a panel of 150 x 100 quads
// (30,000 triangles) facing down with ten times the point light's power.
Scene many_emitters(LightSelection selection) {
  Scene s;
  s.name = "many-emitters";
  const uint32_t floor = s.add_material(make_diffuse(Rgb(0.7f)));
  s.add_quad(Vec3(-8.f, 0.f, -8.f), Vec3(-8.f, 0.f, 8.f), Vec3(8.f, 0.f, 8.f), Vec3(8.f, 0.f, -8.f), floor);
  const float intensity = 1.f;
  s.add_point_light(Vec3(0.f, 0.5f, 0.f), Rgb(intensity));
  // Panel: x in [4, 7], z in [-1.5, 1.5] at height 3; power pi * area * L = 10 * 4 pi I.
  const int nx = 150, nz = 100;
  const float x0 = 4.f, z0 = -1.5f, sx = 3.f / float(nx), sz = 3.f / float(nz);
  const float radiance = 10.f * 4.f * intensity / 9.f;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < nz; ++j) {
      const Vec3 p(x0 + float(i) * sx, 3.f, z0 + float(j) * sz);
      // Counter-clockwise seen from below: the normal points down, towards the floor.
      s.add_quad(p, p + Vec3(sx, 0.f, 0.f), p + Vec3(sx, 0.f, sz), p + Vec3(0.f, 0.f, sz), floor, Rgb(radiance));
    }
  const Vec3 eye(0.f, 4.f, -3.f);
  s.camera = make_perspective_camera(eye, Vec3(0.5f, 0.f, 0.f) - eye, Vec3(0.f, 1.f, 0.f), 60.f, 48, 48);
  s.light_selection = selection;
  s.finalize();
  return s;
}

TEST(LightSelection, TreeBeatsUniformAndPowerNextToAManyTriangleEmitter) {
  const Scene tree = many_emitters(LightSelection::bvh);
  ASSERT_EQ(tree.lights.size(), 30001u);
  const Accel accel(tree);
  const uint32_t spp = 4;
  const RenderConfig reference_config = testing::default_config("pt", testing::test_seed(80));
  const testing::Rendered reference = testing::render_integrator(tree, accel, reference_config, 1024);
  size_t lit = 0;
  for (const Rgb& px : reference.mean.pixels) lit += px.r > 1e-3f;
  ASSERT_GT(lit, reference.mean.size() * 9 / 10);  // the floor fills the image
  double error[3];
  for (LightSelection s : {LightSelection::uniform, LightSelection::power, LightSelection::bvh}) {
    const Scene scene = many_emitters(s);
    const testing::Rendered r = testing::render_integrator(scene, accel, testing::default_config("pt", testing::test_seed(81)), spp);
    error[int(s)] = image_error(r.mean, reference.mean, &reference.variance).rel_mse;
    fmt::print("{}: relMSE {:.4g} at {} spp\n", light_selection_name(s), error[int(s)], spp);
  }
  const double tree_error = error[int(LightSelection::bvh)];
  EXPECT_LE(tree_error, 0.25 * error[int(LightSelection::uniform)]);
  EXPECT_LE(tree_error, 0.7 * error[int(LightSelection::power)]);
}

}  // namespace
}  // namespace pathspace
