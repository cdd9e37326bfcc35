// Furnace tests for image environments: a diffuse plane (albedo a, normal +z) under a lat-long map
// whose rows vary with theta (zero below the horizon) and whose columns vary with phi, mapped so
// that the map's up axis is world +z: L_out = a/pi * E with E = 2 pi int R(theta) cos sin dtheta,
// R the bilinear row profile (the column factor averages to 1 over phi), integrated here by
// Simpson's rule. PT with MIS, NEE only and BSDF sampling only, LT, BPT, SPPM and PCLT (t-tests of
// independent whole-image means), and a constant equal-area map equal to a constant light.
// alpha = 0.01, Sidak-corrected over the tests in this file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "pathspace/camera/perspective_camera.h"
#include "support/integrator_comparison.h"
#include "support/statistics.h"
#include "support/test_names.h"

namespace pathspace {
namespace {

constexpr int kTestsInFile = 8;
const double kAlpha = testing::sidak(0.01, kTestsInFile);
constexpr int kW = 32, kH = 16;
const float kRows[kH] = {3.f, 2.5f, 0.5f, 4.f, 1.f, 1.5f, 0.2f, 2.f, 0, 0, 0, 0, 0, 0, 0, 0};
constexpr float kAlbedo = 0.6f, kScale = 1.3f;

EnvironmentImage sky_image() {
  EnvironmentImage e;
  e.name = "rows";
  e.width = kW;
  e.height = kH;
  e.mapping = EnvironmentMapping::lat_long;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const float c = 1.f + 0.8f * std::cos(2.f * float(M_PI) * (float(x) + 0.5f) / float(kW));
      e.texels.push_back(Rgb(kRows[y] * c));
    }
  // Map up (local y) = world +z; local x = world x, local z = world -y.
  e.axis_x = Vec3(1, 0, 0);
  e.axis_y = Vec3(0, 0, 1);
  e.axis_z = Vec3(0, -1, 0);
  return e;
}

// R(theta): linear between row centres in v = theta / pi, clamped at the first and last row.
double row_profile(double theta) {
  const double y = theta / M_PI * kH - 0.5;
  const double fy = std::floor(y);
  const int y0 = std::max(0, int(fy)), y1 = std::min(kH - 1, int(fy) + 1);
  const double a = y - fy;
  return kRows[y0] * (1 - a) + kRows[y1] * a;
}

double expected_radiance() {
  const int n = 200000;  // Simpson over [0, pi/2]; the profile is piecewise linear in theta
  const double h = (M_PI / 2) / n;
  double s = 0;
  for (int i = 0; i <= n; ++i) {
    const double t = i * h;
    const double f = row_profile(t) * std::cos(t) * std::sin(t);
    s += f * (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2));
  }
  const double irradiance = 2 * M_PI * s * h / 3;
  return kAlbedo / M_PI * irradiance * kScale;
}

Scene plane_scene(EnvironmentImage image, const Rgb& scale) {
  Scene s;
  const uint32_t m = s.add_material(make_diffuse(Rgb(kAlbedo)));
  const float e = 2.f;
  s.add_quad(Vec3(-e, -e, 0), Vec3(e, -e, 0), Vec3(e, e, 0), Vec3(-e, e, 0), m);
  if (image.empty()) s.add_environment_light(scale);
  else s.add_environment_map(std::move(image), scale);
  s.camera = make_perspective_camera(Vec3(0, 0, 1), Vec3(0.1f, 0.2f, -1.f), Vec3(0, 1, 0), 30.f, 16, 16);
  s.finalize();
  return s;
}

// Whole-image mean (red channel) and its standard error from the variance-of-the-mean image.
void expect_image_mean(const testing::Rendered& r, double expected, const char* what) {
  double m = 0, v = 0;
  for (size_t i = 0; i < r.mean.size(); ++i) {
    m += r.mean.pixels[i].r;
    v += r.variance.pixels[i].r;
  }
  const double n = double(r.mean.size());
  m /= n;
  const double se = std::sqrt(v) / n;
  const double p = testing::normal_two_sided_p((m - expected) / se);
  std::printf("%s: mean %.5f +- %.5f expected %.5f p %.3f\n", what, m, se, expected, p);
  EXPECT_GT(p, kAlpha) << what << ": mean " << m << " +- " << se << " expected " << expected;
}

