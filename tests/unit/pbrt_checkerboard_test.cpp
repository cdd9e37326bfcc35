// pbrt-v4's 2D checkerboard texture: a diffuse reflectance bound to it is tex1 where
// floor(u uscale + udelta) + floor(v vscale + vdelta) is even and tex2 elsewhere, with hard edges
// (nearest-texel lookup of a 2x2 texture); unsupported forms fall back to the mean with a warning.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/io/pbrt/pbrt_scene_builder.h"
#include "pathspace/scene/texture.h"

namespace pathspace {
namespace {

Scene load_world(const std::string& world, std::vector<std::string>* warnings) {
  LoadWarnings lw(warnings);
  return pbrt::load_pbrt_string("LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" [ 40 ]\nWorldBegin\n" + world,
                                "test.pbrt", ".", {}, &lw, nullptr);
}

const std::string kQuad = "Shape \"trianglemesh\" \"point3 P\" [ 0 0 0  1 0 0  1 1 0  0 1 0 ] \"integer indices\" [ 0 1 2 0 2 3 ]\n";

TEST(PbrtCheckerboard, ChecksFollowPbrtsParity) {
  std::vector<std::string> w;
  const Scene s = load_world(
      "Texture \"checks\" \"spectrum\" \"checkerboard\" \"float uscale\" 4 \"float vscale\" 2 \"rgb tex1\" [ 0.8 0.1 0.1 ] "
      "\"rgb tex2\" [ 0.1 0.1 0.8 ]\nMaterial \"diffuse\" \"texture reflectance\" \"checks\"\n" + kQuad, &w);
  ASSERT_EQ(s.triangles.size(), 2u);
  const Material& m = s.materials[s.triangles[0].material];
  ASSERT_GE(m.diffuse_texture, 0);
  const TextureView t = s.textures[size_t(m.diffuse_texture)].view();
  const Rgb red(0.8f, 0.1f, 0.1f), blue(0.1f, 0.1f, 0.8f);
  // (u, v) -> (s, t) = (4u, 2v): parity of floor(s) + floor(t).
  EXPECT_EQ(texture_lookup(t, {0.1f, 0.2f}) * m.diffuse, red);    // (0.4, 0.4): 0 + 0
  EXPECT_EQ(texture_lookup(t, {0.3f, 0.2f}) * m.diffuse, blue);   // (1.2, 0.4): 1 + 0
  EXPECT_EQ(texture_lookup(t, {0.3f, 0.7f}) * m.diffuse, red);    // (1.2, 1.4): 1 + 1
  EXPECT_EQ(texture_lookup(t, {0.6f, 0.7f}) * m.diffuse, blue);   // (2.4, 1.4): 2 + 1
  EXPECT_EQ(texture_lookup(t, {0.74f, 0.2f}) * m.diffuse, red);   // hard edge: no blending near 0.75
  EXPECT_EQ(texture_lookup(t, {0.76f, 0.2f}) * m.diffuse, blue);
  EXPECT_TRUE(w.empty()) << ::testing::PrintToString(w);
}

TEST(PbrtCheckerboard, UnsupportedFormsUseTheMean) {
  std::vector<std::string> w;
  const Scene s = load_world("Texture \"c\" \"float\" \"checkerboard\" \"float tex1\" 1 \"float tex2\" 0\n"
                             "Material \"diffuse\" \"texture reflectance\" \"c\"\n" + kQuad, &w);
  EXPECT_EQ(s.materials[s.triangles[0].material].diffuse_texture, -1);
  EXPECT_EQ(s.materials[s.triangles[0].material].diffuse, Rgb(0.5f));
  ASSERT_FALSE(w.empty());
  EXPECT_NE(w[0].find("approximated by its mean"), std::string::npos) << w[0];
  EXPECT_THROW(load_world("Texture \"c\" \"spectrum\" \"checkerboard\" \"integer dimension\" 3\n", &w), Error);
}

TEST(PbrtMixTexture, ConstantsMixExactly) {
  std::vector<std::string> w;
  const Scene s = load_world("Texture \"a\" \"spectrum\" \"constant\" \"rgb value\" [ 1 0 0 ]\n"
                             "Texture \"m\" \"spectrum\" \"mix\" \"texture tex1\" \"a\" \"rgb tex2\" [ 0 0 1 ] \"float amount\" 0.25\n"
                             "Material \"diffuse\" \"texture reflectance\" \"m\"\n" + kQuad, &w);
  EXPECT_EQ(s.materials[s.triangles[0].material].diffuse, Rgb(0.75f, 0.f, 0.25f));
  EXPECT_TRUE(w.empty()) << ::testing::PrintToString(w);
}

}  // namespace
}  // namespace pathspace
