// Mitsuba XML loading (src/pathspace/io/mitsuba/): every supported element kind in both naming
// versions (0.6 camelCase, 3 snake_case), <default>/$substitution, ids and refs, approximations as
// warnings with file:line:column, malformed input as pathspace::Error with its location. The
// Bitterli Cornell box tests (same image from scene_v3.xml and scene-v4.pbrt, Tungsten's walls) are
// in mitsuba_cornell_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "pathspace/base/error.h"
#include "pathspace/io/image_io.h"
#include "pathspace/io/mitsuba/mitsuba_loader.h"
#include "pathspace/io/mitsuba/mitsuba_materials.h"
#include "pathspace/io/named_spectra.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/io/spectrum/spectrum_to_rgb.h"
#include "pathspace/scene/scene_validation.h"
#include "support/load_errors.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

using pathspace::testing::TempDir;

struct Loaded {
  Scene scene;
  std::vector<std::string> warnings;
  SceneFileSettings settings;
};

Loaded load(const std::string& text, const std::string& folder = ".") {
  Loaded r;
  LoadWarnings w(&r.warnings);
  r.scene = mitsuba::load_mitsuba_string(text, "scene.xml", folder, {}, &w, &r.settings);
  return r;
}

// Wraps elements into a Mitsuba 3 scene with one area light, so that only the elements' own
// warnings matter. The body starts on line 2.
std::string scene3(const std::string& body) {
  return "<scene version=\"3.0.0\">\n" + body +
         "\n<shape type=\"rectangle\"><bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"0\"/></bsdf>"
         "<emitter type=\"area\"><rgb name=\"radiance\" value=\"1\"/></emitter></shape>\n</scene>\n";
}

// The first warning containing `text`, or "" when none does.
std::string find_warning(const std::vector<std::string>& warnings, const std::string& text) {
  for (const std::string& w : warnings)
    if (w.find(text) != std::string::npos) return w;
  return {};
}

// Loads `text` expecting a pathspace::Error whose message starts with `where` and contains `what`.
void expect_error(const std::string& text, const std::string& where, const std::string& what, const std::string& folder = ".") {
  testing::expect_load_error([&] { load(text, folder); }, where, what, text);
}

Vec3 normal_of(const Scene& s, const Triangle& t) {
  return triangle_normal(s.positions[t.v[0]], s.positions[t.v[1]], s.positions[t.v[2]]);
}

// One scene in either naming: `v06` spells property names as Mitsuba 0.6 does.
std::string versioned_scene(bool v06) {
  auto n = [&](const char* snake, const char* camel) { return std::string(v06 ? camel : snake); };
  return std::string("<scene version=\"") + (v06 ? "0.6.0" : "3.0.0") + "\">\n" +
         "  <default name=\"spp\" value=\"16\"/>\n"
         "  <integrator type=\"path\"><integer name=\"" + n("max_depth", "maxDepth") + "\" value=\"8\"/></integrator>\n"
         "  <sensor type=\"perspective\">\n"
         "    <float name=\"fov\" value=\"40\"/><string name=\"" + n("fov_axis", "fovAxis") + "\" value=\"y\"/>\n"
         "    <transform name=\"" + n("to_world", "toWorld") + "\"><lookat origin=\"0, 1, 5\" target=\"0, 1, 0\" up=\"0, 1, 0\"/></transform>\n"
         "    <sampler type=\"independent\"><integer name=\"" + n("sample_count", "sampleCount") + "\" value=\"$spp\"/></sampler>\n"
         "    <film type=\"hdrfilm\"><integer name=\"width\" value=\"40\"/><integer name=\"height\" value=\"20\"/></film>\n"
         "  </sensor>\n"
         "  <bsdf type=\"twosided\" id=\"white\"><bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"0.2, 0.4, 0.6\"/></bsdf></bsdf>\n"
         "  <bsdf type=\"plastic\" id=\"plastic\"><float name=\"" + n("int_ior", "intIOR") + "\" value=\"1.5\"/>"
         "<float name=\"" + n("ext_ior", "extIOR") + "\" value=\"1\"/>"
         "<rgb name=\"" + n("diffuse_reflectance", "diffuseReflectance") + "\" value=\"0.5\"/></bsdf>\n"
         "  <bsdf type=\"roughconductor\" id=\"metal\"><string name=\"material\" value=\"Au\"/><string name=\"distribution\" value=\"ggx\"/>"
         "<float name=\"" + n("alpha_u", "alphaU") + "\" value=\"0.3\"/><float name=\"" + n("alpha_v", "alphaV") + "\" value=\"0.3\"/></bsdf>\n"
         "  <shape type=\"rectangle\"><ref id=\"white\"/></shape>\n"
         "  <shape type=\"cube\"><ref id=\"plastic\"/></shape>\n"
         "  <shape type=\"sphere\"><float name=\"radius\" value=\"0.5\"/><ref id=\"metal\"/></shape>\n"
         "  <shape type=\"rectangle\">\n"
         "    <transform name=\"" + n("to_world", "toWorld") + "\"><rotate x=\"1\" angle=\"90\"/><translate y=\"2\"/></transform>\n"
         "    <bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"0\"/></bsdf>\n"
         "    <emitter type=\"area\"><rgb name=\"radiance\" value=\"5\"/></emitter>\n"
         "  </shape>\n"
         "</scene>\n";
}

void expect_versioned_scene(const Loaded& r) {
  const Scene& s = r.scene;
  EXPECT_EQ(s.camera.width, 40);
  EXPECT_EQ(s.camera.height, 20);
  EXPECT_NEAR(distance(s.camera.position, Vec3(0, 1, 5)), 0.f, 1e-6f);
  EXPECT_NEAR(s.camera.forward.z, -1.f, 1e-6f);
  EXPECT_NEAR(s.camera.right.x, 1.f, 1e-6f);  // Mitsuba's camera x axis points left; the image's right is +x
  EXPECT_NEAR(s.camera.up.y, 1.f, 1e-6f);
  EXPECT_NEAR(s.camera.tan_y, std::tan(20.0 * M_PI / 180.0), 1e-6);  // fov_axis y: 40 degrees vertically
  EXPECT_NEAR(s.camera.tan_x, 2.0 * std::tan(20.0 * M_PI / 180.0), 1e-6);
  EXPECT_EQ(r.settings.spp, 16);
  EXPECT_EQ(s.max_path_segments, 8);  // Mitsuba's max_depth counts segments, as pathspace does
  ASSERT_EQ(s.triangles.size(), 2u + 12u + 2u);
  ASSERT_EQ(s.spheres.size(), 1u);
  const Material& white = s.materials[s.triangles[0].material];
  EXPECT_EQ(white.diffuse, Rgb(0.2f, 0.4f, 0.6f));
  EXPECT_TRUE(white.two_sided);
  // Plastic is a coat over Lambert with nothing absorbed; Mitsuba's default linear model becomes
  // the base albedo rho / (1 - Fdr (1 - rho)), Fdr = 0.5963 for eta 1.5 (tests/stat/layered_bsdf_test.cpp).
  const Material& plastic = s.materials[s.triangles[2].material];
  EXPECT_EQ(plastic.type, MaterialType::coated_diffuse);
  EXPECT_FLOAT_EQ(plastic.ior, 1.5f);
  EXPECT_FLOAT_EQ(plastic.alpha, 0.f);
  EXPECT_NEAR(plastic.diffuse.r, 0.5f / (1.f - 0.5963f * 0.5f), 2e-4f);
  const Material& metal = s.materials[s.spheres[0].material];
  EXPECT_EQ(metal.type, MaterialType::rough_conductor);
  EXPECT_FLOAT_EQ(metal.alpha, 0.3f);
  Rgb au_eta;
  ASSERT_TRUE(find_named_spectrum("metal-Au-eta", &au_eta));
  EXPECT_EQ(metal.eta, au_eta);
  EXPECT_FLOAT_EQ(s.spheres[0].radius, 0.5f);
  ASSERT_EQ(s.lights.size(), 2u);
  for (const Light& l : s.lights) {
    EXPECT_EQ(l.type, LightType::area_triangle);
    EXPECT_EQ(l.value, Rgb(5.f));
    EXPECT_FALSE(l.two_sided);
    const Triangle& t = s.triangles[l.shape];
    EXPECT_NEAR(normal_of(s, t).y, -1.f, 1e-6f);  // +z rotated 90 degrees about x: emits downwards
    EXPECT_NEAR(s.positions[t.v[0]].y, 2.f, 1e-6f);
  }
}

