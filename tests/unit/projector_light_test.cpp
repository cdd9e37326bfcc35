// Lights with images (scene/point_light_intensity.h): Mitsuba's projector lights a plane at
// distance 1 with irradiance pi * scale * image(uv), u running against the frame's x and v along
// its y; pbrt-v4's projection light has intensity scale * image, the image's top row towards -y;
// nothing leaves a projector outside its frustum; the emission pdf equals the sampled density and
// the mean emission weight is the light's power (t-tests at alpha 1e-3), which matches the closed
// forms (Mitsuba: pi scale E 4 tan_u tan_v; pbrt: scale c times the frustum's solid angle);
// Mitsuba's spot fades linearly in the angle and carries its image over the cone; the loaders.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/io/image_io.h"
#include "pathspace/io/mitsuba/mitsuba_loader.h"
#include "pathspace/io/pbrt/pbrt_scene_builder.h"
#include "pathspace/sampling/rng.h"
#include "pathspace/scene/light_emission.h"
#include "support/statistics.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

using testing::TempDir;

// A 2x2 image, distinct texels: (0, 0) top left.
ImageTexture four_texels(bool nearest) {
  ImageTexture t;
  t.name = "four";
  t.width = t.height = 2;
  t.texels = {Rgb(1, 0, 0), Rgb(0, 1, 0), Rgb(0, 0, 1), Rgb(1, 1, 0)};  // top row first
  t.nearest = nearest;
  return t;
}

// A projector at the origin looking along +z (u axis +x, v axis +y), half-angle tangents 0.5 and 0.25.
Scene projector_scene(bool irradiance_plane, bool textured) {
  Scene s;
  s.camera.width = s.camera.height = 1;
  const int32_t tex = textured ? int32_t(s.add_texture(four_texels(true))) : -1;
  s.add_projector_light(Vec3(), Frame(Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)), Rgb(2.f), tex, -0.5f / 0.5f,
                        0.5f / 0.25f, irradiance_plane);
  s.finalize();
  return s;
}

// Irradiance on the plane z = 1 at (x, y) by next event estimation.
Rgb irradiance_at(const Scene& s, float x, float y) {
  LightSample ls;
  const Vec3 p(x, y, 1.f);
  if (!sample_light(s.view(), s.lights[0], p, 0.f, {0.5f, 0.5f}, &ls)) return Rgb();
  return ls.li * std::fabs(ls.wi.z);
}

void expect_rgb_near(const Rgb& a, const Rgb& b) {
  EXPECT_NEAR(a.r, b.r, 1e-5f);
  EXPECT_NEAR(a.g, b.g, 1e-5f);
  EXPECT_NEAR(a.b, b.b, 1e-5f);
}

TEST(ProjectorLight, MitsubaProjectorLightsItsPlaneWithTheImage) {
  const Scene s = projector_scene(true, true);
  // u = 0.5 - x / (2 tan_u), v = 0.5 + y / (2 tan_v); v = 1 is the image's top row.
  expect_rgb_near(irradiance_at(s, 0.25f, 0.125f), Rgb(2, 0, 0));    // u 0.25, v 0.75: top left
  expect_rgb_near(irradiance_at(s, -0.25f, 0.125f), Rgb(0, 2, 0));   // top right
  expect_rgb_near(irradiance_at(s, 0.25f, -0.125f), Rgb(0, 0, 2));   // bottom left
  expect_rgb_near(irradiance_at(s, -0.4f, -0.2f), Rgb(2, 2, 0));     // bottom right, far from the axis: still exact
  EXPECT_EQ(irradiance_at(s, 0.6f, 0.f), Rgb());               // outside the frustum
  EXPECT_EQ(irradiance_at(s, 0.f, 0.3f), Rgb());
  LightSample ls;
  EXPECT_FALSE(sample_light(s.view(), s.lights[0], Vec3(0, 0, -1), 0.f, {0.5f, 0.5f}, &ls));  // behind
  // A constant image lights the plane evenly.
  const Scene c = projector_scene(true, false);
  for (float x : {0.f, 0.2f, -0.45f}) EXPECT_NEAR(irradiance_at(c, x, 0.2f).g, 2.f, 1e-5f);
}

TEST(ProjectorLight, PbrtProjectionHasTheImageAsIntensity) {
  const Scene s = projector_scene(false, false);
  // I = value: the plane's irradiance falls with cos^3.
  const float x = 0.4f, y = 0.2f, c = 1.f / std::sqrt(1.f + x * x + y * y);
  EXPECT_NEAR(irradiance_at(s, x, y).r, 2.f * c * c * c, 1e-5f);
}

