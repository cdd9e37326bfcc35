// Cutout opacity from files (scene/surface_opacity.h): images read as scalars (io/image_io.h,
// ImageContent::scalar: the alpha channel where it is not all one, else the mean of the colour),
// Mitsuba's `mask` (a float or a bitmap, nested in twosided or around it) and pbrt-v4's shape
// "alpha" (a float, or a float imagemap texture), with errors for opacities outside [0, 1].
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/io/image_io.h"
#include "pathspace/io/mitsuba/mitsuba_loader.h"
#include "pathspace/io/pbrt/pbrt_scene_builder.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

using testing::TempDir;

// An uncompressed 32-bit TGA (stb reads it): 2x1 pixels, colour (c, c, c) and the given alphas.
void write_rgba_tga(const std::string& path, unsigned char c, unsigned char alpha0, unsigned char alpha1) {
  const unsigned char header[18] = {0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 1, 0, 32, 0x28};
  const unsigned char pixels[8] = {c, c, c, alpha0, c, c, c, alpha1};  // BGRA, top row first
  std::ofstream f(path, std::ios::binary);
  f.write(reinterpret_cast<const char*>(header), sizeof header);
  f.write(reinterpret_cast<const char*>(pixels), sizeof pixels);
}

TEST(CutoutLoading, ScalarImagesTakeAlphaElseTheMeanColour) {
  const TempDir dir("cutout");
  write_rgba_tga(dir.file("alpha.tga"), 255, 0, 51);
  const Image a = read_image(dir.file("alpha.tga"), LdrEncoding::srgb, ImageContent::scalar);
  ASSERT_EQ(a.width, 2);
  EXPECT_EQ(a.at(0, 0), Rgb(0.f));
  EXPECT_NEAR(a.at(1, 0).r, 0.2f, 1e-6f);  // alpha is linear: 51 / 255
  EXPECT_EQ(a.at(1, 0).g, a.at(1, 0).r);
  // Alpha 1 everywhere says nothing: the colour's mean (sRGB-decoded) is the value, as pbrt-v4 does.
  write_rgba_tga(dir.file("opaque.tga"), 128, 255, 255);
  const Image o = read_image(dir.file("opaque.tga"), LdrEncoding::srgb, ImageContent::scalar);
  const Image colour = read_image(dir.file("opaque.tga"));
  EXPECT_NEAR(o.at(0, 0).r, colour.at(0, 0).r, 1e-6f);
  EXPECT_NEAR(o.at(0, 0).r, 0.2158605f, 1e-5f);
  // No alpha channel: the mean of the colour channels.
  Image rgb(1, 1);
  rgb.at(0, 0) = Rgb(0.1f, 0.2f, 0.6f);
  write_image(dir.file("rgb.exr"), rgb);
  EXPECT_NEAR(read_image(dir.file("rgb.exr"), LdrEncoding::srgb, ImageContent::scalar).at(0, 0).g, 0.3f, 1e-6f);
}

Scene load_mitsuba(const std::string& body, const std::string& folder, std::vector<std::string>* warnings = nullptr) {
  std::vector<std::string> w;
  LoadWarnings lw(warnings ? warnings : &w);
  const std::string text = "<scene version=\"3.0.0\"><sensor type=\"perspective\"/>\n" + body + "\n<emitter type=\"constant\"/>\n</scene>\n";
  return mitsuba::load_mitsuba_string(text, "scene.xml", folder, {}, &lw, nullptr);
}