TEST(MitsubaLoader, Version3SnakeCase) {
  const Loaded r = load(versioned_scene(false));
  expect_versioned_scene(r);
  EXPECT_EQ(find_warning(r.warnings, "version"), "");
  EXPECT_EQ(find_warning(r.warnings, "plastic"), "");
}

TEST(MitsubaLoader, Version06CamelCase) {
  const Loaded r = load(versioned_scene(true));
  expect_versioned_scene(r);
  for (const std::string& w : r.warnings) EXPECT_EQ(w.find("is not supported; ignored"), std::string::npos) << w;  // every camelCase name understood
}

TEST(MitsubaLoader, SnakeCaseOfCamelCaseNames) {
  EXPECT_EQ(mitsuba::snake_case("maxDepth"), "max_depth");
  EXPECT_EQ(mitsuba::snake_case("intIOR"), "int_ior");
  EXPECT_EQ(mitsuba::snake_case("toWorld"), "to_world");
  EXPECT_EQ(mitsuba::snake_case("diffuseReflectance"), "diffuse_reflectance");
  EXPECT_EQ(mitsuba::snake_case("max_depth"), "max_depth");
}

TEST(MitsubaLoader, DefaultsAndSubstitution) {
  const std::string sensor =
      "<sensor type=\"perspective\"><film type=\"hdrfilm\"><integer name=\"width\" value=\"$w\"/>"
      "<integer name=\"height\" value=\"$h\"/></film></sensor>";
  Loaded r = load(scene3("<default name=\"w\" value=\"32\"/><default name=\"h\" value=\"24\"/>" + sensor));
  EXPECT_EQ(r.scene.camera.width, 32);
  EXPECT_EQ(r.scene.camera.height, 24);
  // The first <default> of a name wins (Mitsuba: a default only applies when nothing set it before).
  r = load(scene3("<default name=\"w\" value=\"16\"/><default name=\"w\" value=\"8\"/><default name=\"h\" value=\"4\"/>" + sensor));
  EXPECT_EQ(r.scene.camera.width, 16);
  // Substitution inside a value and in type attributes.
  r = load(scene3("<default name=\"kind\" value=\"path\"/><default name=\"d\" value=\"2\"/>"
                  "<integrator type=\"$kind\"><integer name=\"max_depth\" value=\"1$d\"/></integrator>"));
  EXPECT_EQ(r.scene.max_path_segments, 12);
  // Film defaults without <default>: Mitsuba's 768x576.
  r = load(scene3("<sensor type=\"perspective\"/>"));
  EXPECT_EQ(r.scene.camera.width, 768);
  EXPECT_EQ(r.scene.camera.height, 576);
  expect_error(scene3(sensor), "scene.xml:2:", "undefined parameter '$w'");
  expect_error(scene3("<default name=\"a b\" value=\"1\"/>"), "scene.xml:2:1:", "<default> needs a name");
  expect_error(scene3("<default name=\"x\"/>"), "scene.xml:2:1:", "has no value");
}

// Parameters from outside (render -D NAME=VALUE) take the place of the file's <default>s, define
// names the file has no <default> for, and the last -D of a name wins.
TEST(MitsubaLoader, DefinesFromOutside) {
  const std::string sensor =
      "<default name=\"w\" value=\"32\"/><sensor type=\"perspective\"><film type=\"hdrfilm\"><integer name=\"width\" value=\"$w\"/>"
      "<integer name=\"height\" value=\"$h\"/></film></sensor>";
  const auto load_with = [&](const std::vector<std::pair<std::string, std::string>>& defines) {
    SceneLoadOptions o;
    o.defines = defines;
    std::vector<std::string> warnings;
    LoadWarnings w(&warnings);
    return mitsuba::load_mitsuba_string(scene3(sensor), "scene.xml", ".", o, &w, nullptr);
  };
  Scene s = load_with({{"h", "20"}});
  EXPECT_EQ(s.camera.width, 32);  // the file's <default>
  EXPECT_EQ(s.camera.height, 20);
  s = load_with({{"h", "20"}, {"w", "40"}, {"w", "48"}});
  EXPECT_EQ(s.camera.width, 48);
  try {
    load_with({{"w", "40"}});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no -D h=VALUE"), std::string::npos) << e.what();
  }
  EXPECT_THROW(load_with({{"a b", "1"}}), Error);
}

// <rfilter> becomes the camera's pixel filter with Mitsuba 3's parameters and defaults; Mitchell
// warns that its negative lobes are dropped, lanczos is not built (box, with a warning), and a bad
// radius is an error at the filter.
TEST(MitsubaLoader, ReconstructionFilters) {
  const auto with_filter = [](const std::string& rfilter) {
    return scene3("<sensor type=\"perspective\"><film type=\"hdrfilm\">" + rfilter + "</film></sensor>");
  };
  Loaded r = load(with_filter("<rfilter type=\"tent\"/>"));
  EXPECT_TRUE(r.warnings.empty()) << ::testing::PrintToString(r.warnings);
  EXPECT_EQ(r.scene.camera.filter.kind, PixelFilterKind::tent);
  EXPECT_EQ(r.scene.camera.filter.radius, 1.f);
  r = load(with_filter("<rfilter type=\"gaussian\"><float name=\"stddev\" value=\"0.25\"/></rfilter>"));
  EXPECT_EQ(r.scene.camera.filter.kind, PixelFilterKind::gaussian);
  EXPECT_EQ(r.scene.camera.filter.sigma, 0.25f);
  EXPECT_EQ(r.scene.camera.filter.radius, 1.f);  // 4 stddev
  r = load(with_filter("<rfilter type=\"catmullrom\"/>"));
  EXPECT_EQ(r.scene.camera.filter.kind, PixelFilterKind::mitchell);
  EXPECT_EQ(r.scene.camera.filter.b, 0.f);
  EXPECT_EQ(r.scene.camera.filter.c, 0.5f);
  EXPECT_NE(find_warning(r.warnings, "negative lobes are dropped"), "");
  r = load(with_filter("<rfilter type=\"lanczos\"/>"));
  EXPECT_TRUE(r.scene.camera.filter.is_unit_box());
  EXPECT_NE(find_warning(r.warnings, "'lanczos' not supported"), "");
  r = load(with_filter("<rfilter type=\"box\"/>"));
  EXPECT_TRUE(r.scene.camera.filter.is_unit_box());
  EXPECT_TRUE(r.warnings.empty()) << ::testing::PrintToString(r.warnings);
  expect_error(with_filter("<rfilter type=\"tent\"><float name=\"radius\" value=\"-1\"/></rfilter>"), "scene.xml:2:",
               "radius -1 must be in (0, 16]");
}

