// Mitsuba bitmap textures bound as image textures (io/mitsuba/mitsuba_textures.h) and the uvs of
// Mitsuba's shapes: which texel a hit sees must be the one Mitsuba shows (v = 0 is an image's top
// row in Mitsuba, its bottom row in pathspace; to_uv scale and offset; raw; OBJ flip_tex_coords).
#include <gtest/gtest.h>

#include <fstream>

#include "pathspace/io/image_io.h"
#include "pathspace/io/mitsuba/mitsuba_loader.h"
#include "pathspace/scene/texture.h"
#include "support/mitsuba_text.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

using pathspace::testing::TempDir;

using Loaded = testing::LoadedMitsuba;

Loaded load(const std::string& body, const std::string& folder) {
  return testing::load_mitsuba_text(
      "<scene version=\"3.0.0\"><sensor type=\"perspective\"/>\n" + body + "\n<emitter type=\"constant\"/>\n</scene>\n", folder);
}

bool has_warning(const Loaded& r, const std::string& text) {
  for (const std::string& w : r.warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

// 2x2 texels, each distinct: (0, 0) top left.
Image four_texels() {
  Image img(2, 2);
  img.at(0, 0) = Rgb(1, 0, 0);
  img.at(1, 0) = Rgb(0, 1, 0);
  img.at(0, 1) = Rgb(0, 0, 1);
  img.at(1, 1) = Rgb(1, 1, 0);
  return img;
}

std::string bitmap(const std::string& file, const std::string& extra = "") {
  return "<texture type=\"bitmap\" name=\"reflectance\"><string name=\"filename\" value=\"" + file + "\"/>" + extra + "</texture>";
}

std::string textured_rectangle(const std::string& extra = "") {
  return "<shape type=\"rectangle\"><bsdf type=\"diffuse\">" + bitmap("tex.exr", extra) + "</bsdf></shape>";
}

// The texture value at the rectangle's local point (x, y): the uv interpolated along the diagonal
// from vertex 0 (local (-1, -1)) to vertex 2 (local (1, 1)), where x = y.
Rgb rectangle_lookup(const Scene& s, float t) {
  const Material& m = s.materials[s.triangles[0].material];
  const Point2 a = s.uvs[s.triangles[0].v[0]], c = s.uvs[s.triangles[0].v[2]];
  const Point2 uv{a.x + (c.x - a.x) * t, a.y + (c.y - a.y) * t};
  return texture_lookup(s.textures[size_t(m.diffuse_texture)].view(), uv);
}

TEST(MitsubaTextures, DiffuseBitmapIsBoundWithMitsubasOrientation) {
  TempDir dir("mitsuba-tex");
  write_image(dir.file("tex.exr"), four_texels());
  const Loaded r = load(textured_rectangle(), dir.path.string());
  EXPECT_TRUE(r.warnings.empty()) << ::testing::PrintToString(r.warnings);
  ASSERT_EQ(r.scene.textures.size(), 1u);
  const Material& m = r.scene.materials[r.scene.triangles[0].material];
  EXPECT_EQ(m.diffuse, Rgb(1.f));
  ASSERT_EQ(m.diffuse_texture, 0);
  // Mitsuba's rectangle: uv = ((x + 1) / 2, (y + 1) / 2), v = 0 the image's top row. Local (-0.5, -0.5)
  // is Mitsuba uv (0.25, 0.25): the top-left texel; local (0.5, 0.5) the bottom-right one.
  EXPECT_EQ(rectangle_lookup(r.scene, 0.25f), Rgb(1, 0, 0));
  EXPECT_EQ(rectangle_lookup(r.scene, 0.75f), Rgb(1, 1, 0));
}

TEST(MitsubaTextures, ToUvScaleAndOffset) {
  TempDir dir("mitsuba-tex");
  write_image(dir.file("tex.exr"), four_texels());
  // uv' = 2 uv + (0.25, 0.75): local (-0.5, -0.5) -> (0.75, 1.25) = texel (1, 0) (top right, v wrapped).
  const Loaded r = load(textured_rectangle("<transform name=\"to_uv\"><scale x=\"2\" y=\"2\"/><translate x=\"0.25\" y=\"0.75\"/></transform>"),
                        dir.path.string());
  EXPECT_TRUE(r.warnings.empty()) << ::testing::PrintToString(r.warnings);
  const TextureView t = r.scene.textures[0].view();
  EXPECT_EQ(t.uscale, 2.f);
  EXPECT_EQ(t.udelta, 0.25f);
  EXPECT_EQ(rectangle_lookup(r.scene, 0.25f), Rgb(0, 1, 0));
  // local (0, 0) -> (1.25, 1.75) = texel (0, 1) (bottom left).
  EXPECT_EQ(rectangle_lookup(r.scene, 0.5f), Rgb(0, 0, 1));
}

TEST(MitsubaTextures, RawFilterWrapAndSharing) {
  TempDir dir("mitsuba-tex");
  Image grey(1, 1);
  grey.at(0, 0) = Rgb(0.5f);  // PNG stores sRGB(0.5) = 188
  write_image(dir.file("grey.png"), grey);
  const Loaded r = load(
      "<texture type=\"bitmap\" id=\"shared\"><string name=\"filename\" value=\"grey.png\"/></texture>\n"
      "<shape type=\"rectangle\"><bsdf type=\"diffuse\"><ref name=\"reflectance\" id=\"shared\"/></bsdf></shape>\n"
      "<shape type=\"cube\"><bsdf type=\"diffuse\"><ref name=\"reflectance\" id=\"shared\"/></bsdf></shape>\n"
      "<shape type=\"disk\"><bsdf type=\"diffuse\">" +
          bitmap("grey.png", "<boolean name=\"raw\" value=\"true\"/><string name=\"wrap_mode\" value=\"mirror\"/>"
                             "<string name=\"filter_type\" value=\"nearest\"/>") +
          "</bsdf></shape>\n"
          "<shape type=\"rectangle\"><bsdf type=\"plastic\">" +
          std::string("<texture type=\"bitmap\" name=\"diffuse_reflectance\"><string name=\"filename\" value=\"grey.png\"/></texture>") +
          "</bsdf></shape>",
      dir.path.string());
  ASSERT_EQ(r.scene.textures.size(), 2u);  // sRGB (shared by three materials) and raw
  EXPECT_NEAR(r.scene.textures[0].texel(0).r, 0.5f, 3e-3f);
  EXPECT_NEAR(r.scene.textures[1].texel(0).r, 188.f / 255.f, 1e-6f);
  EXPECT_EQ(r.scene.textures[1].wrap, TextureWrap::mirror);  // wrap and filter are the texture's own
  EXPECT_TRUE(r.scene.textures[1].nearest);
  EXPECT_EQ(r.scene.textures[0].wrap, TextureWrap::repeat);
  EXPECT_FALSE(r.scene.textures[0].nearest);
  EXPECT_FALSE(has_warning(r, "wrap_mode")) << ::testing::PrintToString(r.warnings);
  // plastic: a coat over the textured base (the linear model's albedo remap needs a constant albedo).
  const Material& plastic = r.scene.materials[r.scene.triangles.back().material];
  EXPECT_EQ(plastic.type, MaterialType::coated_diffuse);
  EXPECT_EQ(plastic.diffuse_texture, 0);
  EXPECT_FLOAT_EQ(plastic.diffuse.r, 1.f);
  EXPECT_TRUE(has_warning(r, "approximated by the nonlinear one"));
}

TEST(MitsubaTextures, UnboundTexturesStayMeanColours) {
  TempDir dir("mitsuba-tex");
  write_image(dir.file("tex.exr"), four_texels());
  const Loaded r = load("<shape type=\"rectangle\"><bsdf type=\"dielectric\"><texture type=\"bitmap\" name=\"specular_transmittance\">"
                        "<string name=\"filename\" value=\"tex.exr\"/></texture></bsdf></shape>",
                        dir.path.string());
  EXPECT_TRUE(r.scene.textures.empty());
  EXPECT_TRUE(has_warning(r, "approximated by its mean colour")) << ::testing::PrintToString(r.warnings);
}

TEST(MitsubaTextures, ShapeUvs) {
  TempDir dir("mitsuba-tex");
  {
    std::ofstream obj(dir.file("quad.obj"));
    obj << "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 0.25\nf 1/1 2/2 3/3\n";
  }
  const Loaded r = load("<shape type=\"cube\"/>\n<shape type=\"disk\"/>\n<shape type=\"obj\"><string name=\"filename\" value=\"quad.obj\"/></shape>\n"
                        "<shape type=\"obj\"><string name=\"filename\" value=\"quad.obj\"/><boolean name=\"flip_tex_coords\" value=\"false\"/></shape>",
                        dir.path.string());
  EXPECT_TRUE(r.warnings.empty()) << ::testing::PrintToString(r.warnings);
  const Scene& s = r.scene;
  ASSERT_EQ(s.uvs.size(), s.positions.size());
  // Cube: 6 faces x 4 corners; the -y face's first corner (1, -1, -1) has Mitsuba uv (0, 1).
  EXPECT_EQ(s.positions[0], Vec3(1, -1, -1));
  EXPECT_EQ(s.uvs[0].x, 0.f);
  EXPECT_EQ(s.uvs[0].y, 0.f);
  EXPECT_EQ(s.uvs[1].x, 1.f);  // (1, -1, 1): Mitsuba (1, 1)
  // Disk: the first fan triangle's rim vertex at angle 0 has Mitsuba uv (1, 0).
  EXPECT_EQ(s.uvs[24 + 1].x, 1.f);
  EXPECT_EQ(s.uvs[24 + 1].y, 1.f);
  // OBJ: Mitsuba flips v on reading and on lookup, so the file's uvs stay; flip_tex_coords=false flips.
  // (Each OBJ: its 3 positions, then 3 corner vertices that carry the uvs.)
  const size_t obj = s.positions.size() - 12;
  EXPECT_EQ(s.uvs[obj + 5].y, 0.25f);
  EXPECT_EQ(s.uvs[obj + 6 + 5].y, 0.75f);
}

}  // namespace
}  // namespace pathspace
