// pbrt-v4 participating media (io/pbrt/pbrt_media.h): MakeNamedMedium's homogeneous, uniformgrid
// and rgbgrid media with pbrt-v4's defaults, MediumInterface bindings of shapes, lights and the
// camera through the graphics state, Material "interface", the subsurface material (a dielectric
// around its own medium), and bad media as errors at their file:line:column.
#include <gtest/gtest.h>

#include <cmath>

#include "pathspace/io/pbrt/pbrt_scene_builder.h"
#include "pathspace/media/grid_lookup.h"
#include "support/load_errors.h"
#include "support/near_expectations.h"

namespace pathspace {
namespace {

const char* kCamera = "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" [ 40 ]\n"
                      "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" [ 16 ]\n";

// The world starts on line 5 (the camera's three lines and WorldBegin come first).
Scene load(const std::string& world, std::vector<std::string>* warnings = nullptr) {
  LoadWarnings w(warnings);
  return pbrt::load_pbrt_string(std::string(kCamera) + "WorldBegin\n" + world, "test.pbrt", "", {}, &w, nullptr);
}

// Loads `world` expecting an Error whose message starts with `where` and contains `what`.
void expect_error(const std::string& world, const std::string& where, const std::string& what) {
  testing::expect_load_error([&] { load(world); }, where, what, world);
}

using testing::expect_rgb_near;
using testing::expect_vec_near;

const char* kQuad = "Shape \"trianglemesh\" \"point3 P\" [ -1 -1 0  1 -1 0  1 1 0  -1 1 0 ] \"integer indices\" [ 0 1 2  0 2 3 ]\n";

TEST(PbrtMedia, HomogeneousWithPbrtDefaults) {
  std::vector<std::string> w;
  const Scene s = load(
      "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [ 0.1 0.2 0.3 ] \"rgb sigma_s\" [ 0.5 0.5 0.5 ]\n"
      "  \"float scale\" 2 \"float g\" 0.3\n"
      "MakeNamedMedium \"plain\" \"string type\" \"homogeneous\"\n"
      "MakeNamedMedium \"glow\" \"string type\" \"homogeneous\" \"rgb Le\" [ 1 1 1 ]\n"
      "Shape \"sphere\"\n",
      &w);
  ASSERT_EQ(s.media.media.size(), 3u);
  const Medium& fog = s.media.media[0];
  EXPECT_EQ(fog.type, MediumType::homogeneous);
  expect_rgb_near(fog.sigma_t, Rgb(1.2f, 1.4f, 1.6f));
  expect_rgb_near(fog.albedo, Rgb(1.f / 1.2f, 1.f / 1.4f, 1.f / 1.6f));
  EXPECT_FLOAT_EQ(fog.g, 0.3f);
  const Medium& plain = s.media.media[1];  // pbrt-v4: sigma_a = sigma_s = 1, g = 0
  expect_rgb_near(plain.sigma_t, Rgb(2.f));
  expect_rgb_near(plain.albedo, Rgb(0.5f));
  EXPECT_EQ(plain.g, 0.f);
  ASSERT_EQ(w.size(), 1u) << ::testing::PrintToString(w);
  EXPECT_NE(w[0].find("test.pbrt:8:52: warning: MakeNamedMedium \"glow\": emission (\"Le\") of media is not supported"), std::string::npos)
      << w[0];
  // Nothing binds the media: no shape, light or camera lies in one.
  EXPECT_TRUE(s.media.sphere_interfaces.empty());
  EXPECT_EQ(s.media.camera_medium, kVacuum);
}

TEST(PbrtMedia, MediumInterfaceBindsShapesAndLights) {
  const Scene s = load(
      "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
      "MakeNamedMedium \"smoke\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [ 2 2 2 ]\n"
      "AttributeBegin\n"
      "  MediumInterface \"fog\" \"\"\n"
      "  Material \"interface\"\n"
      "  Shape \"sphere\"\n" +  // sphere 0: fog inside
      std::string(kQuad) +      // triangles 0, 1: fog inside
      "  AttributeBegin\n"
      "    MediumInterface \"smoke\"\n"  // both sides smoke: no transition
      "    Material \"diffuse\"\n"
      "    Shape \"sphere\"\n"               // sphere 1
      "    LightSource \"point\"\n"          // light 0 in smoke
      "    AreaLightSource \"diffuse\"\n" +  // triangles 2, 3 and lights 1, 2: emit into smoke
      std::string(kQuad) +
      "  AttributeEnd\n"
      "  TransformBegin\n"
      "    MediumInterface \"smoke\" \"fog\"\n"  // TransformEnd restores the transform only
      "  TransformEnd\n"
      "  Shape \"sphere\"\n"  // sphere 2: smoke inside, fog outside
      "AttributeEnd\n"
      "Shape \"sphere\"\n"       // sphere 3: vacuum
      "LightSource \"point\"\n");  // light 3: vacuum
  ASSERT_EQ(s.spheres.size(), 4u);
  ASSERT_EQ(s.triangles.size(), 4u);
  ASSERT_EQ(s.lights.size(), 4u);
  const SceneMedia& m = s.media;
  ASSERT_EQ(m.sphere_interfaces.size(), 4u);
  EXPECT_EQ(m.sphere_interfaces[0].inside, 0);
  EXPECT_EQ(m.sphere_interfaces[0].outside, kVacuum);
  EXPECT_TRUE(m.sphere_interfaces[0].transition);
  EXPECT_FALSE(m.sphere_interfaces[1].transition);
  EXPECT_EQ(m.sphere_interfaces[2].inside, 1);
  EXPECT_EQ(m.sphere_interfaces[2].outside, 0);
  EXPECT_TRUE(m.sphere_interfaces[2].transition);
  EXPECT_FALSE(m.sphere_interfaces[3].transition);
  ASSERT_EQ(m.triangle_interfaces.size(), 4u);
  for (int t : {0, 1}) {
    EXPECT_EQ(m.triangle_interfaces[t].inside, 0);
    EXPECT_TRUE(m.triangle_interfaces[t].transition);
  }
  for (int t : {2, 3}) EXPECT_FALSE(m.triangle_interfaces[t].transition);
  ASSERT_EQ(m.light_media.size(), 4u);
  EXPECT_EQ(m.light_media[0], 1);
  EXPECT_EQ(m.light_media[1], 1);
  EXPECT_EQ(m.light_media[2], 1);
  EXPECT_EQ(m.light_media[3], kVacuum);
  // Material "interface": one material that only bounds media.
  EXPECT_EQ(s.materials[s.spheres[0].material].type, MaterialType::interface);
  EXPECT_EQ(s.materials[s.triangles[0].material].type, MaterialType::interface);
  EXPECT_EQ(s.spheres[0].material, s.spheres[2].material);
  EXPECT_EQ(s.materials[s.spheres[1].material].type, MaterialType::standard);
}

TEST(PbrtMedia, CameraMediumAndLateDefinitions) {
  LoadWarnings w(nullptr);
  // pbrt-v4's CameraMedium: the outside medium at Camera; the medium may be defined after it.
  const Scene s = pbrt::load_pbrt_string(
      "MediumInterface \"\" \"air\"\nCamera \"perspective\"\nMediumInterface \"\"\nWorldBegin\n"
      "MakeNamedMedium \"air\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [ 0.01 0.01 0.01 ] \"rgb sigma_s\" [ 0 0 0 ]\n"
      "Shape \"sphere\"\n",
      "cam.pbrt", "", {}, &w, nullptr);
  EXPECT_EQ(s.media.camera_medium, 0);
  EXPECT_TRUE(s.media.sphere_interfaces.empty());
  EXPECT_EQ(load("Shape \"sphere\"\n").media.camera_medium, kVacuum);
  // Instances keep the media of their definition.
  const Scene inst = load(
      "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
      "ObjectBegin \"ball\"\nMediumInterface \"fog\" \"\"\nMaterial \"interface\"\nShape \"sphere\"\nObjectEnd\n"
      "ObjectInstance \"ball\"\nTranslate 3 0 0\nObjectInstance \"ball\"\n");
  ASSERT_EQ(inst.media.sphere_interfaces.size(), 2u);
  EXPECT_EQ(inst.media.sphere_interfaces[1].inside, 0);
  EXPECT_TRUE(inst.media.sphere_interfaces[1].transition);
}

TEST(PbrtMedia, NamedInterfaceMaterial) {
  const Scene s = load("MakeNamedMaterial \"boundary\" \"string type\" \"interface\"\nNamedMaterial \"boundary\"\nShape \"sphere\"\n");
  ASSERT_EQ(s.spheres.size(), 1u);
  EXPECT_EQ(s.materials[s.spheres[0].material].type, MaterialType::interface);
}

// pbrt-v4's subsurface material: a dielectric boundary around its own homogeneous medium, bound
// inside the shapes that use it (outside: the graphics state's outside medium).
TEST(PbrtMedia, SubsurfaceIsADielectricAroundItsMedium) {
  const Scene s = load(
      "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
      "MakeNamedMaterial \"skin\" \"string type\" \"subsurface\" \"float eta\" 1.4 \"rgb sigma_a\" [ 0.1 0.2 0.3 ]\n"
      "  \"rgb sigma_s\" [ 1 2 3 ] \"float scale\" 10 \"float g\" 0.2\n"
      "NamedMaterial \"skin\"\n"
      "Shape \"sphere\"\n"
      "MediumInterface \"\" \"fog\"\n"
      "Material \"subsurface\"\n"
      "Shape \"sphere\"\n");
  ASSERT_EQ(s.media.media.size(), 3u);  // fog, skin's interior, the default subsurface's interior
  ASSERT_EQ(s.spheres.size(), 2u);
  const Material& skin = s.materials[s.spheres[0].material];
  EXPECT_EQ(skin.type, MaterialType::standard);
  EXPECT_FLOAT_EQ(skin.ior, 1.4f);
  const MediumInterface a = s.media.sphere_interfaces.at(0), b = s.media.sphere_interfaces.at(1);
  ASSERT_TRUE(a.transition);
  EXPECT_EQ(a.outside, kVacuum);
  const Medium& inside = s.media.media[size_t(a.inside)];
  expect_rgb_near(inside.sigma_t, Rgb(11.f, 22.f, 33.f), 1e-4f);
  EXPECT_FLOAT_EQ(inside.g, 0.2f);
  ASSERT_TRUE(b.transition);
  EXPECT_EQ(b.outside, 0);  // fog
  expect_rgb_near(s.media.media[size_t(b.inside)].sigma_t, Rgb(2.5511f, 3.2124f, 3.784f), 1e-4f);  // pbrt-v4's defaults
  EXPECT_FLOAT_EQ(s.materials[s.spheres[1].material].ior, 1.33f);
  expect_error("Material \"subsurface\"\n  \"float mfp\" 1\nShape \"sphere\"\n", "test.pbrt:6:3:", "\"mfp\" is not supported");
  expect_error("Material \"subsurface\" \"float g\" 1\nShape \"sphere\"\n", "test.pbrt:5:1:", "g must lie in (-1, 1)");
}

TEST(PbrtMedia, UniformGridPlacedByItsTransform) {
  const Scene s = load(
      "AttributeBegin\n  Translate 1 2 3\n  Scale 2 2 2\n"
      "  MakeNamedMedium \"cloud\" \"string type\" \"uniformgrid\" \"integer nx\" 2 \"integer ny\" 1 \"integer nz\" 3\n"
      "    \"float density\" [ 0 1 2 3 4 5 ] \"point3 p0\" [ -1 -1 -1 ] \"point3 p1\" [ 1 1 1 ]\n"
      "    \"rgb sigma_a\" [ 1 1 1 ] \"rgb sigma_s\" [ 3 3 3 ] \"float scale\" 0.5 \"float g\" -0.2\n"
      "AttributeEnd\n"
      "MakeNamedMedium \"unit\" \"string type\" \"uniformgrid\" \"float density\" [ 7 ]\n"
      "Shape \"sphere\"\n");
  ASSERT_EQ(s.media.media.size(), 2u);
  const Medium& m = s.media.media[0];
  EXPECT_EQ(m.type, MediumType::grid);
  expect_rgb_near(m.sigma_t, Rgb(2.f));  // (sigma_a + sigma_s) * scale
  expect_rgb_near(m.albedo, Rgb(0.75f));
  EXPECT_FLOAT_EQ(m.g, -0.2f);
  EXPECT_EQ(m.density.nx, 2u);
  EXPECT_EQ(m.density.ny, 1u);
  EXPECT_EQ(m.density.nz, 3u);
  EXPECT_EQ(m.density.channels, 1u);
  for (uint32_t i = 0; i < 6; ++i) EXPECT_EQ(s.media.grid_values[m.density.offset + i], float(i));
  // The box's corners (medium space -1 and 1 under Translate * Scale) are the unit cube's.
  expect_vec_near(grid_point(m, Vec3(-1, 0, 1)), Vec3(0, 0, 0));
  expect_vec_near(grid_point(m, Vec3(3, 4, 5)), Vec3(1, 1, 1));
  expect_vec_near(grid_point(m, Vec3(1, 2, 3)), Vec3(0.5f, 0.5f, 0.5f));
  // At sample (1, 0, 2)'s centre the grid holds its value, x fastest: 2 * 5.
  const Vec3 centre(1.5f / 2.f, 0.5f, 2.5f / 3.f);
  expect_rgb_near(medium_sigma_t(m, s.media.grid_values.data(), centre), Rgb(10.f), 1e-4f);
  // Defaults: nx = ny = nz = 1, the unit cube, sigma_a = sigma_s = 1.
  const Medium& unit = s.media.media[1];
  EXPECT_EQ(unit.density.nx, 1u);
  expect_rgb_near(unit.sigma_t, Rgb(2.f));
  expect_vec_near(grid_point(unit, Vec3(0.25f, 0.5f, 1.f)), Vec3(0.25f, 0.5f, 1.f));
}

TEST(PbrtMedia, RgbGrid) {
  const Scene s = load(
      "MakeNamedMedium \"tint\" \"string type\" \"rgbgrid\" \"integer nz\" 2 \"float scale\" 2\n"
      "  \"rgb sigma_a\" [ 0.1 0.2 0.3  1 1 1 ] \"rgb sigma_s\" [ 0.3 0.2 0.1  0 0 0 ]\n"
      "MakeNamedMedium \"half\" \"string type\" \"rgbgrid\" \"rgb sigma_s\" [ 3 1 0 ]\n"
      "Shape \"sphere\"\n");
  ASSERT_EQ(s.media.media.size(), 2u);
  const Medium& m = s.media.media[0];
  EXPECT_EQ(m.type, MediumType::grid);
  expect_rgb_near(m.sigma_t, Rgb(2.f));
  EXPECT_EQ(m.density.channels, 3u);
  EXPECT_EQ(m.density.nz, 2u);
  const float* v = s.media.grid_values.data();
  const float density[6] = {0.4f, 0.4f, 0.4f, 1.f, 1.f, 1.f}, albedo[6] = {0.75f, 0.5f, 0.25f, 0.f, 0.f, 0.f};
  ASSERT_EQ(m.albedo_grid.nz, 2u);
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(v[m.density.offset + i], density[i], 1e-6f);
    EXPECT_NEAR(v[m.albedo_grid.offset + i], albedo[i], 1e-6f);
  }
  // A grid not given is 1 everywhere (pbrt-v4's RGBGridMedium).
  const Medium& half = s.media.media[1];
  EXPECT_NEAR(v[half.density.offset], 4.f, 1e-6f);
  EXPECT_NEAR(v[half.density.offset + 2], 1.f, 1e-6f);
  EXPECT_NEAR(v[half.albedo_grid.offset], 0.75f, 1e-6f);
  EXPECT_NEAR(v[half.albedo_grid.offset + 2], 0.f, 1e-6f);
}

TEST(PbrtMedia, BadMediaAreErrorsWithTheirLocation) {
  const std::string fog = "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n";
  expect_error("MediumInterface \"nope\" \"\"\nShape \"sphere\"\n", "test.pbrt:5:1:", "medium \"nope\" is not defined");
  expect_error(fog + "MediumInterface \"fog\" \"fgo\"\n", "test.pbrt:6:1:", "medium \"fgo\" is not defined");
  expect_error("MakeNamedMedium \"m\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [ -1 0 0 ]\n", "test.pbrt:5:49:",
               "\"sigma_a\" must be finite and >= 0");
  expect_error("MakeNamedMedium \"m\" \"string type\" \"homogeneous\" \"float scale\" -2\n", "test.pbrt:5:49:", "\"scale\"");
  expect_error("MakeNamedMedium \"m\" \"string type\" \"homogeneous\" \"float g\" 1\n", "test.pbrt:5:49:", "must lie in (-1, 1)");
  expect_error("MakeNamedMedium \"m\" \"string type\" \"homogeneous\" \"string preset\" \"Ketchup\"\n", "test.pbrt:5:49:",
               "\"preset\" is not supported");
  expect_error(fog + fog, "test.pbrt:6:1:", "named medium \"fog\" redefined");
  expect_error("MakeNamedMedium \"m\" \"string type\" \"cloud\"\n", "test.pbrt:5:1:", "medium type \"cloud\" is not supported");
  expect_error("MakeNamedMedium \"m\"\n", "test.pbrt:5:1:", "has no \"string type\"");
  const std::string grid = "MakeNamedMedium \"g\" \"string type\" \"uniformgrid\" ";
  expect_error(grid + "\"integer nx\" 2 \"float density\" [ 1 2 3 ]\n", "test.pbrt:5:64:", "has 3 values; nx * ny * nz = 2 x 1 x 1 asks for 2");
  expect_error(grid + "\"integer nx\" 0 \"float density\" [ 1 ]\n", "test.pbrt:5:49:", "\"nx\" must be >= 1");
  expect_error(grid + "\"float density\" [ 1 -2 ] \"integer ny\" 2\n", "test.pbrt:5:49:", "value 1 is -2");
  expect_error(grid + "\"float density\" [ nan ]\n", "test.pbrt:5:67:", "not finite");
  expect_error(grid + "\"integer nx\" 1\n", "test.pbrt:5:1:", "needs \"float density\"");
  expect_error(grid + "\"float density\" [ 1 ] \"point3 p1\" [ 1 0 1 ]\n", "test.pbrt:5:1:", "flat");
  expect_error("MakeNamedMedium \"r\" \"string type\" \"rgbgrid\" \"integer nx\" 2 \"rgb sigma_a\" [ 1 1 1 ]\n", "test.pbrt:5:60:",
               "has 3 values; nx * ny * nz = 2 x 1 x 1 asks for 6");
  expect_error("MakeNamedMedium \"r\" \"string type\" \"rgbgrid\"\n", "test.pbrt:5:1:", "needs \"rgb sigma_a\" and/or \"rgb sigma_s\"");
}

}  // namespace
}  // namespace pathspace