// The thinlens sensor in both namings sets the camera's lens without a warning; both parameters are
// required (Mitsuba 0.6 requires them; Mitsuba 3's focus_distance default 0 is degenerate).
TEST(MitsubaLoader, ThinLensSensor) {
  Loaded r = load(scene3("<sensor type=\"thinlens\"><float name=\"aperture_radius\" value=\"0.1\"/>"
                         "<float name=\"focus_distance\" value=\"2.5\"/></sensor>"));
  EXPECT_TRUE(r.warnings.empty()) << ::testing::PrintToString(r.warnings);
  EXPECT_EQ(r.scene.camera.lens_radius, 0.1f);
  EXPECT_EQ(r.scene.camera.focus_distance, 2.5f);
  r = load("<scene version=\"0.6.0\">\n<sensor type=\"thinlens\"><float name=\"apertureRadius\" value=\"0.2\"/>"
           "<float name=\"focusDistance\" value=\"4\"/></sensor>\n"
           "<shape type=\"rectangle\"><emitter type=\"area\"><rgb name=\"radiance\" value=\"1\"/></emitter></shape>\n</scene>\n");
  EXPECT_EQ(r.scene.camera.lens_radius, 0.2f);
  EXPECT_EQ(r.scene.camera.focus_distance, 4.f);
  r = load(scene3("<sensor type=\"thinlens\"><float name=\"aperture_radius\" value=\"0\"/>"
                  "<float name=\"focus_distance\" value=\"1\"/></sensor>"));
  EXPECT_TRUE(r.scene.camera.is_pinhole());
  expect_error(scene3("<sensor type=\"thinlens\"><float name=\"aperture_radius\" value=\"0.1\"/></sensor>"), "scene.xml:2:1:",
               "focus_distance");
  expect_error(scene3("<sensor type=\"thinlens\"><float name=\"aperture_radius\" value=\"-1\"/>"
                      "<float name=\"focus_distance\" value=\"1\"/></sensor>"),
               "scene.xml:2:", "aperture_radius must be");
  expect_error(scene3("<sensor type=\"thinlens\"><float name=\"aperture_radius\" value=\"0.1\"/>"
                      "<float name=\"focus_distance\" value=\"0\"/></sensor>"),
               "scene.xml:2:", "focus_distance must be");
}

TEST(MitsubaLoader, SensorFilmSamplerIntegrator) {
  Loaded r = load(scene3(
      "<integrator type=\"path\"><integer name=\"max_depth\" value=\"-1\"/><boolean name=\"hide_emitters\" value=\"true\"/></integrator>\n"
      "<sensor type=\"perspective\"><string name=\"focal_length\" value=\"35mm\"/>\n"
      "<film type=\"hdrfilm\"><integer name=\"width\" value=\"30\"/><integer name=\"height\" value=\"20\"/><rfilter type=\"gaussian\"/></film>\n"
      "<sampler type=\"stratified\"/></sensor>"));
  EXPECT_EQ(r.scene.max_path_segments, 1024);  // -1: unbounded
  EXPECT_EQ(r.settings.spp, 4);                // Mitsuba's default sample_count
  // focal_length 35 mm: the fov spans the 36x24 mm film's diagonal; the shorter (y) axis gets 20/diag of it.
  const double tan_diag = std::hypot(36.0, 24.0) / 70.0;
  EXPECT_NEAR(r.scene.camera.tan_y, tan_diag * 20.0 / std::hypot(30.0, 20.0), 1e-5);
  EXPECT_NE(find_warning(r.warnings, "scene.xml:2:63: warning: hide_emitters"), "") << ::testing::PrintToString(r.warnings);
  EXPECT_EQ(r.scene.camera.filter.kind, PixelFilterKind::gaussian);  // Mitsuba's stddev 0.5, radius 2
  EXPECT_EQ(r.scene.camera.filter.radius, 2.f);
  // Options override the file's resolution.
  SceneLoadOptions o;
  o.width = 8;
  o.height = 6;
  std::vector<std::string> warnings;
  LoadWarnings w(&warnings);
  const Scene s = mitsuba::load_mitsuba_string(scene3("<sensor type=\"perspective\"/>"), "scene.xml", ".", o, &w, nullptr);
  EXPECT_EQ(s.camera.width, 8);
  EXPECT_EQ(s.camera.height, 6);
  // `direct`: emission and direct light, i.e. 2 segments, without a warning for its sample counts.
  const Loaded direct = load(scene3("<integrator type=\"direct\"><integer name=\"emitter_samples\" value=\"4\"/></integrator>"));
  EXPECT_EQ(direct.scene.max_path_segments, 2);
  EXPECT_EQ(find_warning(direct.warnings, "integrator"), "") << ::testing::PrintToString(direct.warnings);
  expect_error(scene3("<sensor type=\"orthographic\"/>"), "scene.xml:2:1:", "sensor type 'orthographic' is not supported");
  expect_error(scene3("<sensor type=\"perspective\"><float name=\"fov\" value=\"180\"/></sensor>"), "scene.xml:2:1:", "field of view");
  expect_error(scene3("<integrator type=\"path\"><integer name=\"max_depth\" value=\"0\"/></integrator>"), "scene.xml:2:1:", "max_depth");
}

// Materials straight from <bsdf> elements, in file order.
std::vector<Material> bsdfs(const std::string& body, std::vector<std::string>* warnings, const std::string& folder = ".") {
  const mitsuba::Document doc(scene3(body), "m.xml");
  LoadWarnings w(warnings);
  mitsuba::NamedMaterials named;
  std::vector<Material> out;
  for (const pugi::xml_node& n : doc.scene().children("bsdf")) {
    out.push_back(mitsuba::make_bsdf(doc, n, named, folder, &w));
    if (!doc.attr(n, "id").empty()) named[doc.attr(n, "id")] = out.back();
  }
  return out;
}

