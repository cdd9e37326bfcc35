// The spot light: pbrt-v4's smoothstep falloff, next event estimation towards it, emission sampling
// inside its cone (directions, pdf, and flux: the mean emission weight is the light's power), and
// the pbrt-v4 `LightSource "spot"` statement (from, to, coneangle, conedelta, I, scale).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/io/pbrt/pbrt_scene_builder.h"
#include "pathspace/scene/light_emission.h"
#include "pathspace/sampling/rng.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

float cos_deg(float d) { return std::cos(d * float(M_PI) / 180.f); }

Scene spot_scene() {
  Scene s;
  s.camera.width = s.camera.height = 1;  // finalize() wants a film size
  s.add_spot_light(Vec3(0, 0, 2), Vec3(0, 0, -1), Rgb(3.f), cos_deg(30.f), cos_deg(20.f));
  s.finalize();
  return s;
}

TEST(SpotLight, FalloffIsPbrtsSmoothstep) {
  const Scene s = spot_scene();
  const Light& l = s.lights[0];
  auto at = [&](float deg) { return spot_falloff(l, Vec3(std::sin(deg * float(M_PI) / 180.f), 0.f, -std::cos(deg * float(M_PI) / 180.f))); };
  EXPECT_FLOAT_EQ(at(0.f), 1.f);
  EXPECT_FLOAT_EQ(at(19.f), 1.f);
  EXPECT_FLOAT_EQ(at(31.f), 0.f);
  const float c = cos_deg(25.f), t = (c - cos_deg(30.f)) / (cos_deg(20.f) - cos_deg(30.f));
  EXPECT_NEAR(at(25.f), t * t * (3.f - 2.f * t), 1e-5f);
  EXPECT_EQ(point_intensity(l, Vec3(0, 0, 1)), Rgb(0.f));  // behind the light
}

TEST(SpotLight, NextEventEstimationSeesTheFalloff) {
  const Scene s = spot_scene();
  const SceneView v = s.view();
  LightSample ls;
  ASSERT_TRUE(sample_light(v, s.lights[0], Vec3(0, 0, 0), 0.f, {0.5f, 0.5f}, &ls));
  EXPECT_TRUE(ls.delta);
  EXPECT_NEAR(ls.li.r, 3.f / 4.f, 1e-6f);  // I / d^2 on the axis
  EXPECT_FALSE(sample_light(v, s.lights[0], Vec3(5, 0, 1.9f), 0.f, {0.5f, 0.5f}, &ls));  // outside the cone
}

TEST(SpotLight, EmissionStaysInTheConeAndCarriesThePower) {
  const Scene s = spot_scene();
  const SceneView v = s.view();
  const Light& l = s.lights[0];
  Pcg32 rng(7, 3);
  const int n = 200000;
  double sum = 0, sum_sq = 0;
  for (int i = 0; i < n; ++i) {
    EmissionSample e;
    const Point2 up{rng.next_float(), rng.next_float()}, ud{rng.next_float(), rng.next_float()};
    if (!sample_emission(v, l, 0.f, up, ud, &e)) continue;  // falloff 0 at the cone's very edge: weight 0
    ASSERT_GE(dot(e.d, l.direction), l.cos_total - 1e-6f);
    float pa, pw;
    emission_pdf(v, l, e.p, e.n, e.d, 0.f, &pa, &pw);
    ASSERT_NEAR(pw, e.pdf_w, 1e-4f * e.pdf_w);
    sum += e.weight.r;
    sum_sq += double(e.weight.r) * e.weight.r;
  }
  // E[weight] = integral of I(w) over directions = 2 pi (1 - (cos_falloff + cos_total) / 2) I.
  const double power = 2.0 * M_PI * (1.0 - 0.5 * (double(l.cos_falloff) + double(l.cos_total))) * 3.0;
  const testing::MeanTest t = testing::t_test_mean(sum, sum_sq, n, power);
  EXPECT_GT(t.p, 1e-3) << "mean flux " << t.mean << " vs " << power;
  EXPECT_NEAR(s.light_power(0), power, 1e-4 * power);
}

TEST(SpotLight, PbrtStatement) {
  std::vector<std::string> w;
  LoadWarnings lw(&w);
  const Scene s = pbrt::load_pbrt_string(
      "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\nTranslate 1 0 0\n"
      "LightSource \"spot\" \"point3 from\" [ 0 4 0 ] \"point3 to\" [ 0 0 0 ] \"float coneangle\" 40 \"float conedelta\" 10 "
      "\"rgb I\" [ 2 2 2 ] \"float scale\" 1.5\nShape \"sphere\"\n",
      "spot.pbrt", ".", {}, &lw, nullptr);
  ASSERT_EQ(s.lights.size(), 1u);
  const Light& l = s.lights[0];
  EXPECT_EQ(l.type, LightType::spot);
  EXPECT_NEAR(distance(l.position, Vec3(1, 4, 0)), 0.f, 1e-6f);
  EXPECT_NEAR(l.direction.y, -1.f, 1e-6f);
  EXPECT_NEAR(l.cos_total, cos_deg(40.f), 1e-6f);
  EXPECT_NEAR(l.cos_falloff, cos_deg(30.f), 1e-6f);
  EXPECT_EQ(l.value, Rgb(3.f));
  EXPECT_TRUE(w.empty()) << ::testing::PrintToString(w);
  EXPECT_THROW(pbrt::load_pbrt_string("Camera \"perspective\"\nWorldBegin\nLightSource \"spot\" \"point3 from\" [ 0 0 0 ] \"point3 to\" [ 0 0 0 ]\n",
                                      "spot.pbrt", ".", {}, &lw, nullptr),
               Error);
}

}  // namespace
}  // namespace pathspace
