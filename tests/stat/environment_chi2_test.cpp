// Chi-square tests of environment-map importance sampling: the piecewise-constant 2D distribution
// on the unit square against its own density, and the environment light's directions (sample_light
// for NEE, sample_emission for light paths) against light_pdf / emission_pdf, for a non-uniform
// lat-long and a non-uniform equal-area image under a rotated frame. Every sample's pdf must equal
// the pdf function at the sampled direction.
// Significance: alpha = 0.01 for the file, Sidak-corrected over its kChi2Tests chi-square tests.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "pathspace/scene/light_emission.h"
#include "pathspace/scene/environment_image.h"
#include "support/chi2.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

constexpr int kChi2Tests = 5;
const double kAlpha = testing::sidak(0.01, kChi2Tests);

// A smooth gradient, a bright "sun" texel, a dark band and a black patch (zero density there).
EnvironmentImage test_image(EnvironmentMapping m, int w, int h) {
  EnvironmentImage e;
  e.name = "chi2";
  e.width = w;
  e.height = h;
  e.mapping = m;
  e.texels.resize(size_t(w * h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float v = 0.2f + float(x) / float(w) + 2.f * float(y) / float(h);
      if (y == h / 3) v *= 0.05f;
      if (x >= w / 2 && x < w / 2 + 3 && y >= 2 * h / 3 && y < 2 * h / 3 + 3) v = 0.f;
      e.texels[size_t(y * w + x)] = Rgb(v, 0.5f * v, 2.f * v);
    }
  e.texels[size_t((h / 4) * w + w / 5)] = Rgb(40.f);
  const Vec3 z = normalize(Vec3(0.3f, 0.5f, 0.8f));
  e.axis_z = z;
  e.axis_x = normalize(cross(Vec3(0, 1, 0), z));
  e.axis_y = cross(z, e.axis_x);
  e.prepare();
  return e;
}

struct EnvScene {
  EnvironmentImage image;
  Light light;
  SceneView view() const {
    SceneView v;
    v.lights = &light;
    v.num_lights = 1;
    v.environment_light = 0;
    v.environment_map = image.view();
    v.bounds = BoundingSphere{Vec3(0.5f, 0.f, -1.f), 2.f};
    return v;
  }
};

EnvScene env_scene(EnvironmentMapping m, int w, int h) {
  EnvScene s;
  s.image = test_image(m, w, h);
  s.light.type = LightType::environment;
  s.light.value = Rgb(1.5f);
  return s;
}

void report(const char* name, const testing::Chi2Result& r) {
  std::printf("%s: chi2 %.1f dof %.0f p %.4f\n", name, r.statistic, r.dof, r.p_value);
  EXPECT_TRUE(r.passed(kAlpha)) << name << " chi2 " << r.statistic << " dof " << r.dof << " p " << r.p_value << " < "
                                << kAlpha << " " << r.error << "; evidence: " << r.evidence;
}

TEST(EnvironmentChi2, Piecewise2DOnTheSquare) {  // 1 test
  const EnvironmentImage e = test_image(EnvironmentMapping::lat_long, 13, 7);
  const Piecewise2DView d = e.view().distribution;
  uint64_t bad = 0;
  testing::Chi2Options o;
  o.name = "env_piecewise2d";
  o.seed = 11;
  o.alpha = kAlpha;
  const auto r = testing::grid_chi2(
      testing::Grid2{0, 1, 0, 1, 39, 28},
      [&](Pcg32& rng) {
        float pdf;
        const Point2 uv = d.sample({rng.next_float(), rng.next_float()}, &pdf);
        // uv = (cell + fraction) / size may round onto the next cell's edge: rare, not never.
        if (!(pdf > 0.f) || pdf != d.pdf(uv)) ++bad;
        return testing::Outcome{0, uv.x, uv.y, {}};
      },
      [&](double x, double y) { return double(d.pdf({float(x), float(y)})); }, o);
  report("env_piecewise2d", r);
  EXPECT_LE(bad, o.samples / 100000);
}

void check_nee(const char* name, EnvironmentMapping m, int w, int h, uint64_t seed) {
  const EnvScene s = env_scene(m, w, h);
  const SceneView v = s.view();
  const Vec3 ref(0.2f, -0.3f, 0.1f);
  uint64_t bad = 0;
  std::string first;
  testing::Chi2Options o;
  o.name = name;
  o.seed = seed;
  o.alpha = kAlpha;
  const auto r = testing::direction_chi2(
      {s.image.axis_z},
      [&](Pcg32& rng) {
        LightSample ls;
        // A sample is rejected only where the (bilinear) radiance is black: still a sampled direction.
        const bool ok = sample_light(v, s.light, ref, 0.f, {rng.next_float(), rng.next_float()}, &ls);
        if (!ok && !(ls.pdf_w > 0.f && is_black(ls.li))) return testing::Outcome{};
        // environment_pdf is what MIS evaluates for an escaping ray: exactly the sample's pdf.
        // light_pdf takes a point (ref + wi) and evaluates it for the renormalised difference.
        const float pdf = environment_pdf(v, ls.wi);
        const Vec3 p = ref + ls.wi;
        const float via_point = light_pdf(v, s.light, ref, p, Vec3(), 0.f);
        const Rgb le = environment_radiance(v, s.light, ls.wi);
        if (pdf != ls.pdf_w || via_point != environment_pdf(v, normalize(p - ref)) || !(le == ls.li) || ls.delta ||
            !std::isinf(ls.dist)) {
          if (bad++ == 0) first = "pdf_w " + std::to_string(ls.pdf_w) + " environment_pdf " + std::to_string(pdf);
        }
        return testing::Outcome{0, 0, 0, ls.wi};
      },
      [&](const Vec3& wdir) { return double(light_pdf(v, s.light, ref, ref + wdir, Vec3(), 0.f)); }, o);
  report(name, r);
  EXPECT_EQ(bad, 0u) << first;
}

TEST(EnvironmentChi2, LatLongNee) { check_nee("env_latlong_nee", EnvironmentMapping::lat_long, 24, 12, 12); }
TEST(EnvironmentChi2, EqualAreaNee) { check_nee("env_equalarea_nee", EnvironmentMapping::equal_area, 16, 16, 13); }

// Light paths: the propagation direction d is the opposite of a direction towards the map.
void check_emission(const char* name, EnvironmentMapping m, int w, int h, uint64_t seed) {
  const EnvScene s = env_scene(m, w, h);
  const SceneView v = s.view();
  uint64_t bad = 0;
  std::string first;
  testing::Chi2Options o;
  o.name = name;
  o.seed = seed;
  o.alpha = kAlpha;
  const auto r = testing::direction_chi2(
      {-s.image.axis_z},
      [&](Pcg32& rng) {
        EmissionSample e;
        const bool ok =
            sample_emission(v, s.light, 0.f, {rng.next_float(), rng.next_float()}, {rng.next_float(), rng.next_float()}, &e);
        if (!ok && !(e.pdf_w > 0.f && is_black(e.le))) return testing::Outcome{};
        if (!ok) return testing::Outcome{0, 0, 0, e.d};  // black direction: sampled, not emitted
        float pa, pw;
        emission_pdf(v, s.light, e.p, e.n, e.d, 0.f, &pa, &pw);
        const Rgb expected_weight = environment_radiance(v, s.light, -e.d) / (pa * pw);
        const bool weight_ok = fabsf(e.weight.r - expected_weight.r) <= 1e-5f * expected_weight.r;
        // The origin lies on the disk of the bounding sphere's radius, upstream of the scene.
        const Vec3 rel = e.p - (v.bounds.center - e.d * v.bounds.radius);
        const bool on_disk = fabsf(dot(rel, e.d)) < 1e-4f && length(rel) <= v.bounds.radius * 1.0001f;
        if (pw != e.pdf_w || pa != e.pdf_a || !weight_ok || !on_disk || !e.infinite) {
          if (bad++ == 0) first = "pdf_w " + std::to_string(e.pdf_w) + " emission_pdf " + std::to_string(pw);
        }
        return testing::Outcome{0, 0, 0, e.d};
      },
      [&](const Vec3& d) {
        float pa, pw;
        emission_pdf(v, s.light, d, d, d, 0.f, &pa, &pw);
        return double(pw);
      },
      o);
  report(name, r);
  EXPECT_EQ(bad, 0u) << first;
}

TEST(EnvironmentChi2, LatLongEmission) { check_emission("env_latlong_emission", EnvironmentMapping::lat_long, 20, 10, 14); }
TEST(EnvironmentChi2, EqualAreaEmission) { check_emission("env_equalarea_emission", EnvironmentMapping::equal_area, 12, 12, 15); }

}  // namespace
}  // namespace pathspace