TEST(MitsubaLoader, Materials) {
  std::vector<std::string> w;
  const std::vector<Material> m = bsdfs(
      "<bsdf type=\"diffuse\"><srgb name=\"reflectance\" value=\"0.5\"/></bsdf>\n"                                   // 2
      "<bsdf type=\"twosided\" id=\"two\"><bsdf type=\"diffuse\"/></bsdf>\n"                                         // 3
      "<bsdf type=\"conductor\"/>\n"                                                                                 // 4
      "<bsdf type=\"conductor\"><string name=\"material\" value=\"Cu\"/></bsdf>\n"                                   // 5
      "<bsdf type=\"roughconductor\"><float name=\"alpha\" value=\"0.2\"/><rgb name=\"specular_reflectance\" value=\"0.3\"/></bsdf>\n"  // 6
      "<bsdf type=\"dielectric\"><string name=\"int_ior\" value=\"water\"/><string name=\"ext_ior\" value=\"vacuum\"/>"
      "<rgb name=\"specular_transmittance\" value=\"0.9, 0.8, 0.7\"/></bsdf>\n"                                      // 7
      "<bsdf type=\"roughdielectric\"><string name=\"distribution\" value=\"ggx\"/><float name=\"alpha\" value=\"0.3\"/>"
      "<float name=\"int_ior\" value=\"1.5\"/><float name=\"ext_ior\" value=\"1\"/></bsdf>\n"                        // 8
      "<bsdf type=\"thindielectric\"/>\n"                                                                            // 9
      "<bsdf type=\"roughplastic\"><string name=\"distribution\" value=\"ggx\"/><float name=\"alpha\" value=\"0.1\"/>"
      "<float name=\"int_ior\" value=\"1.5\"/><float name=\"ext_ior\" value=\"1\"/><spectrum name=\"diffuse_reflectance\" value=\"0.5\"/></bsdf>\n"  // 10
      "<bsdf type=\"hair\"/>\n"                                                                                      // 11
      "<ref id=\"two\"/>\n"                                                                                          // 12 (not a bsdf element: skipped)
      "<bsdf type=\"twosided\"><ref id=\"two\"/></bsdf>\n"                                                           // 13
      "<bsdf type=\"diffuse\"><spectrum name=\"reflectance\" value=\"400:0.2, 500:0.4, 600:0.6\"/><float name=\"foo\" value=\"1\"/></bsdf>",  // 14
      &w);
  ASSERT_EQ(m.size(), 12u);
  const float lin = std::pow((0.5f + 0.055f) / 1.055f, 2.4f);  // srgb 0.5 decoded
  EXPECT_NEAR(m[0].diffuse.g, lin, 1e-6f);
  EXPECT_FALSE(m[0].two_sided);  // Mitsuba BSDFs are one-sided unless wrapped
  EXPECT_TRUE(m[1].two_sided);
  EXPECT_EQ(m[1].diffuse, Rgb(0.5f));  // Mitsuba's default reflectance
  EXPECT_EQ(m[2].type, MaterialType::rough_conductor);
  EXPECT_EQ(m[2].eta, Rgb(1.f));  // Mitsuba 3's default material "none": a perfect mirror
  EXPECT_GE(m[2].k.r, 100.f);
  Rgb cu;
  ASSERT_TRUE(find_named_spectrum("metal-Cu-k", &cu));
  EXPECT_EQ(m[3].k, cu);
  EXPECT_LT(m[3].alpha, 1e-3f);
  EXPECT_FLOAT_EQ(m[4].alpha, 0.2f);
  EXPECT_EQ(m[4].distribution, MicrofacetDistribution::beckmann);  // Mitsuba's default distribution, no warning
  EXPECT_EQ(m[4].tint, Rgb(0.3f));  // specular_reflectance scales the reflection (Bitterli's veach-mis plates)
  EXPECT_EQ(m[2].tint, Rgb(1.f));
  EXPECT_EQ(find_warning(w, "specular_reflectance"), "");
  EXPECT_EQ(find_warning(w, "distribution approximated"), "");
  EXPECT_EQ(m[5].type, MaterialType::standard);
  EXPECT_FLOAT_EQ(m[5].ior, 1.333f);
  EXPECT_EQ(m[5].specular, Rgb(0.9f, 0.8f, 0.7f));
  EXPECT_EQ(m[6].type, MaterialType::rough_dielectric);
  EXPECT_FLOAT_EQ(m[6].alpha, 0.3f);
  EXPECT_EQ(m[6].distribution, MicrofacetDistribution::ggx);
  EXPECT_FLOAT_EQ(m[6].ior, 1.5f);
  EXPECT_FLOAT_EQ(m[7].ior, 1.5046f / 1.000277f);  // bk7 in air, Mitsuba's defaults
  EXPECT_NE(find_warning(w, "m.xml:9:1: warning: thindielectric approximated"), "");
  EXPECT_EQ(m[8].type, MaterialType::coated_diffuse);
  EXPECT_FLOAT_EQ(m[8].alpha, 0.1f);
  EXPECT_EQ(m[8].distribution, MicrofacetDistribution::ggx);
  EXPECT_NEAR(m[8].diffuse.r, 0.5f / (1.f - 0.5963f * 0.5f), 2e-4f);
  EXPECT_EQ(m[9].diffuse, Rgb(0.5f));
  EXPECT_NE(find_warning(w, "m.xml:11:1: warning: BSDF type 'hair' not supported"), "");
  EXPECT_TRUE(m[10].two_sided);
  // Sampled spectra are converted as reflectances (tests/unit/spectrum_test.cpp); zero outside 400-600 nm.
  const Rgb sampled = spectrum_to_rgb(spectrum_from_pairs({400, 0.2, 500, 0.4, 600, 0.6}, {}, "test"), SpectrumUse::reflectance);
  for (int i = 0; i < 3; ++i) EXPECT_FLOAT_EQ(m[11].diffuse[i], sampled[i]);
  EXPECT_NE(find_warning(w, "m.xml:14:86: warning: <bsdf type=\"diffuse\">: <float name=\"foo\"> is not supported; ignored"), "");

  auto expect_bsdf_error = [](const std::string& body, const std::string& where, const std::string& what) {
    std::vector<std::string> ignored;
    try {
      bsdfs(body, &ignored);
      ADD_FAILURE() << "no error for " << body;
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).rfind(where, 0), 0u) << e.what();
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  expect_bsdf_error("<bsdf type=\"twosided\"><ref id=\"nope\"/></bsdf>", "m.xml:2:23:", "<ref id=\"nope\"> names no <bsdf>");
  expect_bsdf_error("<bsdf type=\"dielectric\">\n  <string name=\"int_ior\" value=\"unobtainium\"/></bsdf>", "m.xml:3:3:", "unknown index of refraction");
  expect_bsdf_error("<bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"0.1 0.2\"/></bsdf>", "m.xml:2:22:", "1 or 3 values");
  expect_bsdf_error("<bsdf type=\"twosided\"/>", "m.xml:2:1:", "needs a nested <bsdf>");
  expect_bsdf_error("<bsdf type=\"roughconductor\"><string name=\"distribution\" value=\"phong\"/></bsdf>", "m.xml:2:1:", "beckmann or ggx");
}

