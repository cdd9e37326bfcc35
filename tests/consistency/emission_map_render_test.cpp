// Area lights with an emission map (glTF emissiveTexture; lights/light.h): radiance value * T(uv).
//  - Seen directly from above, the emitter's image is the closed form value * T(uv) averaged over
//    each pixel's footprint: path tracing sees it at camera-ray hits (hit uv), light tracing and
//    BPT at the light path's first vertex (the emission sample's uv).
//  - Lighting a floor beside it, path tracing (next event estimation at sampled points, and BSDF
//    hits with MIS), light tracing and BPT agree pixel by pixel, with the emitter's points sampled
//    by the map's brightness (2 x 2 cells per triangle, lights/emission_cells.h).
// Per-pixel z-tests at alpha 0.01 Sidak over the 5 comparisons.
#include <gtest/gtest.h>

#include "pathspace/accel/accel.h"
#include "pathspace/scene/texture.h"
#include "support/integrator_comparison.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

const double kAlphaImage = testing::sidak(0.01, 5);
const Rgb kValue(2.f, 1.5f, 1.f);

// 4 x 4 texels with strong contrast in every channel, bilinear.
ImageTexture emission_map() {
  ImageTexture t;
  t.name = "emission map";
  t.width = t.height = 4;
  for (int i = 0; i < 16; ++i) t.texels.push_back(Rgb(0.1f + 0.06f * float(i), 1.f - 0.06f * float(i), float(i % 3) * 0.45f));
  return t;
}

// A 2 x 2 emitter at height `z` facing +z (or -z), its uv the unit square over it (u along x, v
// along y).
void add_mapped_emitter(Scene* s, float z, bool facing_down) {
  const uint32_t black = s->add_material(make_diffuse(Rgb(0.f)));
  const size_t first = s->positions.size();
  const Point2 uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const int order[2][4] = {{0, 1, 2, 3}, {0, 3, 2, 1}};  // counter-clockwise around the normal
  const int* o = order[facing_down ? 1 : 0];
  auto corner = [&](int k) { return Vec3(2.f * uv[k].x - 1.f, 2.f * uv[k].y - 1.f, z); };
  s->add_quad(corner(o[0]), corner(o[1]), corner(o[2]), corner(o[3]), black, kValue);
  s->uvs.resize(first);
  for (const int k : {o[0], o[1], o[2], o[2], o[3], o[0]}) s->uvs.push_back(uv[k]);
  const int32_t tex = int32_t(s->add_texture(emission_map()));
  for (Light& l : s->lights) l.texture = tex;
}

RenderConfig lt_config(uint64_t seed) {
  LtSettings lt;
  lt.light_paths = 16384;
  return make_render_config("lt", lt, testing::test_seed(seed));
}

TEST(EmissionMapRender, SeenDirectlyItIsTheMap) {
  Scene s;
  add_mapped_emitter(&s, 0.f, false);
  s.camera = make_perspective_camera(Vec3(0.03f, -0.02f, 3.f), Vec3(0, 0, -1), Vec3(0, 1, 0), 45.f, 16, 16);
  s.finalize();
  const Accel accel(s);
  const TextureView map = s.textures[0].view();
  const Image expected = testing::footprint_average(s, accel, 32, [&](const SurfaceHit* hit) {
    return hit && hit->light != kNoLight ? kValue * texture_lookup(map, hit->uv) : Rgb();
  });
  float lo = 1e9f, hi = 0.f;
  for (const Rgb& c : expected.pixels) lo = std::min(lo, c.g), hi = std::max(hi, c.g);
  EXPECT_GT(hi - lo, 0.5f) << "the map must show";
  testing::expect_matches_exact(testing::render_integrator(s, accel, testing::default_config("pt", testing::test_seed(601)), 16), expected,
                                "pt", kAlphaImage);
  testing::expect_matches_exact(testing::render_integrator(s, accel, lt_config(602), 64), expected, "lt", kAlphaImage);
  testing::expect_matches_exact(testing::render_integrator(s, accel, testing::default_config("bpt", testing::test_seed(603)), 32),
                                expected, "bpt", kAlphaImage);
}

TEST(EmissionMapRender, ItLightsAFloorAlikeInEveryIntegrator) {
  Scene s;
  add_mapped_emitter(&s, 0.6f, true);
  s.add_quad(Vec3(-3, -3, 0), Vec3(3, -3, 0), Vec3(3, 3, 0), Vec3(-3, 3, 0), s.add_material(make_diffuse(Rgb(0.7f))));
  s.uvs.resize(s.positions.size());
  // Seen from below the floor's plane is no good: from the side, above the floor, under the emitter.
  s.camera = make_perspective_camera(Vec3(2.6f, 0.1f, 0.3f), normalize(Vec3(-1, 0, -0.15f)), Vec3(0, 0, 1), 60.f, 16, 16);
  s.finalize();
  ASSERT_EQ(s.lights[0].emission_grid, 2u);
  const Accel accel(s);
  const testing::Rendered pt = testing::render_integrator(s, accel, testing::default_config("pt", testing::test_seed(611)), 256);
  double mean = 0.0;
  for (const Rgb& c : pt.mean.pixels) mean += average(c);
  EXPECT_GT(mean / double(pt.mean.size()), 0.02) << "the floor must be lit";
  testing::expect_same_image(pt, testing::render_integrator(s, accel, lt_config(612), 256), "emission map: pt vs lt", kAlphaImage, "pt", "lt");
  testing::expect_same_image(pt, testing::render_integrator(s, accel, testing::default_config("bpt", testing::test_seed(613)), 256),
                             "emission map: pt vs bpt", kAlphaImage, "pt", "bpt");
}

}  // namespace
}  // namespace pathspace
