// Image textures: bilinear lookup at texel centres and between them, repeat addressing, the uv
// transform, sRGB decoding of 8-bit files (and the linear option), uv and shading-normal
// interpolation on triangles, spherical uv on spheres, and the shaded material.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/camera/perspective_camera.h"
#include "pathspace/io/image_io.h"
#include "pathspace/io/texture_file.h"
#include "pathspace/scene/shading_material.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

// A texture named "t" of width x height linear texels, every other field at its default.
ImageTexture texture_of(int width, int height, std::vector<Rgb> texels) {
  ImageTexture t;
  t.name = "t";
  t.width = width;
  t.height = height;
  t.texels = std::move(texels);
  return t;
}

// 2x2 texels, row 0 at the top: a b / c d.
const Rgb kTexels[4] = {Rgb(1.f, 0.f, 0.f), Rgb(0.f, 1.f, 0.f), Rgb(0.f, 0.f, 1.f), Rgb(1.f, 1.f, 1.f)};

TextureView two_by_two() { return TextureView{kTexels, 2, 2}; }

void expect_rgb_near(const Rgb& a, const Rgb& b, float tol = 1e-6f) {
  EXPECT_NEAR(a.r, b.r, tol);
  EXPECT_NEAR(a.g, b.g, tol);
  EXPECT_NEAR(a.b, b.b, tol);
}

TEST(TextureLookup, TexelCentresReturnTheTexels) {
  const TextureView t = two_by_two();
  // Texel (i, j) has its centre at u = (i + 0.5) / w, v = 1 - (j + 0.5) / h (v = 0 at the bottom row).
  expect_rgb_near(texture_lookup(t, {0.25f, 0.75f}), kTexels[0]);
  expect_rgb_near(texture_lookup(t, {0.75f, 0.75f}), kTexels[1]);
  expect_rgb_near(texture_lookup(t, {0.25f, 0.25f}), kTexels[2]);
  expect_rgb_near(texture_lookup(t, {0.75f, 0.25f}), kTexels[3]);
}

TEST(TextureLookup, BilinearBetweenTexels) {
  const TextureView t = two_by_two();
  expect_rgb_near(texture_lookup(t, {0.5f, 0.75f}), (kTexels[0] + kTexels[1]) * 0.5f);
  expect_rgb_near(texture_lookup(t, {0.25f, 0.5f}), (kTexels[0] + kTexels[2]) * 0.5f);
  expect_rgb_near(texture_lookup(t, {0.5f, 0.5f}), (kTexels[0] + kTexels[1] + kTexels[2] + kTexels[3]) * 0.25f);
  // A quarter of the way from texel a's centre towards b's: weights 3/4, 1/4.
  expect_rgb_near(texture_lookup(t, {0.375f, 0.75f}), kTexels[0] * 0.75f + kTexels[1] * 0.25f);
}

TEST(TextureLookup, RepeatAddressing) {
  const TextureView t = two_by_two();
  for (const float du : {-3.f, -1.f, 1.f, 2.f, 17.f})
    for (const float dv : {-2.f, 0.f, 1.f, 5.f}) {
      expect_rgb_near(texture_lookup(t, {0.25f + du, 0.75f + dv}), kTexels[0], 1e-5f);
      expect_rgb_near(texture_lookup(t, {0.6f + du, 0.1f + dv}), texture_lookup(t, {0.6f, 0.1f}), 1e-5f);
    }
  // At u = 0 the left column blends with the right one (they are neighbours under wrapping).
  expect_rgb_near(texture_lookup(t, {0.f, 0.75f}), (kTexels[0] + kTexels[1]) * 0.5f);
  expect_rgb_near(texture_lookup(t, {1.f, 0.75f}), (kTexels[0] + kTexels[1]) * 0.5f);
  // Non-finite coordinates stay inside the image.
  const Rgb nan_lookup = texture_lookup(t, {NAN, INFINITY});
  EXPECT_TRUE(all_finite(nan_lookup));
}