// Mitsuba's conductor eta and k are relative to ext_eta (Bitterli's exports write extEta 1).
TEST(MitsubaLoader, ConductorExteriorIndexDividesEtaAndK) {
  std::vector<std::string> w;
  const std::vector<Material> m = bsdfs(
      "<bsdf type=\"roughconductor\"><rgb name=\"eta\" value=\"0.2, 0.9, 1.1\"/><rgb name=\"k\" value=\"3.9, 2.4, 2.1\"/>"
      "<float name=\"ext_eta\" value=\"2\"/></bsdf>\n"
      "<bsdf type=\"roughconductor\"><rgb name=\"eta\" value=\"0.2, 0.9, 1.1\"/><rgb name=\"k\" value=\"3.9, 2.4, 2.1\"/>"
      "<float name=\"ext_eta\" value=\"1\"/></bsdf>",
      &w);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_FLOAT_EQ(m[0].eta.g, 0.45f);
  EXPECT_FLOAT_EQ(m[0].k.r, 1.95f);
  EXPECT_EQ(m[1].eta, Rgb(0.2f, 0.9f, 1.1f));
  EXPECT_EQ(find_warning(w, "ext_eta"), "");
}

TEST(MitsubaLoader, BitmapTexturesUseTheirMeanColour) {
  TempDir dir("mitsuba");
  Image img(2, 1);
  img.at(0, 0) = Rgb(0.2f, 0.4f, 0.6f);
  img.at(1, 0) = Rgb(0.4f, 0.6f, 0.8f);
  write_image(dir.file("tex.exr"), img);
  std::vector<std::string> w;
  const std::vector<Material> m = bsdfs(
      "<texture type=\"bitmap\" id=\"shared\"><string name=\"filename\" value=\"tex.exr\"/></texture>\n"
      "<bsdf type=\"diffuse\"><texture type=\"bitmap\" name=\"reflectance\"><string name=\"filename\" value=\"tex.exr\"/>"
      "<string name=\"filter_type\" value=\"nearest\"/></texture></bsdf>\n"
      "<bsdf type=\"diffuse\">\n  <ref name=\"reflectance\" id=\"shared\"/></bsdf>\n"
      "<bsdf type=\"diffuse\"><texture type=\"checkerboard\" name=\"reflectance\"><rgb name=\"color0\" value=\"0.2\"/>"
      "<rgb name=\"color1\" value=\"0.6\"/></texture></bsdf>",
      &w, dir.path.string());
  ASSERT_EQ(m.size(), 3u);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(m[size_t(i)].diffuse.r, 0.3f, 1e-6f);
    EXPECT_NEAR(m[size_t(i)].diffuse.g, 0.5f, 1e-6f);
    EXPECT_NEAR(m[size_t(i)].diffuse.b, 0.7f, 1e-6f);
  }
  EXPECT_NEAR(m[2].diffuse.r, 0.4f, 1e-6f);
  EXPECT_NE(find_warning(w, "m.xml:3:22: warning: bitmap texture 'tex.exr' for 'reflectance' approximated by its mean colour"), "")
      << ::testing::PrintToString(w);
  EXPECT_NE(find_warning(w, "m.xml:2:1: warning: bitmap texture 'tex.exr'"), "");  // the referenced texture's own line
  EXPECT_NE(find_warning(w, "checkerboard texture for 'reflectance' approximated"), "");

  expect_error(scene3("<shape type=\"rectangle\"><bsdf type=\"diffuse\">\n<texture type=\"bitmap\" name=\"reflectance\">"
                      "<string name=\"filename\" value=\"missing.png\"/></texture></bsdf></shape>"),
               "scene.xml:3:1:", "texture file 'missing.png' not found", dir.path.string());
  expect_error(scene3("<shape type=\"rectangle\"><bsdf type=\"diffuse\"><ref name=\"reflectance\" id=\"nope\"/></bsdf></shape>"),
               "scene.xml:2:46:", "names no top-level <texture>");
}

TEST(MitsubaLoader, IdsAndRefsShareOneMaterial) {
  const Loaded r = load(scene3(
      "<bsdf type=\"diffuse\" id=\"grey\"><rgb name=\"reflectance\" value=\"0.3\"/></bsdf>"
      "<shape type=\"rectangle\"><ref id=\"grey\"/></shape><shape type=\"cube\"><ref name=\"bsdf\" id=\"grey\"/></shape>"
      "<shape type=\"disk\"/><shape type=\"disk\"/>"));
  ASSERT_GE(r.scene.triangles.size(), 14u);
  EXPECT_EQ(r.scene.triangles[0].material, r.scene.triangles[2].material);
  EXPECT_EQ(r.scene.materials[r.scene.triangles[0].material].diffuse, Rgb(0.3f));
  // Shapes without a BSDF share Mitsuba's default (one-sided diffuse 0.5).
  const uint32_t d0 = r.scene.triangles[14].material, d1 = r.scene.triangles[14 + 64].material;
  EXPECT_EQ(d0, d1);
  EXPECT_EQ(r.scene.materials[d0].diffuse, Rgb(0.5f));
  expect_error(scene3("<shape type=\"cube\">\n  <ref id=\"later\"/></shape><bsdf type=\"diffuse\" id=\"later\"/>"), "scene.xml:3:3:",
               "<ref id=\"later\"> names no <bsdf> defined before it");
}