// E[weight] of sample_emission is the light's power, and emission_pdf agrees with the sampled pdf.
void expect_emission_carries_power(const Scene& s, double power, const std::string& what) {
  SCOPED_TRACE(what);
  const SceneView v = s.view();
  const Light& l = s.lights[0];
  Pcg32 rng(11, 5);
  const int n = 200000;
  double sum = 0, sum_sq = 0;
  for (int i = 0; i < n; ++i) {
    EmissionSample e;
    const Point2 up{rng.next_float(), rng.next_float()}, ud{rng.next_float(), rng.next_float()};
    if (sample_emission(v, l, 0.f, up, ud, &e)) {
      float pa, pw;
      emission_pdf(v, l, e.p, e.n, e.d, 0.f, &pa, &pw);
      ASSERT_NEAR(pw, e.pdf_w, 1e-4f * e.pdf_w);
      sum += luminance(e.weight);
      sum_sq += double(luminance(e.weight)) * luminance(e.weight);
    }
  }
  const testing::MeanTest t = testing::t_test_mean(sum, sum_sq, n, power);
  if (t.std_error < 1e-6 * power) {
    EXPECT_NEAR(t.mean, power, 1e-5 * power);  // every weight equal (a constant Mitsuba projector): no noise to test
  } else {
    EXPECT_GT(t.p, 1e-3) << "mean flux " << t.mean << " vs " << power;
  }
  EXPECT_NEAR(s.light_power(0), power, 2e-3 * power);
}

TEST(ProjectorLight, EmissionCarriesThePower) {
  // Mitsuba: the plane at distance 1 receives pi E over its 4 tan_u tan_v: power 2 * 4 * 0.5 * 0.25 (luminance of grey 2).
  expect_emission_carries_power(projector_scene(true, false), 2.0 * 4.0 * 0.5 * 0.25, "mitsuba, constant");
  // pbrt: value times the frustum's solid angle, 4 asin(sin a sin b).
  const double a = std::atan(0.5), b = std::atan(0.25);
  expect_emission_carries_power(projector_scene(false, false), 2.0 * 4.0 * std::asin(std::sin(a) * std::sin(b)), "pbrt, constant");
  // The image's mean luminance over the plane (each texel a quarter of it).
  double mean_y = 0;
  for (const Rgb& c : four_texels(true).texels) mean_y += 0.25 * luminance(c);
  expect_emission_carries_power(projector_scene(true, true), 2.0 * 4.0 * 0.5 * 0.25 * mean_y, "mitsuba, image");
}

TEST(ProjectorLight, MitsubaSpotFadesLinearlyAndCarriesItsImage) {
  Scene s;
  s.camera.width = s.camera.height = 1;
  const float beam = 10.f, cutoff = 30.f;
  s.add_spot_light(Vec3(), Vec3(0, 0, 1), Rgb(3.f), std::cos(cutoff * float(M_PI) / 180.f), std::cos(beam * float(M_PI) / 180.f));
  s.lights[0].falloff = SpotFalloff::linear_angle;
  s.finalize();
  const Light& l = s.lights[0];
  const auto dir = [](float deg) { return Vec3(std::sin(deg * float(M_PI) / 180.f), 0.f, std::cos(deg * float(M_PI) / 180.f)); };
  EXPECT_NEAR(spot_falloff(l, dir(20.f)), 0.5f, 1e-5f);
  EXPECT_NEAR(spot_falloff(l, dir(25.f)), 0.25f, 1e-5f);
  EXPECT_EQ(spot_falloff(l, dir(5.f)), 1.f);
  EXPECT_EQ(spot_falloff(l, dir(31.f)), 0.f);
  // Power: 2 pi I [(1 - cos b) + ((g - b) cos b + sin b - sin g) / (g - b)], b beam, g cutoff.
  const double b = beam * M_PI / 180.0, g = cutoff * M_PI / 180.0;
  const double power = 2.0 * M_PI * 3.0 * ((1.0 - std::cos(b)) + ((g - b) * std::cos(b) + std::sin(b) - std::sin(g)) / (g - b));
  expect_emission_carries_power(s, power, "mitsuba spot");

  // An image over the cone: uv = 0.5 + 0.5 (x, -y) / (z tan cutoff) (v flipped: v = 1 is the top row).
  Scene t = s;
  t.lights[0].texture = int32_t(t.add_texture(four_texels(true)));
  t.lights[0].axis_u = Vec3(1, 0, 0);
  t.lights[0].axis_v = Vec3(0, 1, 0);
  t.lights[0].uv_scale_u = 0.5f / std::tan(float(g));
  t.lights[0].uv_scale_v = -0.5f / std::tan(float(g));
  t.finalize();
  const Vec3 w = normalize(Vec3(-0.05f, 0.05f, 1.f));  // u < 0.5, v < 0.5: the bottom left texel
  expect_rgb_near(point_light_intensity(t.view(), t.lights[0], w), Rgb(0, 0, 3));
}

