// Rendering with image textures (docs/testing.md):
//  - a textured diffuse quad under a constant sky reflects L_out = albedo(uv) * L_sky, so each pixel
//    must match the texture averaged over the pixel's footprint (computed by quadrature over the
//    same camera rays and lookups), per-pixel z-test; with the hashed path space filter as well,
//    which demodulates by the textured albedo (Binder et al. 2021, eq. 9) and so must keep texture
//    detail sharp;
//  - light tracing agrees with path tracing in a Cornell box whose walls carry textures and whose
//    back wall has tilted vertex normals (uv and shading normals through the real Embree hits; LT
//    applies the adjoint shading-normal correction);
//  - PT's --texture-footprint (scene/texture_footprint.h): a camera hit's textures averaged over its
//    pixel are the same for every ray of the pixel, close to the pixel's exact average where a point
//    lookup is far from it, the same through any lens point of a thin lens focused on the surface,
//    the point lookup itself where the texture is magnified, and what the
//    rendered image converges to (z-test); untextured scenes render bit for bit as without it.
#include <gtest/gtest.h>

#include "pathspace/accel/accel.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/scene/shading_material.h"
#include "pathspace/scene/texture_footprint.h"
#include "support/integrator_comparison.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

using testing::Rendered;

constexpr int kComparisons = 5;
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

// A [-1, 1]^2 quad in z = 0 facing +z, uv (0,0) .. (1,1), seen from above, under a sky of radiance 1,
// textured with a texels x texels checker repeated twice across (16 px: texels / 4 texels per pixel).
Scene textured_quad_scene(int resolution, int texels = 4) {
  Scene s;
  ImageTexture t = checker_texture(texels);
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

// The camera hit's footprint-averaged albedo of each pixel seen through raster position (x + fx, y + fy).
Image footprint_albedo(const Scene& scene, const Accel& accel, float fx, float fy) {
  const SceneView view = scene.view();
  Image out(scene.camera.width, scene.camera.height);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      const Ray ray = scene.camera.generate_ray(float(x) + fx, float(y) + fy);
      SurfaceHit hit;
      if (!accel.intersect(ray, &hit)) continue;
      Material storage;
      out.at(x, y) = footprint_shading_material(view, hit, ray, &storage).diffuse;
    }
  return out;
}

double rms_difference(const Image& a, const Image& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) sum += double(a.pixels[i][c] - b.pixels[i][c]) * double(a.pixels[i][c] - b.pixels[i][c]);
  return std::sqrt(sum / double(3 * a.pixels.size()));
}

TEST(TextureFootprint, AveragesTheTextureOverThePixel) {
  const Scene scene = textured_quad_scene(16, 32);  // about 3 texels per pixel each way: aliased
  const Accel accel(scene);
  const Image exact = expected_radiance(scene, accel);
  const Image centre = footprint_albedo(scene, accel, 0.5f, 0.5f);
  for (const auto& [fx, fy] : {std::pair{0.1f, 0.8f}, std::pair{0.93f, 0.02f}}) {
    const Image jittered = footprint_albedo(scene, accel, fx, fy);
    for (size_t i = 0; i < centre.pixels.size(); ++i) ASSERT_EQ(jittered.pixels[i], centre.pixels[i]) << "pixel " << i;
  }
  const SceneView view = scene.view();
  const Image point = testing::footprint_average(scene, accel, 1, [&](const SurfaceHit* hit) { return hit ? shading_material(view, *hit).diffuse : Rgb(); });
  const double footprint_error = rms_difference(centre, exact), point_error = rms_difference(point, exact);
  // 4 x 4 lookups against a 32 x 32 quadrature of the same bilinear texture: what is left is the
  // coarser rule's error, measured 0.0055 against the point lookup's 0.12.
  EXPECT_LT(footprint_error, 0.1 * point_error) << "footprint " << footprint_error << ", point lookup " << point_error;
  EXPECT_GT(point_error, 0.05) << "the texture must alias at one lookup per pixel, or this proves nothing";
}