TEST(MitsubaLoader, AnalyticShapes) {
  const Loaded r = load(scene3(
      "<shape type=\"cube\"><transform name=\"to_world\"><scale value=\"2\"/><translate x=\"5\"/></transform></shape>\n"
      "<shape type=\"sphere\"><point name=\"center\" x=\"1\" y=\"2\" z=\"3\"/><float name=\"radius\" value=\"0.5\"/>"
      "<transform name=\"to_world\"><scale value=\"2\"/></transform></shape>\n"
      "<shape type=\"sphere\"><boolean name=\"flip_normals\" value=\"true\"/></shape>\n"
      "<shape type=\"sphere\"><transform name=\"to_world\"><scale x=\"2\"/></transform></shape>\n"
      "<shape type=\"disk\"><transform name=\"to_world\"><scale value=\"3\"/></transform></shape>\n"
      "<shape type=\"rectangle\"><boolean name=\"flip_normals\" value=\"true\"/></shape>\n"
      "<shape type=\"rectangle\"><transform name=\"to_world\"><scale z=\"-1\"/></transform></shape>\n"
      "<shape type=\"cylinder\"/>"));
  const Scene& s = r.scene;
  // Cube [-1,1]^3 scaled by 2 around (5,0,0): 12 triangles, all facing out.
  for (size_t i = 0; i < 12; ++i) {
    const Triangle& t = s.triangles[i];
    const Vec3 c = (s.positions[t.v[0]] + s.positions[t.v[1]] + s.positions[t.v[2]]) / 3.f - Vec3(5, 0, 0);
    EXPECT_GT(dot(normal_of(s, t), c), 1.9f) << i;
    for (uint32_t v : t.v) EXPECT_NEAR(std::fabs(s.positions[v].y), 2.f, 1e-6f);
  }
  ASSERT_EQ(s.spheres.size(), 2u);
  EXPECT_NEAR(distance(s.spheres[0].center, Vec3(2, 4, 6)), 0.f, 1e-6f);  // center, then to_world
  EXPECT_FLOAT_EQ(s.spheres[0].radius, 1.f);
  EXPECT_TRUE(s.spheres[1].inward_normals);
  EXPECT_NE(find_warning(r.warnings, "scene.xml:5:1: warning: sphere under a non-uniform scale or shear triangulated"), "");
  // The ellipsoid (x scaled by 2): 64 x 32 rows of the tessellated sphere, 3968 triangles, with
  // Mitsuba's uvs (v = 1 at the +z pole after the flip to pathspace's convention) and smooth shading
  // normals, those of the ellipsoid x^2 / 4 + y^2 + z^2 = 1.
  const size_t ellipsoid_triangles = 64 * 62;
  ASSERT_EQ(s.normals.size(), s.positions.size());
  ASSERT_EQ(s.uvs.size(), s.positions.size());
  for (size_t i = 12; i < 12 + ellipsoid_triangles; ++i)
    for (uint32_t v : s.triangles[i].v) {
      const Vec3 p = s.positions[v];
      EXPECT_NEAR(p.x * p.x / 4.f + p.y * p.y + p.z * p.z, 1.f, 1e-5f);
      const Vec3 expected = normalize(Vec3(p.x / 4.f, p.y, p.z));
      EXPECT_GT(dot(s.normals[v], expected), 0.99999f) << v;
      const Point2 uv = s.uvs[v];
      EXPECT_TRUE(uv.x >= 0.f && uv.x <= 1.f) << v;
      EXPECT_NEAR(uv.y, std::acos(std::clamp(-p.z, -1.f, 1.f)) / float(M_PI), 1e-4f) << v;  // 0 at -z, 1 at +z
    }
  for (size_t i = 0; i < 12; ++i)
    for (uint32_t v : s.triangles[i].v) EXPECT_EQ(s.normals[v], Vec3()) << "the cube stays flat";
  // The disk: 64 triangles facing +z whose area is the disk's (emitted power unchanged).
  const size_t disk0 = 12 + ellipsoid_triangles;
  double area = 0;
  for (size_t i = disk0; i < disk0 + 64; ++i) {
    const Triangle& t = s.triangles[i];
    area += triangle_area(s.positions[t.v[0]], s.positions[t.v[1]], s.positions[t.v[2]]);
    EXPECT_NEAR(normal_of(s, t).z, 1.f, 1e-6f);
  }
  EXPECT_NEAR(area, M_PI * 9.0, 1e-4);
  EXPECT_NEAR(normal_of(s, s.triangles[disk0 + 64]).z, -1.f, 1e-6f);  // flip_normals
  EXPECT_NEAR(normal_of(s, s.triangles[disk0 + 66]).z, -1.f, 1e-6f);  // a mirroring to_world turns the normal
  EXPECT_NE(find_warning(r.warnings, "scene.xml:9:1: warning: shape type 'cylinder' not supported; skipped"), "");
  expect_error(scene3("<shape type=\"sphere\"><float name=\"radius\" value=\"-1\"/></shape>"), "scene.xml:2:1:", "radius");
}

TEST(MitsubaLoader, MeshFiles) {
  TempDir dir("mitsuba");
  std::ofstream(dir.file("quad.obj")) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
  std::ofstream(dir.file("tri.ply")) << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                                        "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const Loaded r = load(scene3("<shape type=\"obj\"><string name=\"filename\" value=\"quad.obj\"/></shape>\n"
                               "<shape type=\"ply\"><string name=\"filename\" value=\"tri.ply\"/>"
                               "<transform name=\"to_world\"><translate z=\"2\"/></transform>"
                               "<emitter type=\"area\"><rgb name=\"radiance\" value=\"3\"/></emitter></shape>"),
                        dir.path.string());
  const Scene& s = r.scene;
  ASSERT_EQ(s.triangles.size(), 2u + 1u + 2u);
  EXPECT_NEAR(normal_of(s, s.triangles[0]).z, 1.f, 1e-6f);
  EXPECT_NEAR(s.positions[s.triangles[2].v[0]].z, 2.f, 1e-6f);
  EXPECT_EQ(s.triangles[2].light, 0);
  EXPECT_EQ(s.lights[0].value, Rgb(3.f));
  EXPECT_NE(find_warning(r.warnings, "scene.xml:3:1: warning: an emissive shape's BSDF is ignored"), "");  // the default BSDF reflects
  expect_error(scene3("<shape type=\"ply\">\n<string name=\"filename\" value=\"none.ply\"/></shape>"), "scene.xml:2:1:", "none.ply",
               dir.path.string());
  expect_error(scene3("<shape type=\"obj\"/>"), "scene.xml:2:1:", "needs a filename", dir.path.string());
}

// Mitsuba 3's instancing: a shapegroup's shapes appear once per instance, under its to_world.
TEST(MitsubaLoader, ShapegroupInstances) {
  const Loaded r = load(scene3(
      "<shape type=\"shapegroup\" id=\"pair\">\n"
      "  <shape type=\"rectangle\"><transform name=\"to_world\"><translate x=\"1\"/></transform></shape>\n"
      "  <shape type=\"sphere\"><float name=\"radius\" value=\"0.5\"/></shape>\n"
      "</shape>\n"
      "<shape type=\"instance\"><ref id=\"pair\"/><transform name=\"to_world\"><translate y=\"10\"/></transform></shape>\n"
      "<shape type=\"instance\"><ref id=\"pair\"/><transform name=\"to_world\"><scale value=\"2\"/></transform></shape>"));
  const Scene& s = r.scene;
  ASSERT_EQ(s.spheres.size(), 2u);
  EXPECT_NEAR(s.spheres[0].center.y, 10.f, 1e-6f);
  EXPECT_NEAR(s.spheres[1].radius, 1.f, 1e-6f);  // the instance's scale on top of the shape's radius
  ASSERT_EQ(s.triangles.size(), 2u + 2u + 2u);   // two rectangles placed, then scene3's emitter
  const Vec3 first = s.positions[s.triangles[0].v[0]], second = s.positions[s.triangles[2].v[0]];
  EXPECT_NEAR(first.y, second.y / 2.f + 10.f, 1e-5f);  // the same corner: translated, then scaled about the origin
  EXPECT_NEAR(second.x, 2.f * (first.x), 1e-5f);
  EXPECT_EQ(r.warnings.size(), 1u) << ::testing::PrintToString(r.warnings);  // only scene3's missing sensor
  expect_error(scene3("<shape type=\"instance\"><ref id=\"none\"/></shape>"), "scene.xml:2:1:", "no shapegroup 'none'");
  expect_error(scene3("<shape type=\"shapegroup\" id=\"g\"><shape type=\"instance\"/></shape>"), "scene.xml:2:", "cannot hold a shapegroup or an instance");
  expect_error(scene3("<shape type=\"shapegroup\"/>"), "scene.xml:2:1:", "needs an id");
}

