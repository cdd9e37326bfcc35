// Image environments in a scene with occlusion (a diffuse sphere on a glossy-free plane under a
// non-uniform lat-long sky with a bright sun texel): PT (MIS) and BPT must agree per pixel, which
// checks BPT's MIS densities for the image; and a constant image must render as the constant light
// of the same value (PT, per-pixel z-test of independent renders).
#include <gtest/gtest.h>

#include <cmath>

#include "support/integrator_comparison.h"

namespace pathspace {
namespace {

EnvironmentImage sky(bool constant) {
  EnvironmentImage e;
  e.name = constant ? "constant" : "sky";
  e.width = 24;
  e.height = 12;
  e.mapping = EnvironmentMapping::lat_long;
  for (int y = 0; y < e.height; ++y)
    for (int x = 0; x < e.width; ++x) {
      const float v = constant ? 0.8f : 0.3f + 0.1f * float(x % 5) + (y < 6 ? 0.6f : 0.05f);
      e.texels.push_back(Rgb(v, 0.9f * v, 1.1f * v));
    }
  if (!constant) e.texels[3 * 24 + 7] = Rgb(60.f, 50.f, 40.f);  // a sun above the horizon
  e.axis_x = Vec3(1, 0, 0);
  e.axis_y = Vec3(0, 0, 1);  // map up = world +z
  e.axis_z = Vec3(0, -1, 0);
  return e;
}

Scene sphere_on_plane(EnvironmentImage image, const Rgb& value) {
  Scene s;
  const uint32_t floor = s.add_material(make_diffuse(Rgb(0.6f)));
  const uint32_t ball = s.add_material(make_diffuse(Rgb(0.4f, 0.5f, 0.7f)));
  s.add_quad(Vec3(-3, -3, 0), Vec3(3, -3, 0), Vec3(3, 3, 0), Vec3(-3, 3, 0), floor);
  s.add_sphere(Vec3(0, 0, 0.7f), 0.7f, ball);
  if (image.empty()) s.add_environment_light(value);
  else s.add_environment_map(std::move(image), value);
  s.camera = make_perspective_camera(Vec3(0, -4, 2.5f), Vec3(0, 1, -0.45f), Vec3(0, 0, 1), 40.f, 20, 20);
  s.finalize();
  return s;
}

TEST(EnvironmentImage, PtAndBptAgree) {
  const Scene scene = sphere_on_plane(sky(false), Rgb(1.f));
  const Accel accel(scene);
  const testing::Rendered pt = testing::render_integrator(scene, accel, testing::default_config("pt", testing::test_seed(61)), 512);
  const testing::Rendered bpt = testing::render_integrator(scene, accel, testing::default_config("bpt", testing::test_seed(62)), 256);
  testing::expect_same_image(pt, bpt, "envmap-pt-vs-bpt", 1e-3, "pt", "bpt");
}

TEST(EnvironmentImage, ConstantImageRendersAsConstantLight) {
  const Scene image = sphere_on_plane(sky(true), Rgb(1.25f));
  const Scene constant = sphere_on_plane(EnvironmentImage{}, Rgb(0.8f * 1.25f, 0.72f * 1.25f, 0.88f * 1.25f));
  const testing::Rendered a = testing::render_integrator(image, testing::default_config("pt", testing::test_seed(63)), 256);
  const testing::Rendered b = testing::render_integrator(constant, testing::default_config("pt", testing::test_seed(64)), 256);
  testing::expect_same_image(a, b, "envmap-constant-vs-constant-light", 1e-3, "image", "constant");
}

}  // namespace
}  // namespace pathspace
