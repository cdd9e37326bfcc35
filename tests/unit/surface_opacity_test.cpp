// Cutout opacity (scene/surface_opacity.h) at the level of single rays: the fraction of rays that
// pass a surface of opacity a is 1 - a (binomial z-tests, Sidak-corrected alpha 1e-3), the answer
// is a pure function of the ray, nearest-hit and shadow queries agree ray by ray, two stacked
// cutouts let (1 - a)^2 through (independent decisions), opacity textures are read at the hit's uv,
// and emitters stay opaque. Whole images: tests/consistency/cutout_render_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "pathspace/accel/accel.h"
#include "pathspace/sampling/rng.h"
#include "pathspace/scene/scene.h"
#include "pathspace/scene/surface_opacity.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

constexpr int kRays = 40000;
const double kAlpha = testing::sidak(1e-3, 8);

// Unit quads in the planes z = heights[i], facing +z, uv (0,0)..(1,1) over [0,1]^2; material i
// has opacity opacities[i].
Scene stacked_quads(const std::vector<float>& heights, const std::vector<float>& opacities) {
  Scene s;
  for (size_t i = 0; i < heights.size(); ++i) {
    Material m = make_diffuse(Rgb(0.5f));
    m.opacity = opacities[i];
    const uint32_t mat = s.add_material(m);
    const float z = heights[i];
    s.add_quad(Vec3(0, 0, z), Vec3(1, 0, z), Vec3(1, 1, z), Vec3(0, 1, z), mat);
    for (const Point2& uv : {Point2{0, 0}, Point2{1, 0}, Point2{1, 1}, Point2{1, 1}, Point2{0, 1}, Point2{0, 0}})
      s.uvs.push_back(uv);
  }
  s.add_environment_light(Rgb(1.f));
  s.camera = make_perspective_camera(Vec3(0.5f, 0.5f, 5.f), Vec3(0, 0, -1), Vec3(0, 1, 0), 30.f, 8, 8);
  s.finalize();
  return s;
}

// Downward rays from random points above the quads, through random points of [0.01, 0.99]^2.
std::vector<Ray> downward_rays(uint64_t seed) {
  Pcg32 rng(seed, 3);
  std::vector<Ray> rays;
  for (int i = 0; i < kRays; ++i) {
    const Vec3 target(0.01f + 0.98f * rng.next_float(), 0.01f + 0.98f * rng.next_float(), 0.f);
    const Vec3 origin(rng.next_float(), rng.next_float(), 5.f);
    rays.push_back(Ray{origin, normalize(target - origin), 0.f, kInfinity});
  }
  return rays;
}

// Fraction of rays that hit nothing; checks that occluded() agrees with intersect() for each ray.
double pass_fraction(const Scene& scene, const std::vector<Ray>& rays) {
  const Accel accel(scene);
  size_t passed = 0, disagree = 0;
  for (const Ray& r : rays) {
    SurfaceHit hit;
    const bool found = accel.intersect(r, &hit);
    passed += !found;
    disagree += found != accel.occluded(r);
  }
  EXPECT_EQ(disagree, 0u) << "nearest-hit and shadow queries must pass the same rays";
  return double(passed) / double(rays.size());
}

void expect_binomial(double fraction, double p, const std::string& what) {
  if (p <= 0.0 || p >= 1.0) {
    EXPECT_EQ(fraction, p) << what;
    return;
  }
  const double z = (fraction - p) / std::sqrt(p * (1.0 - p) / kRays);
  EXPECT_GE(testing::normal_two_sided_p(z), kAlpha) << what << ": " << fraction << " passed, expected " << p << " (z " << z << ")";
}

TEST(SurfaceOpacity, OneMinusOpacityOfTheRaysPass) {
  const std::vector<Ray> rays = downward_rays(1);
  for (float a : {0.f, 0.25f, 0.7f, 1.f}) {
    const Scene s = stacked_quads({0.f}, {a});
    expect_binomial(pass_fraction(s, rays), 1.0 - a, "opacity " + std::to_string(a));
  }
}

TEST(SurfaceOpacity, StackedCutoutsDecideIndependently) {
  // pbrt-v4 hashes the ray alone: two half-covered layers would then pass half the rays, not a quarter.
  const Scene s = stacked_quads({0.f, 0.5f}, {0.5f, 0.5f});
  expect_binomial(pass_fraction(s, downward_rays(2)), 0.25, "two layers of opacity 0.5");
}

TEST(SurfaceOpacity, TheAnswerIsAFunctionOfTheRay) {
  const Scene s = stacked_quads({0.f}, {0.5f});
  const SceneView v = s.view();
  const Vec3 o(0.3f, 0.4f, 2.f), d = normalize(Vec3(0.1f, 0.f, -1.f));
  const bool first = ray_passes_cutout(v.triangles, v.materials, v.uvs, v.textures, 0, 0.2f, 0.3f, o, d);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(ray_passes_cutout(v.triangles, v.materials, v.uvs, v.textures, 0, 0.2f, 0.3f, o, d), first);
  // Another triangle or ray gets its own draw: over many rays both answers occur.
  int passes = 0;
  for (int i = 0; i < 64; ++i)
    passes += ray_passes_cutout(v.triangles, v.materials, v.uvs, v.textures, 0, 0.2f, 0.3f, o + Vec3(1e-3f * float(i), 0, 0), d);
  EXPECT_GT(passes, 0);
  EXPECT_LT(passes, 64);
}

TEST(SurfaceOpacity, TextureOpacityIsReadAtTheHitUv) {
  // Opacity 1 on the left half of the texture (u < 0.5), 0 on the right: rays left of x = 0.5 hit,
  // rays right of it pass, except within the bilinear blend of the middle texels.
  Scene s = stacked_quads({0.f}, {1.f});
  ImageTexture t;
  t.name = "half";
  t.width = 2;
  t.height = 1;
  t.texels = {Rgb(1.f), Rgb(0.f)};
  t.nearest = true;
  s.materials[0].opacity_texture = int32_t(s.add_texture(t));
  s.finalize();
  EXPECT_TRUE(s.view().has_cutouts);
  const Accel accel(s);
  for (float x : {0.1f, 0.3f, 0.45f, 0.55f, 0.7f, 0.9f}) {
    SurfaceHit hit;
    const bool found = accel.intersect(Ray{Vec3(x, 0.5f, 1.f), Vec3(0, 0, -1), 0.f, kInfinity}, &hit);
    EXPECT_EQ(found, x < 0.5f) << "x " << x;
  }
}

TEST(SurfaceOpacity, EmittersAndOpaqueScenesAreNotCutouts) {
  Scene s;
  Material m = make_diffuse(Rgb(0.5f));
  m.opacity = 0.f;
  const uint32_t mat = s.add_material(m);
  s.add_quad(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), mat, Rgb(1.f));  // emits: opaque
  s.camera = make_perspective_camera(Vec3(0.5f, 0.5f, 5.f), Vec3(0, 0, -1), Vec3(0, 1, 0), 30.f, 8, 8);
  s.finalize();
  EXPECT_FALSE(s.view().has_cutouts);
  SurfaceHit hit;
  EXPECT_TRUE(Accel(s).intersect(Ray{Vec3(0.3f, 0.6f, 1.f), Vec3(0, 0, -1), 0.f, kInfinity}, &hit));
  EXPECT_FALSE(stacked_quads({0.f}, {1.f}).view().has_cutouts);
}

}  // namespace
}  // namespace pathspace