// Mesh files shade smooth as in Mitsuba 3: the file's normals, else angle-weighted ones from the
// faces; face_normals makes them flat. A folded quad: the fold's vertices get the mean of +z and +x.
TEST(MitsubaLoader, MeshNormals) {
  TempDir dir("mitsuba");
  std::ofstream(dir.file("fold.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\n";
  std::ofstream(dir.file("given.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nvn 0 1 1\nf 1//1 2//2 3//1\n";
  // The shading normal at the triangles' corner at p (the OBJ reader gives corners with a vn their
  // own vertex, after the file's unused ones).
  const auto normal_at = [](const Scene& s, const Vec3& p) {
    for (const Triangle& t : s.triangles)
      for (uint32_t i : t.v)
        if (length(s.positions[i] - p) < 1e-6f && i < s.normals.size()) return s.normals[i];
    return Vec3(-9.f, -9.f, -9.f);
  };
  const Scene smooth = load(scene3("<shape type=\"obj\"><string name=\"filename\" value=\"fold.obj\"/></shape>"), dir.path.string()).scene;
  const float h = std::sqrt(0.5f);
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(0, 1, 0)}) {
    const Vec3 n = normal_at(smooth, p);
    EXPECT_NEAR(n.x, h, 1e-5f);
    EXPECT_NEAR(n.y, 0.f, 1e-5f);
    EXPECT_NEAR(n.z, h, 1e-5f);
  }
  EXPECT_NEAR(normal_at(smooth, Vec3(1, 0, 0)).z, 1.f, 1e-6f);
  EXPECT_NEAR(normal_at(smooth, Vec3(0, 0, 1)).x, 1.f, 1e-6f);
  const Scene flat = load(scene3("<shape type=\"obj\"><string name=\"filename\" value=\"fold.obj\"/>"
                                 "<boolean name=\"face_normals\" value=\"true\"/></shape>"),
                          dir.path.string()).scene;
  for (const Vec3& n : flat.normals) EXPECT_EQ(dot(n, n), 0.f);
  const Scene given = load(scene3("<shape type=\"obj\"><string name=\"filename\" value=\"given.obj\"/></shape>"), dir.path.string()).scene;
  EXPECT_NEAR(normal_at(given, Vec3(0, 0, 0)).z, 1.f, 1e-6f);
  EXPECT_NEAR(normal_at(given, Vec3(1, 0, 0)).y, h, 1e-5f);
}

// <path value="..."/>: relative file names are looked up in the scene's folder first, then in each
// search folder in file order (relative to the scene's folder), as Mitsuba's file resolver does.
TEST(MitsubaLoader, SearchPaths) {
  TempDir dir("mitsuba");
  std::filesystem::create_directories(dir.path / "meshes" / "more");
  std::ofstream(dir.file("meshes/more/quad.obj")) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
  std::ofstream(dir.file("meshes/tri.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::ofstream(dir.file("tri.obj")) << "v 0 0 5\nv 1 0 5\nv 0 1 5\nf 1 2 3\n";  // the scene's folder comes first
  const std::string shapes = "<shape type=\"obj\"><string name=\"filename\" value=\"quad.obj\"/></shape>\n"
                             "<shape type=\"obj\"><string name=\"filename\" value=\"tri.obj\"/></shape>";
  const Loaded r = load(scene3("<path value=\"meshes\"/><path value=\"meshes/more\"/>\n" + shapes), dir.path.string());
  ASSERT_EQ(r.scene.triangles.size(), 2u + 1u + 2u);
  EXPECT_EQ(r.scene.positions[r.scene.triangles[2].v[0]].z, 5.f);
  EXPECT_EQ(find_warning(r.warnings, "<path>"), "");  // read, not ignored
  // Without the search folder the mesh is not found, and the message names where it looked.
  expect_error(scene3(shapes), "scene.xml:2:1:", "quad.obj", dir.path.string());
  expect_error(scene3("<path/>"), "scene.xml:2:1:", "<path> needs a value", dir.path.string());
}

// <include filename="..."/>: the included file's scene elements take the include's place (found
// like any file name), nested includes too, and each keeps its own file:line:column in messages.
TEST(MitsubaLoader, Includes) {
  TempDir dir("mitsuba");
  std::filesystem::create_directories(dir.path / "parts");
  std::ofstream(dir.file("parts/light.xml")) << "<scene version=\"3.0.0\">\n"
                                                "  <emitter type=\"point\"><rgb name=\"intensity\" value=\"$power\"/></emitter>\n"
                                                "  <include filename=\"parts/shape.xml\"/>\n"
                                                "</scene>\n";
  std::ofstream(dir.file("parts/shape.xml")) << "<scene version=\"3.0.0\">\n\n"
                                                "  <shape type=\"sphere\"><float name=\"radius\" value=\"$radius\"/></shape>\n"
                                                "</scene>\n";
  const std::string main = "<scene version=\"3.0.0\">\n<default name=\"power\" value=\"7\"/>\n"
                           "<default name=\"radius\" value=\"2\"/>\n<include filename=\"parts/light.xml\"/>\n</scene>\n";
  const Loaded r = load(main, dir.path.string());
  ASSERT_EQ(r.scene.lights.size(), 1u);
  EXPECT_EQ(r.scene.lights[0].value, Rgb(7.f));
  ASSERT_EQ(r.scene.spheres.size(), 1u);
  EXPECT_EQ(r.scene.spheres[0].radius, 2.f);
  // An error in an included file is reported there.
  const std::string bad = "<scene version=\"3.0.0\">\n<default name=\"power\" value=\"7\"/>\n"
                          "<default name=\"radius\" value=\"-1\"/>\n<include filename=\"parts/light.xml\"/>\n</scene>\n";
  expect_error(bad, (dir.path / "parts" / "shape.xml").string() + ":3:3:", "radius", dir.path.string());
  expect_error(scene3("<include filename=\"none.xml\"/>"), "scene.xml:2:1:", "included file 'none.xml' not found", dir.path.string());
  std::ofstream(dir.file("self.xml")) << "<scene version=\"3.0.0\"><include filename=\"self.xml\"/></scene>\n";
  expect_error(scene3("<include filename=\"self.xml\"/>"), (dir.path / "self.xml").string() + ":1:", "more than 256", dir.path.string());
}

TEST(MitsubaLoader, Emitters) {
  TempDir dir("mitsuba");
  Image env(4, 2);
  for (Rgb& c : env.pixels) c = Rgb(0.25f, 0.5f, 1.f);
  write_image(dir.file("sky.exr"), env);
  const Loaded r = load(
      "<scene version=\"3.0.0\">\n"
      "<emitter type=\"point\"><point name=\"position\" value=\"1, 2, 3\"/><rgb name=\"intensity\" value=\"4\"/></emitter>\n"
      "<emitter type=\"point\"><transform name=\"to_world\"><translate y=\"5\"/></transform></emitter>\n"
      "<emitter type=\"spot\"><float name=\"cutoff_angle\" value=\"20\"/></emitter>\n"
      "<emitter type=\"directional\"><vector name=\"direction\" x=\"0\" y=\"-2\" z=\"0\"/><rgb name=\"irradiance\" value=\"3\"/></emitter>\n"
      "<emitter type=\"envmap\"><string name=\"filename\" value=\"sky.exr\"/><float name=\"scale\" value=\"2\"/></emitter>\n"
      "</scene>",
      dir.path.string());
  const Scene& s = r.scene;
  ASSERT_EQ(s.lights.size(), 5u);
  EXPECT_EQ(s.lights[0].type, LightType::point);
  EXPECT_NEAR(distance(s.lights[0].position, Vec3(1, 2, 3)), 0.f, 1e-6f);
  EXPECT_EQ(s.lights[0].value, Rgb(4.f));
  EXPECT_NEAR(distance(s.lights[1].position, Vec3(0, 5, 0)), 0.f, 1e-6f);
  EXPECT_EQ(s.lights[1].value, Rgb(1.f));
  EXPECT_EQ(s.lights[2].type, LightType::spot);  // along +z, beam width 3/4 of the cutoff
  EXPECT_NEAR(s.lights[2].direction.z, 1.f, 1e-6f);
  EXPECT_NEAR(s.lights[2].cos_total, std::cos(20.0 * M_PI / 180.0), 1e-6);
  EXPECT_NEAR(s.lights[2].cos_falloff, std::cos(15.0 * M_PI / 180.0), 1e-6);
  EXPECT_EQ(s.lights[2].falloff, SpotFalloff::linear_angle);  // Mitsuba's fade, exactly
  EXPECT_EQ(s.lights[3].type, LightType::directional);
  EXPECT_NEAR(s.lights[3].direction.y, -1.f, 1e-6f);
  EXPECT_EQ(s.lights[3].value, Rgb(3.f));
  EXPECT_EQ(s.lights[4].type, LightType::environment);  // the image itself, times the scale
  EXPECT_EQ(s.lights[4].value, Rgb(2.f));
  EXPECT_FALSE(s.environment_image.empty());
  EXPECT_EQ(find_warning(r.warnings, "approximated by a constant environment"), "");

  const Loaded c = load(scene3("<emitter type=\"constant\"><rgb name=\"radiance\" value=\"0.5\"/></emitter>"));
  ASSERT_EQ(c.scene.lights.size(), 3u);  // and scene3's two area-light triangles
  EXPECT_EQ(c.scene.lights[0].type, LightType::environment);
  EXPECT_EQ(c.scene.lights[0].value, Rgb(0.5f));
  expect_error(scene3("<emitter type=\"constant\"/>\n<emitter type=\"constant\"/>"), "scene.xml:3:1:", "at most one environment");
  expect_error(scene3("<emitter type=\"envmap\">\n<string name=\"filename\" value=\"none.exr\"/></emitter>"), "scene.xml:3:1:",
               "environment map 'none.exr' not found", dir.path.string());
  expect_error(scene3("<emitter type=\"directional\"><vector name=\"direction\" value=\"0 0 0\"/></emitter>"), "scene.xml:2:1:",
               "direction must be non-zero");
}

TEST(MitsubaLoader, UnsupportedIsAWarningWithItsLocation) {
  const Loaded r = load(scene3("<medium type=\"homogeneous\"/>\n"
                               "<shape type=\"rectangle\">\n  <bsdf type=\"diffuse\">\n    <float name=\"roughness\" value=\"1\"/></bsdf>\n"
                               "  <emitter type=\"point\"/></shape>"));
  EXPECT_NE(find_warning(r.warnings, "scene.xml:2:1: warning: top-level <medium> without an id is never used; ignored"), "");
  EXPECT_NE(find_warning(r.warnings, "scene.xml:5:5: warning: <bsdf type=\"diffuse\">: <float name=\"roughness\"> is not supported; ignored"), "")
      << ::testing::PrintToString(r.warnings);
  EXPECT_NE(find_warning(r.warnings, "scene.xml:6:3: warning: emitter 'point' inside a shape is not supported"), "");
  const Loaded none = load("<scene version=\"3.0.0\"/>");
  // No emitters: scene/scene_validation.h warns, for every format alike.
  std::vector<std::string> checked;
  validate_scene(none.scene, &checked);
  EXPECT_NE(find_warning(checked, "the scene has no light sources"), "");
  EXPECT_NE(find_warning(none.warnings, "no <sensor>"), "");
}

TEST(MitsubaLoader, MalformedInputIsAnErrorWithItsLocation) {
  expect_error("<scene version=\"3.0.0\">\n  <shape type=\"cube\">\n</scene>\n", "scene.xml:3:", "XML syntax error");
  expect_error("<scene version=\"3.0.0\">\n  <shape type=\"cube\"\n", "scene.xml:", "XML syntax error");
  expect_error("<notascene/>", "scene.xml", "no <scene> element");
  expect_error(scene3("<sensor type=\"perspective\">\n  <float name=\"fov\" value=\"4x5\"/></sensor>"), "scene.xml:3:3:", "invalid number in '4x5'");
  expect_error(scene3("<sensor type=\"perspective\">\n  <float name=\"fov\" value=\"nan\"/></sensor>"), "scene.xml:3:3:", "invalid number");
  expect_error(scene3("<sensor type=\"perspective\">\n  <float name=\"fov\" value=\"\"/></sensor>"), "scene.xml:3:3:", "expected one number");
  expect_error(scene3("<shape type=\"cube\"><transform name=\"to_world\">\n  <translate x=\"inf\"/></transform></shape>"), "scene.xml:3:3:",
               "invalid number");
  expect_error(scene3("<shape type=\"cube\"><transform name=\"to_world\">\n  <shear x=\"1\"/></transform></shape>"), "scene.xml:3:3:",
               "unknown transform operation <shear>");
  expect_error(scene3("<shape type=\"cube\"><transform name=\"to_world\">\n  <matrix value=\"1 2 3\"/></transform></shape>"), "scene.xml:3:3:",
               "<matrix> needs 16");
  expect_error(scene3("<sensor type=\"perspective\"><transform name=\"to_world\">\n  <lookat origin=\"0 0 0\" target=\"0 0 0\"/></transform></sensor>"),
               "scene.xml:3:3:", "<lookat>");
  expect_error(scene3("<integrator type=\"path\">\n  <integer name=\"max_depth\" value=\"2.5\"/></integrator>"), "scene.xml:3:3:", "must be an integer");
  expect_error(scene3("<integrator type=\"path\">\n  <float name=\"max_depth\" value=\"2\"/></integrator>"), "scene.xml:3:3:", "must be an <integer>");
  expect_error(scene3("<shape type=\"rectangle\" >\n <boolean name=\"flip_normals\" value=\"yes\"/></shape>"), "scene.xml:3:2:", "boolean");
  expect_error(scene3("<sensor type=\"perspective\"><film type=\"hdrfilm\">\n <integer name=\"width\" value=\"0\"/></film></sensor>"),
               "scene.xml:2:28:", "film width and height");
}

TEST(MitsubaLoader, SceneLoaderDispatchesXmlFiles) {
  EXPECT_TRUE(is_scene_file("a/b.xml"));
  EXPECT_TRUE(is_scene_file("a/b.XML.gz"));
  TempDir dir("mitsuba");
  std::ofstream(dir.file("scene.xml")) << versioned_scene(false);
  std::vector<std::string> warnings;
  SceneFileSettings settings;
  const Scene s = load_scene(dir.file("scene.xml"), {}, &warnings, &settings);
  EXPECT_EQ(s.triangles.size(), 16u);
  EXPECT_EQ(settings.spp, 16);
  EXPECT_EQ(s.materials[s.triangles[2].material].type, MaterialType::coated_diffuse);  // the plastic
  EXPECT_TRUE(warnings.empty()) << ::testing::PrintToString(warnings);
}

}  // namespace
}  // namespace pathspace
