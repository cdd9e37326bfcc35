// pbrt-v4 tokenizer, parser and scene builder on small inline scenes: transforms, named materials,
// includes (also gzip) from a temporary folder, syntax errors with file:line:column, and warnings
// (with locations) for what pathspace does not support.
#include <gtest/gtest.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>

#include "pathspace/io/file_bytes.h"
#include "pathspace/io/pbrt/pbrt_scene_builder.h"
#include "pathspace/io/pbrt/pbrt_tokenizer.h"
#include "pathspace/io/spectrum/white_balance.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

namespace fs = std::filesystem;
using pathspace::testing::TempDir;

const char* kCamera = "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" [ 40 ]\n"
                      "Film \"rgb\" \"integer xresolution\" 64 \"integer yresolution\" [ 32 ]\n";

Scene load(const std::string& world, std::vector<std::string>* warnings = nullptr, SceneLoadOptions options = {},
           SceneFileSettings* settings = nullptr, const std::string& folder = "") {
  LoadWarnings w(warnings);
  return pbrt::load_pbrt_string(std::string(kCamera) + "WorldBegin\n" + world, "test.pbrt", folder, options, &w, settings);
}

// The Error's location (line 0 when no Error was thrown).
FileLoc error_location(const std::string& world, std::string* message = nullptr) {
  try {
    load(world);
  } catch (const Error& e) {
    if (message) *message = e.what();
    return e.location();
  }
  return {};
}

bool has_warning(const std::vector<std::string>& w, const std::string& part) {
  for (const std::string& s : w)
    if (s.find(part) != std::string::npos) return true;
  return false;
}

TEST(PbrtTokenizer, TokensCommentsAndLocations) {
  const std::string src = "Shape \"sphere\" # comment [ ignored\n  \"float radius\" [ 2.5 ]\n\"a\\\"b\"";
  pbrt::Tokenizer t(src, "f.pbrt");
  EXPECT_EQ(t.next().text, "Shape");
  const pbrt::Token s = t.next();
  EXPECT_EQ(s.unquoted(), "sphere");
  EXPECT_EQ(s.loc.column, 7);
  const pbrt::Token p = t.next();
  EXPECT_EQ(p.loc.line, 2);
  EXPECT_EQ(p.loc.column, 3);
  EXPECT_TRUE(t.next().is_open());
  EXPECT_EQ(t.peek().text, "2.5");
  EXPECT_EQ(t.next().text, "2.5");
  EXPECT_TRUE(t.next().is_close());
  EXPECT_EQ(t.next().unquoted(), "a\"b");
  EXPECT_TRUE(t.next().at_end());

  const std::string bad = "Shape \"sphere";
  pbrt::Tokenizer u(bad, "g.pbrt");
  u.next();
  try {
    u.next();
    FAIL() << "unterminated string accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.location().to_string(), "g.pbrt:1:7");
  }
}

TEST(PbrtParser, TransformsPlaceSpheres) {
  const Scene s = load(
      "AttributeBegin\n Translate 1 2 3\n Scale 2 2 2\n Shape \"sphere\" \"float radius\" 0.5\nAttributeEnd\n"
      "AttributeBegin\n Rotate 90 0 0 1\n Translate 1 0 0\n Shape \"sphere\"\nAttributeEnd\n"
      "TransformBegin\n ConcatTransform [1 0 0 0  0 1 0 0  0 0 1 0  -4 0 0 1]\n Shape \"sphere\"\nTransformEnd\n"
      "Transform [1 0 0 0  0 1 0 0  0 0 1 0  0 0 7 1]\nShape \"sphere\"\nIdentity\nShape \"sphere\" \"float radius\" 3\n");
  ASSERT_EQ(s.spheres.size(), 5u);
  EXPECT_EQ(s.spheres[0].center, Vec3(1, 2, 3));
  EXPECT_FLOAT_EQ(s.spheres[0].radius, 1.f);
  EXPECT_NEAR(s.spheres[1].center.x, 0.f, 1e-6f);  // (1,0,0) rotated 90 degrees about z
  EXPECT_NEAR(s.spheres[1].center.y, 1.f, 1e-6f);
  EXPECT_EQ(s.spheres[2].center, Vec3(-4, 0, 0));  // column-major matrix: translation in the last 4
  EXPECT_EQ(s.spheres[3].center, Vec3(0, 0, 7));
  EXPECT_EQ(s.spheres[4].center, Vec3(0, 0, 0));
  EXPECT_FLOAT_EQ(s.spheres[4].radius, 3.f);

  std::string msg;
  const FileLoc loc = error_location("Scale 1 2 1\nShape \"sphere\"\n", &msg);
  EXPECT_EQ(loc.line, 6);  // the Shape statement, not the Scale
  EXPECT_NE(msg.find("non-uniform"), std::string::npos);
}