// Mirror: every other period is the image turned over, so the edge texels meet their own copies;
// clamp: outside is the edge texel, and at the edge the bilinear neighbour is the edge texel itself.
TEST(TextureLookup, MirrorAndClampAddressing) {
  TextureView t = two_by_two();
  t.wrap = TextureWrap::mirror;
  expect_rgb_near(texture_lookup(t, {1.25f, 0.75f}), kTexels[1], 1e-5f);  // u in (1, 2): mirrored, column 1
  expect_rgb_near(texture_lookup(t, {1.75f, 0.75f}), kTexels[0], 1e-5f);
  expect_rgb_near(texture_lookup(t, {-0.25f, 0.75f}), kTexels[0], 1e-5f);
  expect_rgb_near(texture_lookup(t, {2.25f, 0.75f}), kTexels[0], 1e-5f);  // a whole period later: as at 0.25
  expect_rgb_near(texture_lookup(t, {0.25f, 1.25f}), kTexels[0], 1e-5f);   // v mirrored: 1.25 reads as 0.75, the top row
  expect_rgb_near(texture_lookup(t, {0.25f, -0.25f}), kTexels[2], 1e-5f);  // and -0.25 as 0.25, the bottom row
  expect_rgb_near(texture_lookup(t, {0.f, 0.75f}), kTexels[0], 1e-5f);     // the left edge meets itself
  t.wrap = TextureWrap::clamp;
  expect_rgb_near(texture_lookup(t, {5.f, 0.75f}), kTexels[1], 1e-5f);
  expect_rgb_near(texture_lookup(t, {-3.f, -3.f}), kTexels[2], 1e-5f);
  expect_rgb_near(texture_lookup(t, {0.f, 0.75f}), kTexels[0], 1e-5f);
  expect_rgb_near(texture_lookup(t, {1.f, 0.75f}), kTexels[1], 1e-5f);
  EXPECT_TRUE(all_finite(texture_lookup(t, {NAN, -INFINITY})));
  t.nearest = true;
  expect_rgb_near(texture_lookup(t, {0.49f, 0.51f}), kTexels[0]);
  expect_rgb_near(texture_lookup(t, {7.f, 0.51f}), kTexels[1]);
  t.wrap = TextureWrap::mirror;
  expect_rgb_near(texture_lookup(t, {1.1f, 0.51f}), kTexels[1]);
}

TEST(TextureLookup, UvScaleAndOffset) {
  TextureView t = two_by_two();
  t.uscale = 2.f;
  t.vscale = 4.f;
  expect_rgb_near(texture_lookup(t, {0.125f, 0.1875f}), kTexels[0]);  // (0.25, 0.75) after scaling
  t.uscale = t.vscale = 1.f;
  t.udelta = 0.5f;
  expect_rgb_near(texture_lookup(t, {0.25f, 0.75f}), kTexels[1]);
}

TEST(TextureFiles, PngIsSrgbDecodedUnlessLinear) {
  testing::TempDir dir("texture");
  // sRGB code 128 is linear 0.2158605; write it through the PNG encoder (linear -> sRGB 8 bit).
  Image img(2, 1);
  img.pixels[0] = Rgb(0.2158605f);
  img.pixels[1] = Rgb(1.f, 0.f, 0.f);
  const std::string path = dir.file("t.png");
  write_image(path, img);
  Scene scene;
  TextureFiles files;
  const uint32_t srgb = files.add(&scene, path, LdrEncoding::srgb);
  const uint32_t linear = files.add(&scene, path, LdrEncoding::linear);
  EXPECT_EQ(files.add(&scene, path, LdrEncoding::srgb), srgb);  // read once per encoding
  ASSERT_EQ(scene.textures.size(), 2u);
  EXPECT_NEAR(scene.textures[srgb].texel(0).g, 0.2158605f, 1e-6f);
  EXPECT_NEAR(scene.textures[linear].texel(0).g, 128.f / 255.f, 1e-6f);
  expect_rgb_near(scene.textures[srgb].texel(1), Rgb(1.f, 0.f, 0.f));
  EXPECT_THROW(files.add(&scene, dir.file("missing.png"), LdrEncoding::srgb), Error);
}

PerspectiveCamera test_camera() { return make_perspective_camera(Vec3(0, 0, 5), Vec3(0, 0, -1), Vec3(0, 1, 0), 40.f, 8, 8); }

TEST(SurfaceAttributes, TriangleUvAndShadingNormalAreInterpolated) {
  Scene s;
  const uint32_t m = s.add_material(make_diffuse(Rgb(0.5f)));
  s.add_triangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), m);
  s.uvs = {Point2{0.1f, 0.2f}, Point2{0.9f, 0.2f}, Point2{0.1f, 0.6f}};
  s.normals = {Vec3(0, 0, 1), normalize(Vec3(1, 0, 1)), normalize(Vec3(0, 1, 1))};
  s.add_texture(texture_of(1, 1, {Rgb(1.f)}));  // hits carry uvs in scenes with textures
  s.camera = test_camera();
  s.finalize();
  const Accel accel(s);
  SurfaceHit hit;
  ASSERT_TRUE(accel.intersect(Ray{Vec3(0.25f, 0.5f, 1.f), Vec3(0, 0, -1), 0.f, kInfinity}, &hit));
  // Barycentrics of (0.25, 0.5): b1 = 0.25, b2 = 0.5, b0 = 0.25.
  EXPECT_NEAR(hit.uv.x, 0.25f * 0.1f + 0.25f * 0.9f + 0.5f * 0.1f, 1e-5f);
  EXPECT_NEAR(hit.uv.y, 0.25f * 0.2f + 0.25f * 0.2f + 0.5f * 0.6f, 1e-5f);
  const Vec3 n = normalize(Vec3(0, 0, 1) * 0.25f + normalize(Vec3(1, 0, 1)) * 0.25f + normalize(Vec3(0, 1, 1)) * 0.5f);
  EXPECT_NEAR(hit.ns.x, n.x, 1e-5f);
  EXPECT_NEAR(hit.ns.y, n.y, 1e-5f);
  EXPECT_NEAR(hit.ns.z, n.z, 1e-5f);
  EXPECT_NEAR(hit.ng.z, 1.f, 1e-6f);
}

