// Mitsuba participating media (io/mitsuba/mitsuba_media.h, mitsuba_volume_file.h): homogeneous and
// heterogeneous media in Mitsuba 0.6's and 3's parameters, phase functions, .vol grids written here
// and read back, the media of shapes (interior, exterior), the sensor and emitters, the null BSDF,
// and bad media or volume files as errors at their file:line:column.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include "pathspace/base/error.h"
#include "pathspace/io/mitsuba/mitsuba_loader.h"
#include "pathspace/io/mitsuba/mitsuba_volume_file.h"
#include "pathspace/media/grid_lookup.h"
#include "support/load_errors.h"
#include "support/mitsuba_text.h"
#include "support/temp_dir.h"
#include "support/near_expectations.h"

namespace pathspace {
namespace {

using pathspace::testing::TempDir;

using Loaded = testing::LoadedMitsuba;

Loaded load(const std::string& text, const std::string& folder = ".") { return testing::load_mitsuba_text(text, folder); }

const char* kLight =
    "\n<shape type=\"rectangle\"><bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"0\"/></bsdf>"
    "<emitter type=\"area\"><rgb name=\"radiance\" value=\"1\"/></emitter></shape>\n</scene>\n";

// A Mitsuba 3 (or 0.6) scene around `body`, which starts on line 2, with one area light at the end.
std::string scene3(const std::string& body) { return "<scene version=\"3.0.0\">\n" + body + kLight; }
std::string scene06(const std::string& body) { return "<scene version=\"0.6.0\">\n" + body + kLight; }

void expect_error(const std::string& text, const std::string& where, const std::string& what, const std::string& folder = ".") {
  testing::expect_load_error([&] { load(text, folder); }, where, what, text);
}

std::string find_warning(const std::vector<std::string>& warnings, const std::string& text) {
  for (const std::string& w : warnings)
    if (w.find(text) != std::string::npos) return w;
  return {};
}

using testing::expect_rgb_near;
using testing::expect_vec_near;

// A Mitsuba .vol file's bytes (little-endian, whatever the host).
void put32(std::string* b, uint32_t v) {
  for (int i = 0; i < 4; ++i) b->push_back(char((v >> (8 * i)) & 0xff));
}
void put_float(std::string* b, float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  put32(b, u);
}
std::string vol_bytes(int32_t nx, int32_t ny, int32_t nz, int32_t channels, const std::vector<float>& bbox, const std::vector<float>& values,
                      int32_t encoding = 1) {
  std::string b = "VOL";
  b.push_back(char(3));
  for (int32_t v : {encoding, nx, ny, nz, channels}) put32(&b, uint32_t(v));
  for (float f : bbox) put_float(&b, f);
  for (float f : values) put_float(&b, f);
  return b;
}
void write(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

const std::vector<float> kBox = {-1, 0, 0, 1, 1, 1};

TEST(MitsubaMedia, HomogeneousMitsuba3) {
  const Loaded r = load(scene3(
      "<medium type=\"homogeneous\" id=\"fog\">\n"
      "  <rgb name=\"sigma_t\" value=\"1, 2, 4\"/>\n"
      "  <float name=\"albedo\" value=\"0.5\"/>\n"
      "  <float name=\"scale\" value=\"2\"/>\n"
      "  <phase type=\"hg\"><float name=\"g\" value=\"0.4\"/></phase>\n"
      "</medium>\n"
      "<medium type=\"homogeneous\" id=\"plain\"/>\n"
      "<medium type=\"homogeneous\" id=\"hg\"><phase type=\"hg\"/></medium>\n"
      "<medium type=\"homogeneous\" id=\"ray\"><phase type=\"rayleigh\"/></medium>"));
  const std::vector<Medium>& m = r.scene.media.media;
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m[0].type, MediumType::homogeneous);
  expect_rgb_near(m[0].sigma_t, Rgb(2.f, 4.f, 8.f));
  expect_rgb_near(m[0].albedo, Rgb(0.5f));
  EXPECT_FLOAT_EQ(m[0].g, 0.4f);
  expect_rgb_near(m[1].sigma_t, Rgb(1.f));  // Mitsuba 3's defaults: sigma_t 1, albedo 0.75, isotropic
  expect_rgb_near(m[1].albedo, Rgb(0.75f));
  EXPECT_EQ(m[1].g, 0.f);
  EXPECT_FLOAT_EQ(m[2].g, 0.8f);  // hg's default g
  EXPECT_EQ(m[3].g, 0.f);
  EXPECT_NE(find_warning(r.warnings, "scene.xml:10:37: warning: phase function 'rayleigh' is not supported; isotropic used"), "")
      << ::testing::PrintToString(r.warnings);
}

TEST(MitsubaMedia, HomogeneousMitsuba06) {
  const Loaded r = load(scene06(
      "<medium type=\"homogeneous\" id=\"a\"><rgb name=\"sigmaA\" value=\"0.1 0.2 0.3\"/><rgb name=\"sigmaS\" value=\"0.3\"/>"
      "<float name=\"scale\" value=\"10\"/></medium>\n"
      "<medium type=\"homogeneous\" id=\"t\"><rgb name=\"sigmaT\" value=\"2\"/><spectrum name=\"albedo\" value=\"0.25\"/></medium>"));
  const std::vector<Medium>& m = r.scene.media.media;
  ASSERT_EQ(m.size(), 2u);
  expect_rgb_near(m[0].sigma_t, Rgb(4.f, 5.f, 6.f));
  expect_rgb_near(m[0].albedo, Rgb(0.75f, 0.6f, 0.5f));
  expect_rgb_near(m[1].sigma_t, Rgb(2.f));
  expect_rgb_near(m[1].albedo, Rgb(0.25f));
  EXPECT_EQ(find_warning(r.warnings, "not supported"), "") << ::testing::PrintToString(r.warnings);
  expect_error(scene06("<medium type=\"homogeneous\" id=\"k\">\n  <string name=\"material\" value=\"ketchup\"/></medium>"), "scene.xml:3:3:",
               "material presets are not supported");
  expect_error(scene06("<medium type=\"homogeneous\" id=\"k\"/>"), "scene.xml:2:1:", "'skin1' preset");
  expect_error(scene06("<medium type=\"homogeneous\" id=\"k\"><rgb name=\"sigmaA\" value=\"1\"/></medium>"), "scene.xml:2:1:",
               "are both needed");
  expect_error(scene06("<medium type=\"homogeneous\" id=\"k\"><rgb name=\"sigmaA\" value=\"1\"/><rgb name=\"sigmaT\" value=\"1\"/></medium>"),
               "scene.xml:2:1:", "not both pairs");
}

TEST(MitsubaMedia, ShapesSensorAndEmittersBindMedia) {
  const Loaded r = load(scene3(
      "<medium type=\"homogeneous\" id=\"fog\"/>\n"
      "<bsdf type=\"diffuse\" id=\"white\"/>\n"
      "<shape type=\"sphere\"><bsdf type=\"null\"/><ref name=\"interior\" id=\"fog\"/></shape>\n"
      "<shape type=\"cube\"><bsdf type=\"dielectric\"/><medium type=\"homogeneous\" name=\"interior\">"
      "<rgb name=\"sigma_t\" value=\"0.5 1 2\"/><float name=\"albedo\" value=\"0\"/></medium></shape>\n"
      "<shape type=\"rectangle\"><ref id=\"white\"/><ref id=\"fog\" name=\"exterior\"/><emitter type=\"area\"/></shape>\n"
      "<shape type=\"sphere\"><ref name=\"interior\" id=\"fog\"/><ref name=\"exterior\" id=\"fog\"/></shape>\n"
      "<sensor type=\"perspective\"><ref id=\"fog\"/></sensor>\n"
      "<emitter type=\"point\"><ref id=\"fog\"/></emitter>\n"
      "<emitter type=\"spot\"><medium type=\"homogeneous\"><float name=\"sigma_t\" value=\"3\"/></medium></emitter>"));
  const Scene& s = r.scene;
  const SceneMedia& m = s.media;
  ASSERT_EQ(m.media.size(), 3u);  // fog, the cube's glass, the spot's
  expect_rgb_near(m.media[1].sigma_t, Rgb(0.5f, 1.f, 2.f));
  expect_rgb_near(m.media[1].albedo, Rgb(0.f));
  expect_rgb_near(m.media[2].sigma_t, Rgb(3.f));
  ASSERT_EQ(s.spheres.size(), 2u);
  ASSERT_EQ(m.sphere_interfaces.size(), 2u);
  EXPECT_EQ(m.sphere_interfaces[0].inside, 0);
  EXPECT_EQ(m.sphere_interfaces[0].outside, kVacuum);
  EXPECT_TRUE(m.sphere_interfaces[0].transition);
  EXPECT_FALSE(m.sphere_interfaces[1].transition);  // fog on both sides: no boundary
  EXPECT_EQ(s.materials[s.spheres[0].material].type, MaterialType::interface);
  // The cube (12 triangles): coloured glass, the dielectric around its interior medium.
  ASSERT_EQ(s.triangles.size(), 16u);
  ASSERT_EQ(m.triangle_interfaces.size(), 16u);
  for (int t = 0; t < 12; ++t) {
    EXPECT_EQ(m.triangle_interfaces[t].inside, 1);
    EXPECT_EQ(m.triangle_interfaces[t].outside, kVacuum);
    EXPECT_TRUE(m.triangle_interfaces[t].transition);
  }
  EXPECT_GT(s.materials[s.triangles[0].material].ior, 1.f);
  for (int t : {12, 13}) {
    EXPECT_EQ(m.triangle_interfaces[t].inside, kVacuum);
    EXPECT_EQ(m.triangle_interfaces[t].outside, 0);
  }
  for (int t : {14, 15}) EXPECT_FALSE(m.triangle_interfaces[t].transition);
  EXPECT_EQ(s.materials[s.triangles[12].material].diffuse, Rgb(0.5f));  // the <ref id="white"/> BSDF
  // Lights: the rectangle's two area lights and the point light in fog, the spot in its own medium.
  ASSERT_EQ(s.lights.size(), 6u);
  ASSERT_EQ(m.light_media.size(), 6u);
  const int32_t expected[6] = {0, 0, 0, 2, kVacuum, kVacuum};
  for (int l = 0; l < 6; ++l) EXPECT_EQ(m.light_media[l], expected[l]) << "light " << l;
  EXPECT_EQ(m.camera_medium, 0);
  EXPECT_EQ(find_warning(r.warnings, "is not supported; ignored"), "") << ::testing::PrintToString(r.warnings);
}

TEST(MitsubaMedia, HeterogeneousGridsReadFromVolFiles) {
  TempDir dir("mitsuba-media");
  write(dir.file("density.vol"), vol_bytes(2, 1, 1, 1, kBox, {1.f, 3.f}));
  write(dir.file("albedo.vol"), vol_bytes(1, 1, 1, 3, kBox, {0.2f, 0.4f, 0.6f}));
  write(dir.file("grey.vol"), vol_bytes(1, 1, 1, 1, kBox, {0.5f}));
  const std::string to_world = "<transform name=\"to_world\"><translate x=\"10\"/></transform>";
  const Loaded r = load(scene3(
                            "<medium type=\"heterogeneous\" id=\"smoke\">\n"
                            "  <volume name=\"sigma_t\" type=\"gridvolume\"><string name=\"filename\" value=\"density.vol\"/>\n"
                            "    <boolean name=\"use_grid_bbox\" value=\"true\"/>" + to_world + "</volume>\n"
                            "  <volume name=\"albedo\" type=\"gridvolume\"><string name=\"filename\" value=\"albedo.vol\"/>\n"
                            "    <boolean name=\"use_grid_bbox\" value=\"true\"/>" + to_world + "</volume>\n"
                            "  <float name=\"scale\" value=\"4\"/>\n"
                            "  <phase type=\"hg\"><float name=\"g\" value=\"0.5\"/></phase>\n"
                            "</medium>\n"
                            "<medium type=\"heterogeneous\" id=\"unitbox\">\n"
                            "  <volume name=\"sigma_t\" type=\"gridvolume\"><string name=\"filename\" value=\"density.vol\"/>\n"
                            "    <transform name=\"to_world\"><scale value=\"2\"/></transform></volume>\n"
                            "  <rgb name=\"albedo\" value=\"0.9\"/>\n"
                            "</medium>\n"
                            "<medium type=\"heterogeneous\" id=\"grey\">\n"
                            "  <volume name=\"sigma_t\" type=\"gridvolume\"><string name=\"filename\" value=\"density.vol\"/></volume>\n"
                            "  <volume name=\"albedo\" type=\"gridvolume\"><string name=\"filename\" value=\"grey.vol\"/></volume>\n"
                            "</medium>\n"
                            "<medium type=\"heterogeneous\" id=\"constant\">\n"
                            "  <float name=\"sigma_t\" value=\"2\"/>\n"
                            "  <volume name=\"albedo\" type=\"constvolume\"><rgb name=\"value\" value=\"0.5\"/></volume>\n"
                            "</medium>"),
                        dir.path.string());
  const SceneMedia& sm = r.scene.media;
  ASSERT_EQ(sm.media.size(), 4u);
  const float* v = sm.grid_values.data();
  const Medium& smoke = sm.media[0];
  EXPECT_EQ(smoke.type, MediumType::grid);
  expect_rgb_near(smoke.sigma_t, Rgb(4.f));
  EXPECT_FLOAT_EQ(smoke.g, 0.5f);
  EXPECT_EQ(smoke.density.nx, 2u);
  EXPECT_EQ(smoke.density.ny, 1u);
  EXPECT_EQ(smoke.density.channels, 1u);
  EXPECT_EQ(v[smoke.density.offset], 1.f);
  EXPECT_EQ(v[smoke.density.offset + 1], 3.f);
  ASSERT_EQ(smoke.albedo_grid.nx, 1u);
  EXPECT_EQ(smoke.albedo_grid.channels, 3u);
  expect_rgb_near(medium_albedo(smoke, v, Vec3(0.5f, 0.5f, 0.5f)), Rgb(0.2f, 0.4f, 0.6f));
  // The file's box [-1, 1] x [0, 1] x [0, 1], moved by to_world, is the unit cube.
  expect_vec_near(grid_point(smoke, Vec3(9, 0, 0)), Vec3(0, 0, 0));
  expect_vec_near(grid_point(smoke, Vec3(11, 1, 1)), Vec3(1, 1, 1));
  expect_vec_near(grid_point(smoke, Vec3(10, 0.5f, 0.25f)), Vec3(0.5f, 0.5f, 0.25f));
  expect_rgb_near(medium_sigma_t(smoke, v, grid_point(smoke, Vec3(10.5f, 0.5f, 0.5f))), Rgb(12.f));  // sample 1's centre: 4 * 3
  // Mitsuba 3 without use_grid_bbox: the grid spans the unit cube under to_world.
  const Medium& unit = sm.media[1];
  expect_vec_near(grid_point(unit, Vec3(2, 2, 2)), Vec3(1, 1, 1));
  expect_vec_near(grid_point(unit, Vec3(1, 0, 0)), Vec3(0.5f, 0, 0));
  expect_rgb_near(unit.albedo, Rgb(0.9f));
  EXPECT_EQ(unit.albedo_grid.nx, 0u);
  // A one-channel albedo grid is grey.
  const Medium& grey = sm.media[2];
  ASSERT_EQ(grey.albedo_grid.nx, 1u);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(v[grey.albedo_grid.offset + c], 0.5f);
  // Constant sigma_t: a homogeneous medium.
  EXPECT_EQ(sm.media[3].type, MediumType::homogeneous);
  expect_rgb_near(sm.media[3].sigma_t, Rgb(2.f));
  expect_rgb_near(sm.media[3].albedo, Rgb(0.5f));
  EXPECT_EQ(find_warning(r.warnings, "not supported"), "") << ::testing::PrintToString(r.warnings);

  // Mitsuba 0.6: density and albedo volumes, the grid at its file's bounding box.
  const Loaded old = load(scene06(
                              "<medium type=\"heterogeneous\" id=\"smoke\">\n"
                              "  <volume name=\"density\" type=\"gridvolume\"><string name=\"filename\" value=\"density.vol\"/></volume>\n"
                              "  <volume name=\"albedo\" type=\"constvolume\"><spectrum name=\"value\" value=\"0.8\"/></volume>\n"
                              "  <float name=\"scale\" value=\"3\"/>\n"
                              "</medium>\n"
                              "<shape type=\"cube\"><ref name=\"interior\" id=\"smoke\"/><bsdf type=\"null\"/></shape>"),
                          dir.path.string());
  ASSERT_EQ(old.scene.media.media.size(), 1u);
  const Medium& o = old.scene.media.media[0];
  EXPECT_EQ(o.type, MediumType::grid);
  expect_rgb_near(o.sigma_t, Rgb(3.f));
  expect_rgb_near(o.albedo, Rgb(0.8f));
  expect_vec_near(grid_point(o, Vec3(-1, 0, 0)), Vec3(0, 0, 0));
  expect_vec_near(grid_point(o, Vec3(1, 1, 1)), Vec3(1, 1, 1));
  EXPECT_EQ(old.scene.media.triangle_interfaces[0].inside, 0);
}

TEST(MitsubaMedia, VolFilesReadBackAndRefuseBadSizes) {
  TempDir dir("mitsuba-vol");
  const std::vector<float> values = {0.f, 1.f, 2.f, 3.f, 4.f, 5.f, 6.f, 7.f, 8.f, 9.f, 10.f, 11.f};
  const std::string bytes = vol_bytes(2, 3, 2, 1, kBox, values);
  write(dir.file("grid.vol"), bytes);
  const mitsuba::VolumeFile v = mitsuba::read_mitsuba_volume(dir.file("grid.vol"));
  EXPECT_EQ(v.nx, 2u);
  EXPECT_EQ(v.ny, 3u);
  EXPECT_EQ(v.nz, 2u);
  EXPECT_EQ(v.channels, 1u);
  EXPECT_EQ(v.bbox_min[0], -1.0);
  EXPECT_EQ(v.bbox_max[2], 1.0);
  EXPECT_EQ(v.values, values);
  auto expect_parse_error = [](const std::string& b, const std::string& what) {
    try {
      mitsuba::parse_mitsuba_volume(b, "bad.vol");
      ADD_FAILURE() << "no error for " << what;
    } catch (const Error& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.rfind("bad.vol: ", 0), 0u) << m;
      EXPECT_NE(m.find(what), std::string::npos) << m;
    }
  };
  expect_parse_error(bytes.substr(0, bytes.size() - 4), "truncated");
  expect_parse_error(bytes.substr(0, 20), "truncated");
  expect_parse_error(bytes + "xxxx", "where its header asks for");
  expect_parse_error("VOX" + bytes.substr(3), "not a .vol file");
  std::string v2 = bytes;
  v2[3] = 2;
  expect_parse_error(v2, "version 2 is not supported");
  expect_parse_error(vol_bytes(2, 3, 2, 1, kBox, values, 3), "encoding 3 is not supported");
  expect_parse_error(vol_bytes(2, 3, 1, 2, kBox, values), "2 channels");
  expect_parse_error(vol_bytes(2, 0, 2, 1, kBox, values), "has an axis < 1");
  // A header asking for 2^93 values in a small file: refused before anything is allocated.
  expect_parse_error(vol_bytes(2147483647, 2147483647, 2147483647, 3, kBox, values), "truncated");
}

TEST(MitsubaMedia, BadMediaAreErrorsWithTheirLocation) {
  TempDir dir("mitsuba-media-bad");
  write(dir.file("density.vol"), vol_bytes(2, 1, 1, 1, kBox, {1.f, 3.f}));
  write(dir.file("trunc.vol"), vol_bytes(2, 1, 1, 1, kBox, {1.f}));
  write(dir.file("neg.vol"), vol_bytes(2, 1, 1, 1, kBox, {1.f, -1.f}));
  write(dir.file("other.vol"), vol_bytes(1, 1, 1, 3, {0, 0, 0, 2, 2, 2}, {0.5f, 0.5f, 0.5f}));
  expect_error(scene3("<shape type=\"sphere\">\n  <ref name=\"interior\" id=\"nope\"/></shape>"), "scene.xml:3:3:",
               "names no <medium> defined before it");
  expect_error(scene3("<medium type=\"homogeneous\" id=\"m\">\n  <rgb name=\"sigma_t\" value=\"-1 0 0\"/></medium>"), "scene.xml:3:3:",
               "sigma_t must be finite and >= 0");
  expect_error(scene3("<medium type=\"homogeneous\" id=\"m\">\n  <float name=\"albedo\" value=\"2\"/></medium>"), "scene.xml:3:3:",
               "within [0, 1]");
  expect_error(scene3("<medium type=\"homogeneous\" id=\"m\">\n  <float name=\"scale\" value=\"-1\"/></medium>"), "scene.xml:3:3:",
               "scale must be finite and >= 0");
  expect_error(scene3("<medium type=\"homogeneous\" id=\"m\"><phase type=\"hg\">\n  <float name=\"g\" value=\"1\"/></phase></medium>"),
               "scene.xml:3:3:", "g must lie in (-1, 1)");
  expect_error(scene3("<medium type=\"foggy\" id=\"m\"/>"), "scene.xml:2:1:", "medium type 'foggy' is not supported");
  expect_error(scene3("<shape type=\"sphere\">\n  <medium type=\"homogeneous\"/></shape>"), "scene.xml:3:3:", "needs name=\"interior\"");
  expect_error(scene3("<medium type=\"homogeneous\" id=\"m\"/><shape type=\"sphere\"><ref name=\"interior\" id=\"m\"/>\n"
                      "  <medium type=\"homogeneous\" name=\"interior\"/></shape>"),
               "scene.xml:3:3:", "has a second interior medium");
  expect_error(scene3("<medium type=\"homogeneous\" id=\"m\"/><sensor type=\"perspective\"><ref id=\"m\"/>\n"
                      "  <medium type=\"homogeneous\"/></sensor>"),
               "scene.xml:3:3:", "holds a second medium");
  const std::string het = "<medium type=\"heterogeneous\" id=\"m\">\n  <volume name=\"sigma_t\" type=\"gridvolume\">";
  expect_error(scene3(het + "<string name=\"filename\" value=\"none.vol\"/></volume></medium>"), "scene.xml:3:44:",
               "volume file 'none.vol' not found", dir.path.string());
  expect_error(scene3(het + "<string name=\"filename\" value=\"trunc.vol\"/></volume></medium>"), "scene.xml:3:3:", "truncated",
               dir.path.string());
  expect_error(scene3(het + "<string name=\"filename\" value=\"neg.vol\"/></volume></medium>"), "scene.xml:2:1:",
               "density grid has a value -1", dir.path.string());
  expect_error(scene3(het + "<string name=\"filename\" value=\"density.vol\"/></volume>\n"
                            "  <volume name=\"albedo\" type=\"gridvolume\"><string name=\"filename\" value=\"other.vol\"/>"
                            "<boolean name=\"use_grid_bbox\" value=\"true\"/></volume></medium>"),
               "scene.xml:4:3:", "must span the same box", dir.path.string());
  expect_error(scene3("<medium type=\"homogeneous\" id=\"m\">\n  <volume name=\"sigma_t\" type=\"gridvolume\">"
                      "<string name=\"filename\" value=\"density.vol\"/></volume></medium>"),
               "scene.xml:3:3:", "takes constants", dir.path.string());
}

TEST(MitsubaMedia, TopLevelMediumWithoutIdIsAWarning) {
  const Loaded r = load(scene3("<medium type=\"homogeneous\"/>"));
  EXPECT_NE(find_warning(r.warnings, "scene.xml:2:1: warning: top-level <medium> without an id is never used; ignored"), "")
      << ::testing::PrintToString(r.warnings);
  EXPECT_TRUE(r.scene.media.media.empty());
}

}  // namespace
}  // namespace pathspace
