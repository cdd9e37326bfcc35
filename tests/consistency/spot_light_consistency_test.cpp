// A spot light (pbrt-v4's smoothstep falloff) in the empty Cornell box, 16x16: PT (next event
// estimation: the spot is a delta light), LT (emission sampled uniformly in the cone, falloff in
// the weight) and BPT (all strategies, MIS with the spot's emission pdf) render the same image,
// by the per-pixel z-test of support/statistics.h, alpha 0.01 Sidak over the two comparisons. The
// cone is narrow enough that the walls show its edge, so a wrong falloff or cone pdf fails here.
#include <gtest/gtest.h>

#include <cmath>

#include "pathspace/accel/accel.h"
#include "pathspace/scene/builtin_scenes.h"
#include "support/integrator_comparison.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

Scene spot_box() {
  Scene scene = make_builtin_scene("e_p", 16, 16);  // the empty box with a point light under the ceiling
  const Vec3 p = scene.lights.at(0).position;
  const Bounds3 b = scene.geometry_bounds();
  const Vec3 floor_spot((b.lo.x + b.hi.x) * 0.5f + 0.3f * (b.hi.x - b.lo.x), p.y, b.lo.z);  // aim down and aside
  scene.lights.clear();
  scene.add_spot_light(p, floor_spot - p, Rgb(2.f, 1.5f, 1.f), std::cos(40.f * float(M_PI) / 180.f),
                       std::cos(25.f * float(M_PI) / 180.f));
  scene.finalize();
  return scene;
}

TEST(SpotLight, PtLtAndBptAgree) {
  const Scene scene = spot_box();
  const Accel accel(scene);
  LtSettings lt;
  lt.light_paths = 4096;
  const testing::Rendered a = testing::render_integrator(scene, accel, testing::default_config("pt", testing::test_seed(61)), 1024);
  const testing::Rendered b = testing::render_integrator(scene, accel, make_render_config("lt", lt, testing::test_seed(62)), 256);
  const testing::Rendered c = testing::render_integrator(scene, accel, testing::default_config("bpt", testing::test_seed(63)), 512);
  size_t lit = 0;
  for (const Rgb& px : a.mean.pixels) lit += px.r > 1e-3f;
  EXPECT_GT(lit, 50u);
  const double alpha = testing::sidak(0.01, 2);
  testing::expect_same_image(b, a, "spot-lt-vs-pt", alpha, "lt", "pt");
  testing::expect_same_image(c, a, "spot-bpt-vs-pt", alpha, "bpt", "pt");
}

}  // namespace
}  // namespace pathspace