class EnvPlanePt : public ::testing::TestWithParam<std::string> {};

TEST_P(EnvPlanePt, LatLongRowsClosedForm) {  // 3 tests
  const Scene scene = plane_scene(sky_image(), Rgb(kScale));
  PtSettings s;
  s.nee = GetParam() != "bsdf";
  s.bsdf_sampling = GetParam() != "nee";
  const testing::Rendered r = testing::render_integrator(scene, make_render_config("pt", s, 21 + testing::test_seed_base()), 256);
  expect_image_mean(r, expected_radiance(), GetParam().c_str());
}

INSTANTIATE_TEST_SUITE_P(Env, EnvPlanePt, ::testing::Values("mis", "nee", "bsdf"), testing::StringParamName());

// Light paths share a pass: the samples are whole-image means of independent one-pass renders.
void expect_pass_means(const std::string& integrator, int passes, uint64_t seed) {
  const Scene scene = plane_scene(sky_image(), Rgb(kScale));
  const Accel accel(scene);
  RenderConfig config;  // the integrator's defaults but for its light path count
  config.integrator = integrator;
  if (integrator == "lt") {
    LtSettings lt;
    lt.light_paths = 65536;
    config.settings = lt;
  } else if (integrator == "sppm") {
    SppmSettings sppm;
    sppm.photons = 262144;
    config.settings = sppm;
  } else if (integrator == "pclt") {
    PcltSettings pclt;
    pclt.light_paths = 262144;
    config.settings = pclt;
  }
  double sum = 0, sum_sq = 0;
  for (int p = 0; p < passes; ++p) {
    config.seed = seed + uint64_t(p) * 7919 + testing::test_seed_base();
    const testing::Rendered r = testing::render_integrator(scene, accel, config, 1);
    double m = 0;
    for (const Rgb& px : r.mean.pixels) m += px.r;
    m /= double(r.mean.size());
    sum += m;
    sum_sq += m * m;
  }
  const testing::MeanTest t = testing::t_test_mean(sum, sum_sq, passes, expected_radiance());
  std::printf("%s: mean %.5f +- %.5f expected %.5f p %.3f\n", integrator.c_str(), t.mean, t.std_error,
              expected_radiance(), t.p);
  EXPECT_GT(t.p, kAlpha) << integrator << ": mean " << t.mean << " +- " << t.std_error << " expected "
                         << expected_radiance();
}

TEST(EnvPlane, LtMatchesClosedForm) { expect_pass_means("lt", 30, 31); }
TEST(EnvPlane, BptMatchesClosedForm) { expect_pass_means("bpt", 30, 41); }
// The plane is flat and uniformly lit, so a gather ball covers pi r^2 of it: SPPM is unbiased here.
TEST(EnvPlane, SppmMatchesClosedForm) { expect_pass_means("sppm", 30, 71); }
TEST(EnvPlane, PcltMatchesClosedForm) { expect_pass_means("pclt", 30, 81); }

// A constant equal-area image c equals the constant light c: a c on the plane (PT, MIS).
TEST(EnvPlane, ConstantEqualAreaMapIsConstantLight) {
  EnvironmentImage e;
  e.name = "constant";
  e.width = e.height = 8;
  e.mapping = EnvironmentMapping::equal_area;
  e.texels.assign(64, Rgb(0.7f));
  e.axis_x = normalize(Vec3(1, 1, 0));
  e.axis_y = normalize(Vec3(-1, 1, 0));
  const Scene scene = plane_scene(std::move(e), Rgb(2.f));
  expect_image_mean(testing::render_integrator(scene, make_render_config("pt", PtSettings{}, 51 + testing::test_seed_base()), 128),
                    kAlbedo * 0.7 * 2.0, "equal-area constant");
}

}  // namespace
}  // namespace pathspace
