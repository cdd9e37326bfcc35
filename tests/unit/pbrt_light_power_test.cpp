// pbrt-v4's "power" and "illuminance" light parameters (io/pbrt/pbrt_builder_lights.cpp, pbrt_builder_shapes.cpp): a point
// light of power P has intensity I P / (4 pi); a spot divides by its cone's solid angle with the
// smoothstep ramp counted at half; an area light's every pbrt shape (each triangle of a triangle
// mesh, a whole sphere or disk) emits P, cosine-distributed; a projection light's image is scaled to
// P (times "scale", as pbrt-v4); a distant light's "illuminance" is its irradiance and a uniform
// infinite light's is pi L. The emitted powers are checked through Scene::light_power.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/io/image_io.h"
#include "pathspace/io/pbrt/pbrt_scene_builder.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

Scene load_world(const std::string& world, const std::string& folder = ".") {
  std::vector<std::string> w;
  LoadWarnings lw(&w);
  Scene s = pbrt::load_pbrt_string("LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n" + world, "p.pbrt", folder, {}, &lw,
                                   nullptr);
  for (const std::string& m : w) EXPECT_EQ(m.find("power"), std::string::npos) << m;
  return s;
}

TEST(PbrtLightPower, PointAndSpotEmitTheirPower) {
  const Scene p = load_world("LightSource \"point\" \"rgb I\" [ 2 2 2 ] \"float power\" 100\nShape \"sphere\"\n");
  EXPECT_NEAR(p.lights[0].value.g, 2.f * 100.f / float(4.0 * M_PI), 1e-4f);
  EXPECT_NEAR(p.light_power(0), 2.f * 100.f, 1e-2f);  // pbrt-v4 keeps the RGB's own luminance as a factor
  const Scene s = load_world("LightSource \"spot\" \"rgb I\" [ 1 1 1 ] \"float coneangle\" 30 \"float conedelta\" 10 \"float power\" 50\n"
                             "Shape \"sphere\"\n");
  EXPECT_NEAR(s.light_power(0), 50.f, 1e-3f * 50.f);
}

TEST(PbrtLightPower, AreaLightsEmitTheirPowerPerShape) {
  // Two triangles of areas 0.5 and 2: pbrt-v4 makes each its own shape, so each emits the power.
  const Scene m = load_world(
      "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [ 1 1 1 ] \"float power\" 10\n"
      "Shape \"trianglemesh\" \"point3 P\" [ 0 0 0 1 0 0 0 1 0  0 0 1  2 0 1  0 2 1 ] \"integer indices\" [ 0 1 2 3 4 5 ]\nAttributeEnd\n");
  ASSERT_EQ(m.lights.size(), 2u);
  EXPECT_NEAR(m.lights[0].value.r, 10.f / (float(M_PI) * 0.5f), 1e-4f);
  EXPECT_NEAR(m.lights[1].value.r, 10.f / (float(M_PI) * 2.f), 1e-4f);
  // A sphere is one shape; a scaled one too (its world area counts).
  const Scene s = load_world(
      "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [ 1 1 1 ] \"float power\" 10\nScale 2 2 2\nShape \"sphere\" \"float radius\" 0.5\n"
      "AttributeEnd\n");
  EXPECT_NEAR(s.light_power(0), 10.f, 1e-3f);
  // A disk is one shape however many triangles it becomes.
  const Scene d = load_world(
      "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [ 1 1 1 ] \"float power\" 10 \"bool twosided\" true\n"
      "Shape \"disk\" \"float radius\" 2\nAttributeEnd\n");
  double total = 0.0;
  for (size_t i = 0; i < d.lights.size(); ++i) total += d.light_power(i);
  EXPECT_GT(d.lights.size(), 8u);
  EXPECT_NEAR(total, 10.0, 1e-3);
}

TEST(PbrtLightPower, DistantAndInfiniteIlluminance) {
  const Scene d = load_world("LightSource \"distant\" \"rgb L\" [ 1 1 1 ] \"float illuminance\" 3\nShape \"sphere\"\n");
  EXPECT_NEAR(d.lights[0].value.r, 3.f, 1e-6f);
  const Scene i = load_world("LightSource \"infinite\" \"rgb L\" [ 1 1 1 ] \"float illuminance\" 3\nShape \"sphere\"\n");
  EXPECT_NEAR(i.lights[0].value.r, 3.f / float(M_PI), 1e-6f);
}

TEST(PbrtLightPower, ProjectionLightEmitsScaleTimesPower) {
  const testing::TempDir dir("power");
  Image img(4, 2);
  for (size_t k = 0; k < img.pixels.size(); ++k) img.pixels[k] = Rgb(0.1f * float(k + 1));
  write_image(dir.file("slide.exr"), img);
  const Scene s = load_world("LightSource \"projection\" \"string filename\" \"slide.exr\" \"float power\" 20 \"float scale\" 1.5\n"
                             "Shape \"sphere\"\n",
                             dir.path.string());
  EXPECT_NEAR(s.light_power(0), 1.5f * 20.f, 1e-3f * 30.f);
  EXPECT_THROW(load_world("LightSource \"point\" \"float power\" 1e999\n"), Error);
}

}  // namespace
}  // namespace pathspace
