// Rendering with cutout opacity (scene/surface_opacity.h; Mitsuba's mask, pbrt-v4's alpha) against
// closed forms, per-pixel z-tests (support/statistics.h) at a Sidak-corrected alpha of 0.01:
//  - a black quad of opacity a filling the view under a sky of radiance 1: every pixel is 1 - a
//    (path tracing and bidirectional path tracing: camera rays through cutouts);
//  - the same with an opacity texture: each pixel is 1 minus the opacity averaged over its
//    footprint (quadrature over the same camera rays and lookups);
//  - a white floor under a directional light shaded by a black cutout of opacity a above the
//    camera: L = (1 - a) rho E / pi, by path tracing, light tracing, BPT, SPPM and PCLT (shadow
//    rays, light paths, connections and photons through cutouts).
#include <gtest/gtest.h>

#include "pathspace/accel/accel.h"
#include "pathspace/scene/surface_opacity.h"
#include "support/integrator_comparison.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

using testing::Rendered;

constexpr int kComparisons = 8;
const double kAlphaImage = testing::sidak(0.01, kComparisons);
constexpr float kOpacity = 0.35f;

// A black quad [-4, 4]^2 in z = 0 facing +z (uv over [0, 1]^2) of opacity kOpacity, seen from above
// under a sky of radiance 1; with `textured`, its opacity is kOpacity times a 4x4 texture.
Scene cutout_under_sky(bool textured) {
  Scene s;
  Material m = make_diffuse(Rgb(0.f));
  m.opacity = kOpacity;
  if (textured) {
    ImageTexture t;
    t.name = "opacity";
    t.width = t.height = 4;
    for (int i = 0; i < 16; ++i) t.texels.push_back(Rgb(float((i * 7) % 16) / 15.f));
    m.opacity = 1.f;
    m.opacity_texture = int32_t(s.add_texture(t));
  }
  const uint32_t mat = s.add_material(m);
  s.add_quad(Vec3(-4, -4, 0), Vec3(4, -4, 0), Vec3(4, 4, 0), Vec3(-4, 4, 0), mat);
  s.uvs = {Point2{0, 0}, Point2{1, 0}, Point2{1, 1}, Point2{1, 1}, Point2{0, 1}, Point2{0, 0}};
  s.add_environment_light(Rgb(1.f));
  s.camera = make_perspective_camera(Vec3(0.1f, -0.2f, 3.f), Vec3(0, 0, -1), Vec3(0, 1, 0), 40.f, 16, 16);
  s.finalize();
  return s;
}

// 1 minus the opacity averaged over each pixel's footprint (16 x 16 midpoint rule), read at the hits
// of an opaque copy of the scene.
Image expected_transmission(const Scene& scene) {
  Scene opaque = scene;
  opaque.materials[0].opacity = 1.f;
  opaque.materials[0].opacity_texture = -1;
  opaque.finalize();
  const SceneView v = scene.view();
  return testing::footprint_average(opaque, Accel(opaque), 16, [&](const SurfaceHit* hit) {
    if (!hit) return Rgb(1.f);
    const Triangle& tri = v.triangles[hit->prim];
    return Rgb(1.f - triangle_opacity(tri, v.materials[tri.material], v.uvs, v.textures, hit->u, hit->v));
  });
}

Image constant_image(const Scene& s, float value) {
  Image img(s.camera.width, s.camera.height);
  for (Rgb& p : img.pixels) p = Rgb(value);
  return img;
}

void expect_matches(const Rendered& r, const Image& expected, const std::string& what) {
  testing::expect_matches_exact(r, expected, what, kAlphaImage);
}

TEST(CutoutRender, ConstantOpacityUnderSkyTransmitsOneMinusOpacity) {
  const Scene scene = cutout_under_sky(false);
  const Accel accel(scene);
  const Image expected = constant_image(scene, 1.f - kOpacity);
  expect_matches(testing::render_integrator(scene, accel, testing::default_config("pt", testing::test_seed(401)), 256), expected, "pt");
  expect_matches(testing::render_integrator(scene, accel, testing::default_config("bpt", testing::test_seed(402)), 128), expected, "bpt");
}

TEST(CutoutRender, TexturedOpacityUnderSkyFollowsTheTexture) {
  const Scene scene = cutout_under_sky(true);
  const Accel accel(scene);
  const Image expected = expected_transmission(scene);
  float lo = 1.f, hi = 0.f;
  for (const Rgb& c : expected.pixels) lo = std::min(lo, c.r), hi = std::max(hi, c.r);
  EXPECT_GT(hi - lo, 0.3f) << "the texture must show";
  expect_matches(testing::render_integrator(scene, accel, testing::default_config("pt", testing::test_seed(403)), 256), expected, "pt");
}

// A white floor (albedo 0.8, z = 0, [-1, 1]^2) lit straight down by a directional light of irradiance 1, a black
// cutout of opacity kOpacity at z = 2 over all of it, the camera at z = 1 looking down.
Scene shaded_floor() {
  Scene s;
  const uint32_t floor = s.add_material(make_diffuse(Rgb(0.8f)));
  Material black = make_diffuse(Rgb(0.f));
  black.opacity = kOpacity;
  const uint32_t cutout = s.add_material(black);
  // Small, so that light tracing's light paths (from a disk as wide as the scene) mostly land in view.
  s.add_quad(Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), floor);
  s.add_quad(Vec3(-1, -1, 2), Vec3(1, -1, 2), Vec3(1, 1, 2), Vec3(-1, 1, 2), cutout);
  s.add_directional_light(Vec3(0, 0, -1), Rgb(1.f));
  s.camera = make_perspective_camera(Vec3(0.f, 0.f, 1.f), Vec3(0, 0, -1), Vec3(0, 1, 0), 40.f, 16, 16);
  s.finalize();
  return s;
}

TEST(CutoutRender, ShadowsThroughACutoutMatchTheClosedForm) {
  const Scene scene = shaded_floor();
  const Accel accel(scene);
  const Image expected = constant_image(scene, (1.f - kOpacity) * 0.8f * kInvPi);
  expect_matches(testing::render_integrator(scene, accel, testing::default_config("pt", testing::test_seed(404)), 256), expected, "pt");
  LtSettings lt;
  lt.light_paths = 16384;
  expect_matches(testing::render_integrator(scene, accel, make_render_config("lt", lt, testing::test_seed(405)), 256), expected, "lt");
  expect_matches(testing::render_integrator(scene, accel, testing::default_config("bpt", testing::test_seed(406)), 128), expected, "bpt");
  // The gathering estimators: photons and light paths through the cutout onto a floor lit evenly, so
  // their radius adds no bias.
  SppmSettings sppm;
  sppm.photons = 16384;
  expect_matches(testing::render_integrator(scene, accel, make_render_config("sppm", sppm, testing::test_seed(407)), 64), expected, "sppm");
  PcltSettings pclt;
  pclt.light_paths = 16384;
  expect_matches(testing::render_integrator(scene, accel, make_render_config("pclt", pclt, testing::test_seed(408)), 64), expected, "pclt");
}

}  // namespace
}  // namespace pathspace
