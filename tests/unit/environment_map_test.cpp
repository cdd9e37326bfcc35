// Environment maps (lights/environment_map.h): direction <-> uv round trips for both mappings, the
// documented conventions (a bright texel seen in the expected world direction, with and without a
// to_world frame), and the loaders (pbrt-v4 equal-area and pbrt-v3 lat-long, Mitsuba envmap).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "pathspace/io/image_io.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/scene/environment_light.h"
#include "pathspace/sampling/rng.h"
#include "pathspace/scene/environment_image.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

constexpr EnvironmentMapping kMappings[] = {EnvironmentMapping::lat_long, EnvironmentMapping::equal_area};

TEST(EnvironmentMap, UvToDirectionRoundTrips) {
  for (EnvironmentMapping m : kMappings) {
    for (int j = 0; j < 40; ++j)
      for (int i = 0; i < 40; ++i) {
        const Point2 uv{(float(i) + 0.37f) / 40.f, (float(j) + 0.61f) / 40.f};
        const Vec3 d = envmap_uv_to_direction(m, uv);
        EXPECT_NEAR(length(d), 1.f, 1e-5f);
        const Point2 back = envmap_direction_to_uv(m, d);
        EXPECT_NEAR(back.x, uv.x, 2e-5f) << int(m) << " " << uv.x << " " << uv.y;
        EXPECT_NEAR(back.y, uv.y, 2e-5f) << int(m) << " " << uv.x << " " << uv.y;
      }
  }
}

TEST(EnvironmentMap, DirectionToUvRoundTrips) {
  Pcg32 rng(7, 1);
  for (EnvironmentMapping m : kMappings)
    for (int k = 0; k < 2000; ++k) {
      const Vec3 d = square_to_uniform_sphere({rng.next_float(), rng.next_float()});
      const Vec3 back = envmap_uv_to_direction(m, envmap_direction_to_uv(m, d));
      EXPECT_LT(length(back - d), 3e-5f) << int(m);
    }
}

// Fixed points of the conventions, written out independently of the code.
TEST(EnvironmentMap, ConventionAnchors) {
  auto near = [](const Vec3& a, const Vec3& b) { return length(a - b) < 1e-5f; };
  using M = EnvironmentMapping;
  // Mitsuba lat-long: v = 0 is up (+y), u = 0.5 at the horizon looks along +z, u = 0 along -z,
  // u = 0.25 along +x.
  EXPECT_TRUE(near(envmap_uv_to_direction(M::lat_long, {0.3f, 0.f}), Vec3(0, 1, 0)));
  EXPECT_TRUE(near(envmap_uv_to_direction(M::lat_long, {0.5f, 0.5f}), Vec3(0, 0, 1)));
  EXPECT_TRUE(near(envmap_uv_to_direction(M::lat_long, {0.f, 0.5f}), Vec3(0, 0, -1)));
  EXPECT_TRUE(near(envmap_uv_to_direction(M::lat_long, {0.25f, 0.5f}), Vec3(1, 0, 0)));
  // pbrt-v4 equal-area: centre +z, corners -z, edge midpoints (1, .5) +x and (.5, 1) +y.
  EXPECT_TRUE(near(envmap_uv_to_direction(M::equal_area, {0.5f, 0.5f}), Vec3(0, 0, 1)));
  EXPECT_TRUE(near(envmap_uv_to_direction(M::equal_area, {1.f, 1.f}), Vec3(0, 0, -1)));
  EXPECT_TRUE(near(envmap_uv_to_direction(M::equal_area, {1.f, 0.5f}), Vec3(1, 0, 0)));
  EXPECT_TRUE(near(envmap_uv_to_direction(M::equal_area, {0.5f, 1.f}), Vec3(0, 1, 0)));
  EXPECT_TRUE(near(envmap_uv_to_direction(M::equal_area, {0.f, 0.5f}), Vec3(-1, 0, 0)));
}