// A thin lens focused on the quad: every lens point sees the pixel's square on the quad, so rays
// through any lens point of a pixel average the same texels (up to rounding).
TEST(TextureFootprint, ThinLensFocusedOnTheSurfaceSeesThePixel) {
  Scene scene = textured_quad_scene(16, 32);
  ASSERT_TRUE(set_thin_lens(&scene.camera, 0.05f, 3.f));  // the quad lies 3 units below the lens
  scene.finalize();
  const Accel accel(scene);
  const SceneView view = scene.view();
  const Scene pinhole_scene = textured_quad_scene(16, 32);
  const Image pinhole = footprint_albedo(pinhole_scene, Accel(pinhole_scene), 0.5f, 0.5f);
  double largest = 0.0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      for (const Point2 lens : {Point2{0.1f, 0.2f}, Point2{0.9f, 0.6f}}) {
        const Ray ray = scene.camera.generate_ray(float(x) + 0.3f, float(y) + 0.7f, lens);
        SurfaceHit hit;
        ASSERT_TRUE(accel.intersect(ray, &hit));
        Material storage;
        const Rgb a = footprint_shading_material(view, hit, ray, &storage).diffuse, b = pinhole.at(x, y);
        for (int c = 0; c < 3; ++c) largest = std::max(largest, double(std::fabs(a[c] - b[c])));
      }
  EXPECT_LT(largest, 1e-3);
}

TEST(TextureFootprint, MagnifiedTexturesKeepThePointLookup) {
  const Scene scene = textured_quad_scene(16, 4);  // half a texel per pixel
  const Accel accel(scene);
  const SceneView view = scene.view();
  for (const auto& [fx, fy] : {std::pair{0.5f, 0.5f}, std::pair{0.1f, 0.8f}}) {
    const Image footprint = footprint_albedo(scene, accel, fx, fy);
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) {
        SurfaceHit hit;
        ASSERT_TRUE(accel.intersect(scene.camera.generate_ray(float(x) + fx, float(y) + fy), &hit));
        ASSERT_EQ(footprint.at(x, y), shading_material(view, hit).diffuse) << x << "," << y;
      }
  }
}

TEST(TextureFootprint, PathTracingConvergesToTheFootprintAverage) {
  const Scene scene = textured_quad_scene(16, 32);
  const Accel accel(scene);
  const Image expected = footprint_albedo(scene, accel, 0.5f, 0.5f);  // times the sky's radiance 1
  PtSettings pt;
  pt.texture_footprint = true;
  const Rendered footprint = testing::render_integrator(scene, accel, make_render_config("pt", pt, testing::test_seed(306)), 256);
  testing::expect_matches_exact(footprint, expected, "pt --texture-footprint", kAlphaImage);
  // The point lookup converges to nearly the same image, so the z-test alone would not notice PT
  // ignoring the option. Without light sampling every path of this scene is camera, quad, sky, and
  // its value is the albedo times 1 exactly (f cos / pdf = albedo): then each pixel's samples all
  // equal its footprint average, while point lookups scatter over the texels.
  pt.nee = false;
  const Rendered exact = testing::render_integrator(scene, accel, make_render_config("pt", pt, testing::test_seed(308)), 4);
  pt.texture_footprint = false;
  const Rendered point = testing::render_integrator(scene, accel, make_render_config("pt", pt, testing::test_seed(308)), 4);
  double point_variance = 0.0;
  for (size_t i = 0; i < expected.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      ASSERT_NEAR(exact.mean.pixels[i][c], expected.pixels[i][c], 1e-5f * expected.pixels[i][c]) << "pixel " << i;
      ASSERT_LT(exact.variance.pixels[i][c], 1e-10f) << "pixel " << i;
    }
    point_variance += luminance(point.variance.pixels[i]);
  }
  EXPECT_GT(point_variance / double(expected.pixels.size()), 1e-3) << "point lookups should scatter here";
  HashedFilterSettings hashed;
  hashed.key.psf_scale = 8.f;
  const RenderConfig f = with_filter(make_render_config("pt", pt, testing::test_seed(307)), "hashed", hashed);
  testing::expect_matches_exact(testing::render_integrator(scene, accel, f, 128), expected, "pt --texture-footprint + hashed filter",
                                kAlphaImage, false);
}

TEST(TextureFootprint, UntexturedScenesRenderAsWithoutIt) {
  const Scene scene = make_cornell_box(0, 24, 24);
  PtSettings pt;
  pt.texture_footprint = true;
  const Rendered a = testing::render_integrator(scene, testing::default_config("pt", 5), 4);
  const Rendered b = testing::render_integrator(scene, make_render_config("pt", pt, 5), 4);
  for (size_t i = 0; i < a.mean.pixels.size(); ++i) ASSERT_EQ(a.mean.pixels[i], b.mean.pixels[i]) << "pixel " << i;
}

}  // namespace
}  // namespace pathspace
