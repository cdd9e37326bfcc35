// Image textures from scene files: OBJ/MTL map_Kd (with vt coordinates, -s scale and
// "-colorspace linear"), and a missing map that leaves the constant colour with a warning; pbrt-v4
// imagemap (uscale/vscale, encoding) bound to diffuse reflectance directly and through "scale",
// trianglemesh uv and smooth N as vertex attributes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "pathspace/io/image_io.h"
#include "pathspace/io/pbrt/pbrt_scene_builder.h"
#include "pathspace/io/scene_loader.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

using pathspace::testing::TempDir;

void write_texture(const std::string& path) {
  Image img(2, 2);
  img.pixels = {Rgb(1.f, 0.f, 0.f), Rgb(0.f, 1.f, 0.f), Rgb(0.f, 0.f, 1.f), Rgb(1.f, 1.f, 1.f)};
  write_image(path, img);
}

TEST(ObjTextures, MapKdBindsTheImageWithVertexUvs) {
  const TempDir dir("objtex");
  write_texture(dir.file("checker.png"));
  std::ofstream(dir.file("quad.mtl")) << "newmtl tex\nKd 0 0 0\nmap_Kd -s 2 3 1 checker.png\n"
                                          "newmtl lin\nKd 0.5 0.5 0.5\nmap_Kd -colorspace linear checker.png\n"
                                          "newmtl gone\nKd 0.25 0.5 0.75\nmap_Kd nothere.png\n";
  std::ofstream(dir.file("quad.obj")) << "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                          "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                          "usemtl tex\nf 1/1 2/2 3/3\nusemtl lin\nf 1/4 3/2 4/1\nusemtl gone\nf 1 2 4\n";
  std::vector<std::string> w;
  const Scene s = load_scene(dir.file("quad.obj"), {}, &w);
  ASSERT_EQ(s.triangles.size(), 3u);
  const Material& tex = s.materials[s.triangles[0].material];
  const Material& lin = s.materials[s.triangles[1].material];
  const Material& gone = s.materials[s.triangles[2].material];
  ASSERT_GE(tex.diffuse_texture, 0);
  ASSERT_GE(lin.diffuse_texture, 0);
  EXPECT_NE(tex.diffuse_texture, lin.diffuse_texture);  // different encodings and uv transforms
  EXPECT_EQ(tex.diffuse, Rgb(1.f));                      // Kd 0 next to a map counts as white
  EXPECT_EQ(lin.diffuse, Rgb(0.5f));                     // MTL: Kd multiplies map_Kd
  const ImageTexture& t = s.textures[size_t(tex.diffuse_texture)];
  EXPECT_EQ(t.width, 2);
  EXPECT_EQ(t.uscale, 2.f);
  EXPECT_EQ(t.vscale, 3.f);
  EXPECT_NEAR(t.texel(3).r, 1.f, 1e-6f);
  // The PNG stores sRGB 8 bit: a linear read of a (linear 1, 0, 0) texel is still (1, 0, 0).
  EXPECT_NEAR(s.textures[size_t(lin.diffuse_texture)].texel(0).r, 1.f, 1e-6f);
  // Corners with vt became vertices with uvs; the untextured triangle keeps its material colour.
  ASSERT_EQ(s.uvs.size(), s.positions.size());
  const uint32_t* v = s.triangles[1].v;
  EXPECT_EQ(s.uvs[v[0]].x, 0.f);
  EXPECT_EQ(s.uvs[v[0]].y, 1.f);
  EXPECT_EQ(s.uvs[v[1]].x, 1.f);
  EXPECT_EQ(gone.diffuse_texture, -1);
  EXPECT_EQ(gone.diffuse, Rgb(0.25f, 0.5f, 0.75f));
  bool warned = false;
  for (const std::string& m : w) warned |= m.find("nothere.png") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(PbrtTextures, ImagemapBindsToReflectanceWithUvAndNormals) {
  const TempDir dir("pbrttex");
  write_texture(dir.file("checker.png"));
  const std::string text =
      "Camera \"perspective\"\nWorldBegin\n"
      "Texture \"img\" \"spectrum\" \"imagemap\" \"string filename\" \"checker.png\" \"float uscale\" 4 \"float vscale\" 2\n"
      "  \"string encoding\" \"linear\" \"string filter\" \"bilinear\"\n"
      "Texture \"half\" \"spectrum\" \"scale\" \"texture tex\" \"img\" \"float scale\" 0.5\n"
      "Texture \"rough\" \"float\" \"imagemap\" \"string filename\" \"checker.png\"\n"
      "Material \"diffuse\" \"texture reflectance\" \"img\"\n"
      "Shape \"trianglemesh\" \"point3 P\" [ 0 0 0  1 0 0  0 1 0 ] \"integer indices\" [ 0 1 2 ]\n"
      "  \"point2 uv\" [ 0 0  1 0  0 1 ] \"normal N\" [ 0 0 1  0.6 0 0.8  0 0.6 0.8 ]\n"
      "Material \"diffuse\" \"texture reflectance\" \"half\"\n"
      "Shape \"trianglemesh\" \"point3 P\" [ 0 0 1  1 0 1  0 1 1 ] \"integer indices\" [ 0 1 2 ]\n";
  std::vector<std::string> warnings;
  LoadWarnings w(&warnings);
  const Scene s = pbrt::load_pbrt_string(text, "tex.pbrt", dir.path.string(), {}, &w, nullptr);
  ASSERT_EQ(s.triangles.size(), 2u);
  const Material& a = s.materials[s.triangles[0].material];
  const Material& b = s.materials[s.triangles[1].material];
  ASSERT_GE(a.diffuse_texture, 0);
  EXPECT_EQ(b.diffuse_texture, a.diffuse_texture);  // the scale texture shares the image
  EXPECT_EQ(a.diffuse, Rgb(1.f));
  EXPECT_EQ(b.diffuse, Rgb(0.5f));
  ASSERT_EQ(s.textures.size(), 1u);  // the float imagemap is a constant (its mean)
  const ImageTexture& t = s.textures[0];
  EXPECT_EQ(t.uscale, 4.f);
  EXPECT_EQ(t.vscale, 2.f);
  // uv and N of the first mesh are vertex attributes; the second (flat) mesh has none.
  ASSERT_EQ(s.uvs.size(), s.positions.size());
  ASSERT_EQ(s.normals.size(), s.positions.size());
  EXPECT_EQ(s.uvs[s.triangles[0].v[0]].x, 0.f);
  EXPECT_NEAR(s.normals[1].x, 0.6f, 1e-6f);
  EXPECT_EQ(s.normals[3], Vec3());
  for (const std::string& m : warnings) EXPECT_EQ(m.find("approximated by its mean colour (no scene"), std::string::npos) << m;
}

}  // namespace
}  // namespace pathspace