EnvironmentImage one_bright_texel(EnvironmentMapping m, int w, int h, int bx, int by) {
  EnvironmentImage e;
  e.name = "test";
  e.width = w;
  e.height = h;
  e.mapping = m;
  e.texels.assign(size_t(w * h), Rgb());
  e.texels[size_t(by * w + bx)] = Rgb(5.f, 6.f, 7.f);
  return e;
}

// The bright texel (row 0 at the top) is seen in the direction of its centre, after to_world.
TEST(EnvironmentMap, BrightTexelSeenInExpectedDirection) {
  // Lat-long 16 x 8, texel (5, 2): phi = 2 pi 5.5/16, theta = pi 2.5/8, local y up.
  {
    EnvironmentImage e = one_bright_texel(EnvironmentMapping::lat_long, 16, 8, 5, 2);
    // to_world: local x -> world x, local y (up) -> world z, local z -> world -y.
    e.axis_x = Vec3(1, 0, 0);
    e.axis_y = Vec3(0, 0, 1);
    e.axis_z = Vec3(0, -1, 0);
    e.prepare();
    const EnvironmentMapView v = e.view();
    const double phi = 2 * M_PI * 5.5 / 16, theta = M_PI * 2.5 / 8;
    const Vec3 local(float(std::sin(phi) * std::sin(theta)), float(std::cos(theta)), float(-std::cos(phi) * std::sin(theta)));
    const Vec3 world(local.x, -local.z, local.y);
    const Rgb c = envmap_radiance(v, world);
    EXPECT_NEAR(c.r, 5.f, 1e-3f);
    EXPECT_NEAR(c.b, 7.f, 1e-3f);
    EXPECT_TRUE(is_black(envmap_radiance(v, local)));  // the untransformed direction is dark
    EXPECT_TRUE(is_black(envmap_radiance(v, Vec3(world.x, world.y, -world.z))));
  }
  // Equal-area 8 x 8, texel (6, 3): the direction of its centre under pbrt-v4's mapping.
  {
    EnvironmentImage e = one_bright_texel(EnvironmentMapping::equal_area, 8, 8, 6, 3);
    e.prepare();
    const EnvironmentMapView v = e.view();
    const Vec3 d = envmap_uv_to_direction(EnvironmentMapping::equal_area, {6.5f / 8.f, 3.5f / 8.f});
    // Texel centre (6.5, 3.5)/8: u' = 0.625, v' = -0.125, so r = 0.75 (upper half), phi = pi/8 * ...
    const double r = 0.75, phi = (0.125 - 0.625) / r + 1.0;  // in units of pi/4
    const Vec3 expected(float(std::cos(phi * M_PI / 4) * r * std::sqrt(2 - r * r)),
                        float(-std::sin(phi * M_PI / 4) * r * std::sqrt(2 - r * r)), float(1 - r * r));
    EXPECT_LT(length(d - expected), 1e-5f);
    EXPECT_EQ(envmap_radiance(v, d), Rgb(5.f, 6.f, 7.f));
    EXPECT_TRUE(is_black(envmap_radiance(v, Vec3(d.x, d.y, -d.z))));
  }
}

// Writes a w x h PFM whose only bright texel is (bx, by).
std::string write_map(const testing::TempDir& dir, const std::string& name, int w, int h, int bx, int by) {
  Image img(w, h);
  img.at(bx, by) = Rgb(3.f, 3.f, 3.f);
  const std::string path = dir.file(name);
  write_image(path, img);
  return path;
}

const char* kCamera = "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 45\nFilm \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n";

Scene load_text(const testing::TempDir& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir.file(name)) << text;
  std::vector<std::string> warnings;
  return load_scene(dir.file(name), {}, &warnings);
}

