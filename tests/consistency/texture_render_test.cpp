// Rendering with image textures (docs/testing.md):
//  - a textured diffuse quad under a constant sky reflects L_out = albedo(uv) * L_sky, so each pixel
//    must match the texture averaged over the pixel's footprint (computed by quadrature over the
//    same camera rays and lookups), per-pixel z-test; with the hashed path space filter as well,
//    which demodulates by the textured albedo (Binder et al. 2021, eq. 9) and so must keep texture
//    detail sharp;
//  - light tracing agrees with path tracing in a Cornell box whose walls carry textures and whose
//    back wall has tilted vertex normals (uv and shading normals through the real Embree hits; LT
//    applies the adjoint shading-normal correction).
#include <gtest/gtest.h>

#include "pathspace/accel/accel.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/scene/shading_material.h"
#include "support/integrator_comparison.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

using testing::Rendered;

constexpr int kComparisons = 3;
const double kAlphaImage = testing::sidak(0.01, kComparisons);

ImageTexture checker_texture(int n) {
  ImageTexture t;
  t.name = "checker";
  t.width = t.height = n;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const float k = float((i * 7 + j * 3) % 5);
      t.texels.push_back(Rgb(0.1f + 0.2f * k, 0.9f - 0.15f * k, (i + j) % 2 ? 0.8f : 0.2f));
    }
  return t;
}

// A [-1, 1]^2 quad in z = 0 facing +z, uv (0,0) .. (1,1), seen from above, under a sky of radiance 1.
Scene textured_quad_scene(int resolution) {
  Scene s;
  ImageTexture t = checker_texture(4);
  t.uscale = 2.f;  // repeats once across the quad
  s.add_texture(t);
  Material m = make_diffuse(Rgb(1.f));
  m.diffuse_texture = 0;
  const uint32_t mat = s.add_material(m);
  s.add_quad(Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), mat);
  s.uvs = {Point2{0, 0}, Point2{1, 0}, Point2{1, 1}, Point2{1, 1}, Point2{0, 1}, Point2{0, 0}};
  s.add_environment_light(Rgb(1.f));
  s.camera = make_perspective_camera(Vec3(0.05f, -0.03f, 3.f), Vec3(0, 0, -1), Vec3(0, 1, 0), 30.f, resolution, resolution);
  s.finalize();
  return s;
}

// Mean albedo over each pixel's footprint (32 x 32 midpoint rule over the box pixel filter).
Image expected_radiance(const Scene& scene, const Accel& accel) {
  const SceneView view = scene.view();
  return testing::footprint_average(scene, accel, 32, [&](const SurfaceHit* hit) { return hit ? shading_material(view, *hit).diffuse : Rgb(); });
}

TEST(TextureRender, TexturedQuadUnderSkyMatchesTheTexture) {
  const Scene scene = textured_quad_scene(16);
  const Accel accel(scene);
  const Image expected = expected_radiance(scene, accel);
  testing::expect_matches_exact(testing::render_integrator(scene, accel, testing::default_config("pt", testing::test_seed(301)), 256), expected,
                                "pt", kAlphaImage);

  // The texture must show: a flat grey image would fail the test above by far.
  float lo = 1e9f, hi = -1e9f;
  for (const Rgb& c : expected.pixels) {
    lo = std::min(lo, c.r);
    hi = std::max(hi, c.r);
  }
  EXPECT_GT(hi - lo, 0.3f);
}

TEST(TextureRender, HashedFilterKeepsTextureDetail) {
  const Scene scene = textured_quad_scene(16);
  const Accel accel(scene);
  const Image expected = expected_radiance(scene, accel);
  HashedFilterSettings hashed;
  hashed.key.psf_scale = 8.f;  // voxels much larger than a texel: only demodulation keeps detail
  const RenderConfig f = with_filter(testing::default_config("pt", testing::test_seed(302)), "hashed", hashed);
  testing::expect_matches_exact(testing::render_integrator(scene, accel, f, 128), expected, "pt + hashed filter", kAlphaImage, false);
}

// The empty Cornell box (SmallVCM e_c) with a texture on every diffuse wall (pbrt's default
// triangle uvs) and smoothly varying vertex normals tilted by up to ~20 degrees.
Scene textured_cornell_box(int resolution) {
  Scene s = make_cornell_box(1, resolution, resolution);
  const uint32_t tex = s.add_texture(checker_texture(8));
  std::vector<bool> textured(s.materials.size(), false);
  for (const Triangle& t : s.triangles)
    if (t.light == kNoLight && s.materials[t.material].type == MaterialType::standard && !is_black(s.materials[t.material].diffuse))
      textured[t.material] = true;
  for (size_t i = 0; i < s.materials.size(); ++i)
    if (textured[i]) s.materials[i].diffuse_texture = int32_t(tex);
  s.normals.assign(s.positions.size(), Vec3());

  for (const Triangle& t : s.triangles) {
    const Vec3 ng = triangle_normal(s.positions[t.v[0]], s.positions[t.v[1]], s.positions[t.v[2]]);
    for (uint32_t v : t.v) {
      const Vec3& p = s.positions[v];
      const Vec3 tilt(0.4f * sinf(3.f * p.x + 1.f), 0.4f * sinf(2.f * p.y + 2.f), 0.4f * sinf(4.f * p.z + 3.f));
      s.normals[v] = normalize(ng + (tilt - ng * dot(tilt, ng)));
    }
  }
  s.finalize();
  return s;
}

TEST(TextureRender, LightTracingAgreesWithPathTracing) {
  const Scene scene = textured_cornell_box(16);
  const Accel accel(scene);
  LtSettings lt;
  lt.light_paths = 4096;
  Rendered a = testing::render_integrator(scene, accel, make_render_config("lt", lt, testing::test_seed(303)), 256);
  Rendered b = testing::render_integrator(scene, accel, testing::default_config("pt", testing::test_seed(304)), 1024);
  const std::vector<bool> mask = testing::specular_first_hit_mask(scene, accel);
  testing::apply_mask(&a, mask);
  testing::apply_mask(&b, mask);
  testing::expect_same_image(a, b, "lt-vs-pt-textured", kAlphaImage, "lt", "pt");
  // Textures and normals must change the image, or the comparison would prove nothing new.
  const Scene untextured = make_cornell_box(1, 16, 16);
  const Rendered c = testing::render_integrator(untextured, testing::default_config("pt", testing::test_seed(305)), 1024);
  const testing::ImageZTest z = testing::image_z_test(c.mean, c.variance, b.mean, b.variance, 1e-3, kAlphaImage);
  EXPECT_FALSE(z.passed()) << "textures and vertex normals had no visible effect";
}

}  // namespace
}  // namespace pathspace