TEST(CutoutLoading, MitsubaMaskSetsOpacity) {
  const TempDir dir("cutout");
  const auto material = [](const Scene& s) { return s.materials[s.triangles[0].material]; };
  const Material m = material(load_mitsuba(
      "<shape type=\"rectangle\"><bsdf type=\"mask\"><float name=\"opacity\" value=\"0.3\"/><bsdf type=\"diffuse\"/></bsdf></shape>",
      dir.path.string()));
  EXPECT_FLOAT_EQ(m.opacity, 0.3f);
  EXPECT_EQ(m.opacity_texture, -1);
  EXPECT_TRUE(is_black(m.specular));
  // Mitsuba's default opacity is 0.5; twosided keeps the mask and the mask keeps twosided.
  const Material d = material(load_mitsuba(
      "<shape type=\"rectangle\"><bsdf type=\"twosided\"><bsdf type=\"mask\"><bsdf type=\"diffuse\"/></bsdf></bsdf></shape>",
      dir.path.string()));
  EXPECT_FLOAT_EQ(d.opacity, 0.5f);
  EXPECT_TRUE(d.two_sided);
  // A bitmap is read as a scalar texture (here its alpha).
  write_rgba_tga(dir.file("leaf.tga"), 200, 0, 255);
  const Scene t = load_mitsuba(
      "<shape type=\"rectangle\"><bsdf type=\"mask\"><texture type=\"bitmap\" name=\"opacity\"><string name=\"filename\" "
      "value=\"leaf.tga\"/></texture><bsdf type=\"diffuse\"/></bsdf></shape>",
      dir.path.string());
  const Material tm = material(t);
  ASSERT_GE(tm.opacity_texture, 0);
  EXPECT_FLOAT_EQ(tm.opacity, 1.f);
  EXPECT_EQ(t.textures[size_t(tm.opacity_texture)].texel(0), Rgb(0.f));
  EXPECT_EQ(t.textures[size_t(tm.opacity_texture)].texel(1), Rgb(1.f));
  EXPECT_TRUE(t.view().has_cutouts);
  EXPECT_THROW(load_mitsuba("<shape type=\"rectangle\"><bsdf type=\"mask\"><float name=\"opacity\" value=\"1.5\"/>"
                            "<bsdf type=\"diffuse\"/></bsdf></shape>",
                            dir.path.string()),
               Error);
}

Scene load_pbrt(const std::string& world, const std::string& folder, std::vector<std::string>* warnings = nullptr) {
  std::vector<std::string> w;
  LoadWarnings lw(warnings ? warnings : &w);
  return pbrt::load_pbrt_string("LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" [ 40 ]\nWorldBegin\n"
                                "LightSource \"infinite\"\n" + world,
                                "test.pbrt", folder, {}, &lw, nullptr);
}

const std::string kTriangle = "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2] "
                              "\"point2 uv\" [0 0 1 0 0 1] ";

TEST(CutoutLoading, PbrtShapeAlphaSetsOpacityOnACopyOfTheMaterial) {
  const TempDir dir("cutout");
  std::vector<std::string> warnings;
  const Scene s = load_pbrt("Material \"diffuse\"\n" + kTriangle + "\"float alpha\" 0.25\n" + kTriangle + "\n" + kTriangle +
                                "\"float alpha\" 0.25\n",
                            dir.path.string(), &warnings);
  ASSERT_EQ(s.triangles.size(), 3u);
  EXPECT_FLOAT_EQ(s.materials[s.triangles[0].material].opacity, 0.25f);
  EXPECT_FLOAT_EQ(s.materials[s.triangles[1].material].opacity, 1.f);  // the material itself is unchanged
  EXPECT_EQ(s.triangles[2].material, s.triangles[0].material);         // one copy per material and alpha
  for (const std::string& w : warnings) EXPECT_EQ(w.find("alpha"), std::string::npos) << w;

  write_rgba_tga(dir.file("mask.tga"), 90, 255, 0);
  const Scene t = load_pbrt("Texture \"leaf\" \"float\" \"imagemap\" \"string filename\" \"mask.tga\"\nMaterial \"diffuse\"\n" +
                                kTriangle + "\"texture alpha\" \"leaf\"\n",
                            dir.path.string());
  const Material& m = t.materials[t.triangles[0].material];
  ASSERT_GE(m.opacity_texture, 0);
  EXPECT_EQ(t.textures[size_t(m.opacity_texture)].texel(0), Rgb(1.f));
  EXPECT_EQ(t.textures[size_t(m.opacity_texture)].texel(1), Rgb(0.f));
  try {
    load_pbrt(kTriangle + "\"float alpha\" 2\n", dir.path.string());
    ADD_FAILURE() << "alpha 2 was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("test.pbrt:5:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("alpha"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pathspace