TEST(PbrtParser, CameraFilmSamplerIntegrator) {
  SceneFileSettings settings;
  const Scene s = pbrt::load_pbrt_string(
      "Integrator \"path\" \"integer maxdepth\" [ 7 ]\nSampler \"sobol\" \"integer pixelsamples\" 32\n" + std::string(kCamera) +
          "WorldBegin\nShape \"sphere\"\n",
      "t.pbrt", "", {}, nullptr, &settings);
  EXPECT_EQ(s.max_path_segments, 8);  // pbrt maxdepth counts bounces; pathspace counts segments
  EXPECT_EQ(settings.spp, 32);
  EXPECT_EQ(s.camera.width, 64);
  EXPECT_EQ(s.camera.height, 32);
  EXPECT_EQ(s.camera.position, Vec3(0, 0, 5));
  EXPECT_NEAR(s.camera.forward.z, -1.f, 1e-6f);
  // pbrt's LookAt: camera +x = cross(up, dir) = (-1, 0, 0) here; raster x follows camera +x.
  EXPECT_NEAR(s.camera.right.x, -1.f, 1e-6f);
  EXPECT_NEAR(s.camera.up.y, 1.f, 1e-6f);
  EXPECT_NEAR(s.camera.tan_y, std::tan(20.0 * M_PI / 180.0), 1e-6);  // fov spans the shorter axis
  EXPECT_NEAR(s.camera.tan_x, 2.0 * std::tan(20.0 * M_PI / 180.0), 1e-6);

  SceneLoadOptions o;
  o.width = 16, o.height = 48;
  const Scene r = load("Shape \"sphere\"\n", nullptr, o);
  EXPECT_EQ(r.camera.width, 16);
  EXPECT_NEAR(r.camera.tan_x, std::tan(20.0 * M_PI / 180.0), 1e-6);
}