TEST(ProjectorLight, MitsubaLoader) {
  const TempDir dir("projector");
  Image img(4, 2);
  for (Rgb& p : img.pixels) p = Rgb(0.5f);
  write_image(dir.file("slide.exr"), img);
  std::vector<std::string> warnings;
  LoadWarnings lw(&warnings);
  const std::string text =
      "<scene version=\"3.0.0\"><sensor type=\"perspective\"/>\n"
      "<emitter type=\"projector\"><texture type=\"bitmap\" name=\"irradiance\"><string name=\"filename\" value=\"slide.exr\"/>"
      "</texture><float name=\"fov\" value=\"60\"/><float name=\"scale\" value=\"2\"/>"
      "<transform name=\"to_world\"><translate x=\"1\"/></transform></emitter>\n"
      "<emitter type=\"spot\"><texture type=\"bitmap\" name=\"texture\"><string name=\"filename\" value=\"slide.exr\"/></texture>"
      "<float name=\"cutoff_angle\" value=\"30\"/></emitter>\n</scene>\n";
  const Scene s = mitsuba::load_mitsuba_string(text, "scene.xml", dir.path.string(), {}, &lw, nullptr);
  ASSERT_EQ(s.lights.size(), 2u);
  const Light& p = s.lights[0];
  EXPECT_EQ(p.type, LightType::projector);
  EXPECT_TRUE(p.irradiance_plane);
  EXPECT_NEAR(p.value.r, 2.f * float(M_PI), 1e-5f);
  EXPECT_NEAR(p.position.x, 1.f, 1e-6f);
  const double tx = std::tan(30.0 * M_PI / 180.0);  // fov along x; the image is twice as wide as tall
  EXPECT_NEAR(p.uv_scale_u, -0.5 / tx, 1e-5);
  EXPECT_NEAR(p.uv_scale_v, 0.5 / (tx / 2.0), 1e-5);
  const Light& spot = s.lights[1];
  EXPECT_GE(spot.texture, 0);
  EXPECT_EQ(spot.falloff, SpotFalloff::linear_angle);
  EXPECT_THROW(mitsuba::load_mitsuba_string("<scene version=\"3.0.0\"><emitter type=\"projector\"/></scene>", "scene.xml",
                                            dir.path.string(), {}, &lw, nullptr),
               Error);
}

TEST(ProjectorLight, PbrtLoader) {
  const TempDir dir("projector");
  Image img(2, 4);  // taller than wide: fov across x
  for (Rgb& p : img.pixels) p = Rgb(0.25f);
  write_image(dir.file("slide.exr"), img);
  std::vector<std::string> warnings;
  LoadWarnings lw(&warnings);
  const Scene s = pbrt::load_pbrt_string(
      "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\nTranslate 0 2 0\n"
      "LightSource \"projection\" \"string filename\" \"slide.exr\" \"float fov\" 45 \"float scale\" 3\nShape \"sphere\"\n",
      "p.pbrt", dir.path.string(), {}, &lw, nullptr);
  ASSERT_EQ(s.lights.size(), 1u);
  const Light& l = s.lights[0];
  EXPECT_EQ(l.type, LightType::projector);
  EXPECT_FALSE(l.irradiance_plane);
  EXPECT_EQ(l.value, Rgb(3.f));
  EXPECT_NEAR(l.position.y, 2.f, 1e-6f);
  const double t = std::tan(22.5 * M_PI / 180.0);
  EXPECT_NEAR(l.uv_scale_u, 0.5 / t, 1e-5);
  EXPECT_NEAR(l.uv_scale_v, -0.5 / (t * 2.0), 1e-5);
  EXPECT_TRUE(s.textures[size_t(l.texture)].nearest);
  EXPECT_TRUE(warnings.empty()) << ::testing::PrintToString(warnings);
}

}  // namespace
}  // namespace pathspace