TEST(EnvironmentMapLoaders, PbrtEqualAreaWithTransform) {
  testing::TempDir dir("envmap");
  write_map(dir, "sky.pfm", 8, 8, 6, 3);
  const Scene s = load_text(dir, "a.pbrt",
                            std::string(kCamera) + "WorldBegin\nAttributeBegin\nRotate 90 1 0 0\n"
                                                   "LightSource \"infinite\" \"string filename\" \"sky.pfm\" \"float scale\" 2\n"
                                                   "AttributeEnd\nShape \"sphere\" \"float radius\" 0.1\n");
  const SceneView v = s.view();
  ASSERT_GE(v.environment_light, 0);
  ASSERT_TRUE(v.environment_map.texels);
  const Vec3 d = envmap_uv_to_direction(EnvironmentMapping::equal_area, {6.5f / 8.f, 3.5f / 8.f});
  const Vec3 world(d.x, -d.z, d.y);  // Rotate 90 about x: y -> z, z -> -y
  EXPECT_EQ(environment_radiance(v, v.lights[v.environment_light], world), Rgb(6.f));
  EXPECT_TRUE(is_black(environment_radiance(v, v.lights[v.environment_light], d)));
}

TEST(EnvironmentMapLoaders, PbrtNonSquareIsPbrtV3LatLong) {
  testing::TempDir dir("envmap");
  write_map(dir, "sky.pfm", 16, 8, 4, 2);  // phi = 2 pi 4.5/16, theta = pi 2.5/8 about +z
  std::ofstream(dir.file("a.pbrt")) << kCamera << "WorldBegin\nLightSource \"infinite\" \"string filename\" \"sky.pfm\"\n"
                                    << "Shape \"sphere\" \"float radius\" 0.1\n";
  std::vector<std::string> warnings;
  const Scene s = load_scene(dir.file("a.pbrt"), {}, &warnings);
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings[0].find("lat-long"), std::string::npos) << warnings[0];
  const SceneView v = s.view();
  const double phi = 2 * M_PI * 4.5 / 16, theta = M_PI * 2.5 / 8;
  const Vec3 w(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)));
  EXPECT_NEAR(environment_radiance(v, v.lights[v.environment_light], w).r, 3.f, 1e-3f);
  EXPECT_TRUE(is_black(environment_radiance(v, v.lights[v.environment_light], -w)));
}

TEST(EnvironmentMapLoaders, MitsubaEnvmapWithToWorld) {
  testing::TempDir dir("envmap");
  write_map(dir, "sky.pfm", 16, 8, 5, 2);
  const Scene s = load_text(dir, "a.xml",
                            "<scene version=\"3.0.0\">\n"
                            "<sensor type=\"perspective\"><film type=\"hdrfilm\"><integer name=\"width\" value=\"8\"/>"
                            "<integer name=\"height\" value=\"8\"/></film></sensor>\n"
                            "<emitter type=\"envmap\"><string name=\"filename\" value=\"sky.pfm\"/>"
                            "<float name=\"scale\" value=\"0.5\"/>"
                            "<transform name=\"to_world\"><rotate x=\"1\" angle=\"90\"/></transform></emitter>\n"
                            "<shape type=\"sphere\"><float name=\"radius\" value=\"0.1\"/></shape>\n"
                            "</scene>\n");
  const SceneView v = s.view();
  ASSERT_TRUE(v.environment_map.texels);
  const double phi = 2 * M_PI * 5.5 / 16, theta = M_PI * 2.5 / 8;
  const Vec3 local(float(std::sin(phi) * std::sin(theta)), float(std::cos(theta)), float(-std::cos(phi) * std::sin(theta)));
  const Vec3 world(local.x, -local.z, local.y);  // rotate 90 about x
  EXPECT_NEAR(environment_radiance(v, v.lights[v.environment_light], world).g, 1.5f, 1e-3f);
  EXPECT_TRUE(is_black(environment_radiance(v, v.lights[v.environment_light], local)));
}

}  // namespace
}  // namespace pathspace