TEST(SurfaceAttributes, MeshesWithoutAttributesKeepFlatShadingAndDefaultUv) {
  Scene s;
  const uint32_t m = s.add_material(make_diffuse(Rgb(0.5f)));
  s.add_triangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), m);
  s.uvs = {Point2{0.5f, 0.5f}};  // only the first vertex: finalize pads the others with (0, 0)
  s.add_triangle(Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(2, 1, 0), m);
  s.add_texture(texture_of(1, 1, {Rgb(1.f)}));
  s.camera = test_camera();
  s.finalize();
  EXPECT_EQ(s.uvs.size(), s.positions.size());
  EXPECT_TRUE(s.normals.empty());
  const Accel accel(s);
  SurfaceHit hit;
  ASSERT_TRUE(accel.intersect(Ray{Vec3(2.25f, 0.5f, 1.f), Vec3(0, 0, -1), 0.f, kInfinity}, &hit));
  EXPECT_EQ(hit.ns.z, hit.ng.z);
  EXPECT_NEAR(hit.uv.x, 0.f, 1e-6f);
  ASSERT_TRUE(accel.intersect(Ray{Vec3(0.25f, 0.5f, 1.f), Vec3(0, 0, -1), 0.f, kInfinity}, &hit));
  EXPECT_NEAR(hit.uv.x, 0.25f * 0.5f, 1e-5f);
}

TEST(SurfaceAttributes, SphereUvIsSpherical) {
  Scene s;
  const uint32_t m = s.add_material(make_diffuse(Rgb(0.5f)));
  s.add_sphere(Vec3(1, 2, 3), 2.f, m);
  s.add_texture(texture_of(1, 1, {Rgb(1.f)}));  // hits carry uvs in scenes with textures
  s.camera = test_camera();
  s.finalize();
  const Accel accel(s);
  SurfaceHit hit;
  struct Case {
    Vec3 from, dir;
    float u, v;
  } cases[] = {
      {Vec3(1, 2, 10), Vec3(0, 0, -1), -1.f, 1.f},    // +z pole: v = 1 (u undefined)
      {Vec3(1, 2, -10), Vec3(0, 0, 1), -1.f, 0.f},    // -z pole: v = 0
      {Vec3(10, 2, 3), Vec3(-1, 0, 0), 0.f, 0.5f},    // +x on the equator
      {Vec3(1, 10, 3), Vec3(0, -1, 0), 0.25f, 0.5f},  // +y
      {Vec3(-10, 2, 3), Vec3(1, 0, 0), 0.5f, 0.5f},   // -x
      {Vec3(1, -10, 3), Vec3(0, 1, 0), 0.75f, 0.5f},  // -y
  };
  for (const Case& c : cases) {
    ASSERT_TRUE(accel.intersect(Ray{c.from, c.dir, 0.f, kInfinity}, &hit));
    if (c.u >= 0.f) {
      EXPECT_NEAR(hit.uv.x, c.u, 1e-4f);
    }
    EXPECT_NEAR(hit.uv.y, c.v, 1e-3f);
  }
}

TEST(ShadingMaterial, TexturesMultiplyTheReflectances) {
  Scene s;
  s.add_texture(texture_of(2, 2, {kTexels[0], kTexels[1], kTexels[2], kTexels[3]}));
  Material textured = make_phong(Rgb(0.5f), Rgb(0.25f), 10.f);
  textured.diffuse_texture = 0;
  const uint32_t mt = s.add_material(textured);
  const uint32_t mp = s.add_material(make_diffuse(Rgb(0.3f)));
  s.add_triangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), mt);
  s.camera = test_camera();
  s.finalize();
  const SceneView view = s.view();
  const Material a = shading_material(view, mt, Point2{0.75f, 0.75f});
  expect_rgb_near(a.diffuse, kTexels[1] * 0.5f);
  expect_rgb_near(a.glossy, Rgb(0.25f));
  const Material b = shading_material(view, mp, Point2{0.75f, 0.75f});
  expect_rgb_near(b.diffuse, Rgb(0.3f));
  // A copied scene's view points at the copy's texels.
  const Scene copy = s;
  EXPECT_EQ(copy.view().textures[0].texels, copy.textures[0].texels.data());
}

TEST(ShadingMaterial, FinalizeRejectsBadTextureIndices) {
  Scene s;
  Material m = make_diffuse(Rgb(0.5f));
  m.diffuse_texture = 0;
  s.add_material(m);
  s.camera = test_camera();
  EXPECT_THROW(s.finalize(), Error);
}

}  // namespace
}  // namespace pathspace