// pbrt-v4's imaging ratio, exposure time (shutterclose - shutteropen) x iso / 100, scales every
// emitter (so the image) by the same factor; the defaults (1 s, ISO 100) leave them alone.
TEST(PbrtParser, FilmIsoAndExposureTimeScaleEveryEmitter) {
  const std::string world =
      "WorldBegin\nLightSource \"point\" \"rgb I\" [ 1 2 3 ]\nLightSource \"infinite\" \"rgb L\" [ 0.5 0.5 0.5 ]\n"
      "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [ 4 4 4 ]\nShape \"sphere\"\nAttributeEnd\n";
  auto scene_with = [&](const std::string& camera_params, const std::string& film_params, std::vector<std::string>* w = nullptr) {
    LoadWarnings warnings(w);
    return pbrt::load_pbrt_string("Camera \"perspective\" " + camera_params + "\nFilm \"rgb\" " + film_params + "\n" + world,
                                  "t.pbrt", "", {}, &warnings, nullptr);
  };
  const Scene plain = scene_with("", "");
  const Scene scaled = scene_with("\"float shutteropen\" 0.25 \"float shutterclose\" 0.75", "\"float iso\" 400");
  ASSERT_EQ(plain.lights.size(), scaled.lights.size());
  ASSERT_EQ(plain.lights.size(), 3u);
  for (size_t i = 0; i < plain.lights.size(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(scaled.lights[i].value[c], 2.f * plain.lights[i].value[c]) << "light " << i;
  std::vector<std::string> w;
  const Scene balanced = scene_with("", "\"float whitebalance\" 5000 \"string sensor\" \"canon_eos_100d\"", &w);
  EXPECT_EQ(balanced.output_color_matrix, white_balance_matrix(5000.0));
  EXPECT_EQ(plain.output_color_matrix, white_balance_matrix(0.0));
  EXPECT_TRUE(has_warning(w, "treated as \"cie1931\""));
  EXPECT_THROW(scene_with("", "\"float whitebalance\" 1000"), Error);
  EXPECT_THROW(scene_with("\"float shutteropen\" 1 \"float shutterclose\" 1", ""), Error);
  EXPECT_THROW(scene_with("", "\"float iso\" -100"), Error);
}

TEST(PbrtParser, NamedMaterialsAndLights) {
  std::vector<std::string> w;
  const Scene s = load(
      "MakeNamedMaterial \"gold\" \"string type\" \"conductor\" \"spectrum eta\" \"metal-Au-eta\"\n"
      "  \"spectrum k\" \"metal-Au-k\" \"float roughness\" 0.04\n"
      "MakeNamedMaterial \"glass\" \"string type\" [ \"dielectric\" ] \"float eta\" 1.33\n"
      "Texture \"t\" \"spectrum\" \"constant\" \"rgb value\" [ 0.1 0.2 0.3 ]\n"
      "Material \"diffuse\" \"texture reflectance\" \"t\"\nShape \"sphere\"\n"
      "NamedMaterial \"gold\"\nShape \"sphere\"\nNamedMaterial \"glass\"\nShape \"sphere\"\n"
      "AttributeBegin\n Material \"diffuse\" \"rgb reflectance\" [ 0 0 0 ]\n AreaLightSource \"diffuse\" \"rgb L\" [ 1 2 3 ] \"float scale\" 2 \"bool twosided\" true\n"
      " Shape \"trianglemesh\" \"point3 P\" [ 0 0 0  1 0 0  0 1 0 ] \"integer indices\" [ 0 1 2 ]\nAttributeEnd\n"
      "Shape \"trianglemesh\" \"point3 P\" [ 0 0 0  1 0 0  0 1 0 ]\n"
      "LightSource \"point\" \"rgb I\" [ 5 5 5 ] \"point3 from\" [ 0 4 0 ]\n"
      "LightSource \"distant\" \"point3 from\" [ 0 1 0 ] \"point3 to\" [ 0 0 0 ]\n"
      "LightSource \"infinite\" \"rgb L\" [ 0.5 0.5 0.5 ]\n",
      &w);
  ASSERT_EQ(s.spheres.size(), 3u);
  const Material& diffuse = s.materials[s.spheres[0].material];
  EXPECT_EQ(diffuse.diffuse, Rgb(0.1f, 0.2f, 0.3f));
  EXPECT_TRUE(diffuse.two_sided);
  const Material& gold = s.materials[s.spheres[1].material];
  EXPECT_EQ(gold.type, MaterialType::rough_conductor);
  EXPECT_NEAR(gold.alpha, 0.2f, 1e-6f);  // remaproughness: alpha = sqrt(roughness)
  EXPECT_NEAR(gold.k.r, 3.983160f, 1e-5f);
  const Material& glass = s.materials[s.spheres[2].material];
  EXPECT_FLOAT_EQ(glass.ior, 1.33f);
  ASSERT_EQ(s.triangles.size(), 2u);
  ASSERT_EQ(s.lights.size(), 4u);
  EXPECT_EQ(s.lights[0].type, LightType::area_triangle);
  EXPECT_EQ(s.lights[0].value, Rgb(2, 4, 6));
  EXPECT_TRUE(s.lights[0].two_sided);
  EXPECT_EQ(s.triangles[1].light, kNoLight);  // AttributeEnd ended the area light
  EXPECT_EQ(s.lights[1].position, Vec3(0, 4, 0));
  EXPECT_NEAR(s.lights[2].direction.y, -1.f, 1e-6f);  // light travels from -> to
  EXPECT_EQ(s.lights[3].type, LightType::environment);
  EXPECT_TRUE(w.empty()) << w.front();
}

TEST(PbrtParser, IncludesFromTempFolderAlsoGzip) {
  const TempDir temp("pbrt");
  const fs::path& dir = temp.path;
  fs::create_directories(dir / "sub");
  std::ofstream(dir / "sub" / "mat.pbrt") << "Material \"diffuse\" \"rgb reflectance\" [ 0.25 0.5 0.75 ]\n";
  const std::string gz = (dir / "shapes.pbrt.gz").string();
  const std::string shapes = "Shape \"sphere\" \"float radius\" 4\n";
  gzFile f = gzopen(gz.c_str(), "wb");
  gzwrite(f, shapes.data(), unsigned(shapes.size()));
  gzclose(f);
  std::ofstream(dir / "main.pbrt") << kCamera << "WorldBegin\nInclude \"sub/mat.pbrt\"\nImport \"shapes.pbrt.gz\"\n";
  std::vector<std::string> w;
  const Scene s = load_scene((dir / "main.pbrt").string(), {}, &w);
  ASSERT_EQ(s.spheres.size(), 1u);
  EXPECT_FLOAT_EQ(s.spheres[0].radius, 4.f);
  EXPECT_EQ(s.materials[s.spheres[0].material].diffuse, Rgb(0.25f, 0.5f, 0.75f));

  std::ofstream(dir / "broken.pbrt") << "WorldBegin\nInclude \"missing.pbrt\"\n";
  try {
    load_scene((dir / "broken.pbrt").string(), {}, nullptr);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.location().line, 2);
    EXPECT_NE(std::string(e.what()).find("missing.pbrt"), std::string::npos);
  }
}

// A gzip file may not decompress out of proportion to its size (io/file_bytes.h): 4 MiB of blanks
// compress to a few KiB; with a 1 MiB floor and ratio 100 loading stops with an error naming the
// file and the option, and with no limit the same file loads.
TEST(PbrtParser, GzipBombStopsAtTheDecompressionLimit) {
  const TempDir temp("pbrt");
  const std::string gz = (temp.path / "blanks.pbrt.gz").string();
  const std::string text = kCamera + std::string("WorldBegin\n") + std::string(size_t(4) << 20, ' ') + "Shape \"sphere\"\n";
  gzFile f = gzopen(gz.c_str(), "wb9");
  gzwrite(f, text.data(), unsigned(text.size()));
  gzclose(f);
  ASSERT_LT(fs::file_size(gz), size_t(40000)) << "the test needs a ratio above 100";
  set_decompression_limit(100.0, uint64_t(1) << 20);
  try {
    load_scene(gz, {}, nullptr);
    ADD_FAILURE() << "a 4 MiB file of blanks loaded under a 1 MiB limit";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("blanks.pbrt.gz"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--max-decompression-ratio"), std::string::npos) << e.what();
  }
  set_decompression_limit(0.0, uint64_t(1) << 20);
  EXPECT_NO_THROW(load_scene(gz, {}, nullptr));
  set_decompression_limit(kDefaultMaxDecompressionRatio);
}

TEST(PbrtParser, SyntaxErrorsCarryFileLineColumn) {
  std::string msg;
  // kCamera takes 3 lines and WorldBegin the 4th, so the world starts on line 5.
  FileLoc loc = error_location("Shape \"sphere\"\n  Bogus 1 2\n", &msg);
  EXPECT_EQ(loc.to_string(), "test.pbrt:6:3");
  EXPECT_NE(msg.find("unknown directive 'Bogus'"), std::string::npos);
  loc = error_location("Translate 1 x 3\n", &msg);
  EXPECT_EQ(loc.to_string(), "test.pbrt:5:13");
  loc = error_location("Shape \"sphere\" \"float radius\" [ 1\n", &msg);
  EXPECT_EQ(loc.line, 6);
  EXPECT_NE(msg.find("missing ']'"), std::string::npos);
  loc = error_location("Shape \"sphere\" \"floaty radius\" 1\n", &msg);
  EXPECT_EQ(loc.to_string(), "test.pbrt:5:16");
  loc = error_location("Shape \"sphere\" \"float radius\" \"one\"\n", &msg);
  EXPECT_EQ(loc.line, 5);
  loc = error_location("NamedMaterial \"nope\"\n", &msg);
  EXPECT_EQ(loc.to_string(), "test.pbrt:5:1");
  loc = error_location("AttributeEnd\n", &msg);
  EXPECT_EQ(loc.line, 5);
  loc = error_location("Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 3]\n", &msg);
  EXPECT_EQ(loc.line, 5);
  EXPECT_NE(msg.find("out of range"), std::string::npos);
  loc = error_location("LightSource \"infinite\" \"string filename\" \"sky.exr\"\n", &msg);
  EXPECT_NE(msg.find("sky.exr"), std::string::npos);
}

// pbrt-v4's coated materials become layered BSDFs (materials/layered_bsdf.h) with all their
// parameters; the conductor under a coat has eta and k relative to the coat (pbrt-v4 divides them).
TEST(PbrtParser, CoatedMaterialsKeepTheirLayers) {
  std::vector<std::string> w;
  const Scene s = load(
      "Material \"coateddiffuse\" \"rgb reflectance\" [ 0.2 0.4 0.6 ] \"float roughness\" 0.04 \"float eta\" 1.4\n"
      "  \"float thickness\" 0.2 \"rgb albedo\" [ 0.5 0.5 0.5 ] \"float g\" 0.3 \"integer maxdepth\" 20 \"integer nsamples\" 2\n"
      "Shape \"sphere\"\n"
      "Material \"coatedconductor\" \"float interface.eta\" 1.6 \"float interface.roughness\" 0\n"
      "  \"rgb conductor.eta\" [ 0.32 0.48 1.6 ] \"rgb conductor.k\" [ 3.2 3.2 3.2 ] \"float conductor.roughness\" 0.09\n"
      "Shape \"sphere\" \"float radius\" 0.5\n",
      &w);
  ASSERT_EQ(s.spheres.size(), 2u);
  const Material& d = s.materials[s.spheres[0].material];
  EXPECT_EQ(d.type, MaterialType::coated_diffuse);
  EXPECT_EQ(d.diffuse, Rgb(0.2f, 0.4f, 0.6f));
  EXPECT_FLOAT_EQ(d.alpha, 0.2f);  // sqrt(0.04): remapped
  EXPECT_FLOAT_EQ(d.ior, 1.4f);
  EXPECT_FLOAT_EQ(d.thickness, 0.2f);
  EXPECT_EQ(d.medium_albedo, Rgb(0.5f));
  EXPECT_FLOAT_EQ(d.g, 0.3f);
  EXPECT_EQ(d.max_depth, 20);
  EXPECT_EQ(d.n_samples, 2);
  EXPECT_TRUE(d.two_sided);
  const Material& c = s.materials[s.spheres[1].material];
  EXPECT_EQ(c.type, MaterialType::coated_conductor);
  EXPECT_FLOAT_EQ(c.ior, 1.6f);
  EXPECT_FLOAT_EQ(c.alpha, 0.f);
  EXPECT_FLOAT_EQ(c.base_alpha, 0.3f);
  EXPECT_FLOAT_EQ(c.eta.r, 0.2f);
  EXPECT_FLOAT_EQ(c.k.g, 2.f);
  EXPECT_FLOAT_EQ(c.thickness, 0.01f);  // pbrt-v4's default
  EXPECT_TRUE(w.empty()) << w.front();
  std::string message;
  EXPECT_EQ(error_location("Material \"coateddiffuse\" \"float g\" 1\nShape \"sphere\"\n", &message).line, 5) << message;
  EXPECT_EQ(error_location("Material \"coatedconductor\" \"integer maxdepth\" 0\nShape \"sphere\"\n", &message).line, 5) << message;
}

TEST(PbrtParser, UnsupportedFeaturesWarnWithLocation) {
  std::vector<std::string> w;
  load("Shape \"cylinder\" \"float radius\" 1\nShape \"sphere\" \"float zmax\" 0.5 \"float wobble\" 2\n"
       "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
       "Material \"thindielectric\"\nShape \"sphere\"\n",
       &w);
  EXPECT_TRUE(has_warning(w, "test.pbrt:5:1: warning: Shape \"cylinder\" is not supported")) << w.size();
  EXPECT_TRUE(has_warning(w, "test.pbrt:6:1: warning: partial sphere"));
  EXPECT_TRUE(has_warning(w, "test.pbrt:6:33: warning: Shape \"sphere\": parameter \"float wobble\" is not supported"));
  EXPECT_FALSE(has_warning(w, "MakeNamedMedium"));  // media are read (pbrt_media_test.cpp)
  EXPECT_TRUE(has_warning(w, "test.pbrt:8:1: warning: thindielectric approximated"));

}

// PixelFilter becomes the camera's pixel filter with pbrt-v4's parameters and defaults ("triangle" is
// the tent); an --fov override keeps it; sinc is not built (box, warned); a bad radius is an error
// at the statement.
TEST(PbrtParser, PixelFilters) {
  auto load_filter = [](const std::string& filter, std::vector<std::string>* w, SceneLoadOptions o = {}) {
    LoadWarnings lw(w);
    return pbrt::load_pbrt_string(filter + "\nCamera \"perspective\"\nWorldBegin\nShape \"sphere\"\n", "filter.pbrt", "", o, &lw, nullptr);
  };
  std::vector<std::string> w;
  Scene s = load_filter("PixelFilter \"triangle\" \"float xradius\" 1 \"float yradius\" 1", &w);
  EXPECT_TRUE(w.empty()) << ::testing::PrintToString(w);
  EXPECT_EQ(s.camera.filter.kind, PixelFilterKind::tent);
  EXPECT_EQ(s.camera.filter.radius, 1.f);
  SceneLoadOptions fov;
  fov.fov_degrees = 30.f;
  s = load_filter("PixelFilter \"gaussian\" \"float sigma\" 0.4", &w, fov);
  EXPECT_EQ(s.camera.filter.kind, PixelFilterKind::gaussian);
  EXPECT_EQ(s.camera.filter.radius, 1.5f);
  EXPECT_EQ(s.camera.filter.sigma, 0.4f);
  s = load_filter("PixelFilter \"mitchell\" \"float B\" 0.5 \"float C\" 0.25", &w);
  EXPECT_EQ(s.camera.filter.kind, PixelFilterKind::mitchell);
  EXPECT_EQ(s.camera.filter.b, 0.5f);
  EXPECT_TRUE(has_warning(w, "filter.pbrt:1:1: warning: the mitchell filter's negative lobes are dropped"));
  w.clear();
  s = load_filter("PixelFilter \"sinc\"", &w);
  EXPECT_TRUE(s.camera.filter.is_unit_box());
  EXPECT_TRUE(has_warning(w, "PixelFilter \"sinc\" not supported"));
  s = load_filter("", &w);
  EXPECT_TRUE(s.camera.filter.is_unit_box());
  try {
    load_filter("PixelFilter \"box\" \"float xradius\" 0", &w);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("filter.pbrt:1:1"), std::string::npos) << e.what();
  }
}

// pbrt-v4's thin lens: lensradius and focaldistance (default 1e6) set the camera, without warnings;
// an --fov override keeps the lens; bad values are errors at the Camera statement.
TEST(PbrtParser, ThinLensCamera) {
  auto load_camera = [](const std::string& camera, std::vector<std::string>* w, SceneLoadOptions o = {}) {
    LoadWarnings lw(w);
    return pbrt::load_pbrt_string(camera + "\nWorldBegin\nShape \"sphere\"\n", "lens.pbrt", "", o, &lw, nullptr);
  };
  std::vector<std::string> w;
  Scene s = load_camera("Camera \"perspective\" \"float lensradius\" 0.1 \"float focaldistance\" 3", &w);
  EXPECT_TRUE(w.empty()) << ::testing::PrintToString(w);
  EXPECT_FALSE(s.camera.is_pinhole());
  EXPECT_EQ(s.camera.lens_radius, 0.1f);
  EXPECT_EQ(s.camera.focus_distance, 3.f);
  s = load_camera("Camera \"perspective\" \"float lensradius\" 0.25", &w);
  EXPECT_EQ(s.camera.lens_radius, 0.25f);
  EXPECT_EQ(s.camera.focus_distance, 1e6f);  // pbrt-v4's default
  s = load_camera("Camera \"perspective\" \"float focaldistance\" 3", &w);
  EXPECT_TRUE(s.camera.is_pinhole());  // lensradius defaults to 0
  SceneLoadOptions fov;
  fov.fov_degrees = 30.f;
  s = load_camera("Camera \"perspective\" \"float lensradius\" 0.1 \"float focaldistance\" 3", &w, fov);
  EXPECT_EQ(s.camera.lens_radius, 0.1f);
  EXPECT_EQ(s.camera.focus_distance, 3.f);
  EXPECT_TRUE(w.empty()) << ::testing::PrintToString(w);
  for (const char* bad : {"\"float lensradius\" -1", "\"float lensradius\" 0.1 \"float focaldistance\" 0"}) {
    try {
      load_camera(std::string("Camera \"perspective\" ") + bad, &w);
      ADD_FAILURE() << "no error for " << bad;
    } catch (const Error& e) {
      EXPECT_EQ(e.location().to_string(), "lens.pbrt:1:1") << e.what();
    }
  }
}

}  // namespace
}  // namespace pathspace
