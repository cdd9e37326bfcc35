// Motion blur (scene/motion.h) in whole renders, against a closed form and between integrators
// (per-pixel z-tests, support/statistics.h, alpha = 0.01 Sidak-corrected over kComparisons):
//  - A white floor lit straight down by a directional light, under a black occluder that slides
//    along x while the shutter is open, the camera above both. A point x of either plane is covered
//    for the first clamp((x - a) / D, 0, 1) of the shutter (the occluder's near edge starts at a and
//    moves by D; its far edge stays beyond the view). A pixel sees the floor point p through the
//    occluder plane at q: at time t it is lit floor unless q (the camera ray) or p (the shadow ray or
//    the light path) is covered then, so its value is rho E / pi (1 - max(c(q), c(p))). The max
//    holds only when the camera ray and the light see the same instant: a renderer whose shadow rays
//    or light paths took another time than its camera rays would get the product of the two
//    uncovered fractions instead. PT, LT and BPT must match it everywhere; SPPM and PCLT (one time
//    per pass: their photons and light paths meet the camera paths of that pass) blur the shadow's
//    edge in each pass by their radius, and may miss it on a few pixels.
//  - An emitter sliding over a floor: PT's next event estimation samples the light where it is at
//    the path's time, BSDF sampling finds it there through Embree, LT and BPT emit from it there;
//    the four images must agree.
//  - A camera sliding sideways above a floor whose left half is white and right half black, lit
//    straight down: a pinhole's ray keeps its direction while its origin moves by D t, so the floor
//    point a pixel sees at time t is x + D t and its value rho E / pi clamp(-x / D, 0, 1). PT's camera
//    rays, LT's and BPT's camera connections (at the light path's time), and SPPM's and PCLT's
//    passes (one camera per pass) must all see that camera at the path's instant.
//  - A point light of intensity I moving at height h over the white floor: irradiance I h / r^3 at
//    the light's position of each instant, averaged over the shutter (a quadrature in time in the
//    expected image). LT and BPT emit from it, PT's next event estimation aims at it, SPPM's and
//    PCLT's passes light the floor from where it is at the pass's time.
// That BPT's connections join vertices of one instant is checked ray by ray in
// unit/motion_path_time_test.cpp: in the scenes tried here, the inner connections carried too
// small a share of the image for an image test to notice a wrong time.
#include <gtest/gtest.h>

#include <algorithm>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/bpt/bpt_settings.h"
#include "pathspace/integrators/lt/lt_settings.h"
#include "pathspace/integrators/pclt/pclt_settings.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/integrators/sppm/sppm_settings.h"
#include "support/integrator_comparison.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

constexpr int kComparisons = 18;
const double kAlphaImage = testing::sidak(0.01, kComparisons);

constexpr float kAlbedo = 0.8f, kOccluderHeight = 0.75f, kCameraHeight = 1.5f;
// The occluder spans x in [kNearEdge, kNearEdge + kWidth] at shutter open and moves by kTravel.
constexpr float kNearEdge = -0.6f, kWidth = 1.3f, kTravel = 1.2f;

// Appends quad corners moved by `offset` at shutter close (the positions before it stand still).
void move_last_vertices(Scene& s, size_t count, const Vec3& offset) {
  s.positions_end.assign(s.positions.begin(), s.positions.end());
  for (size_t i = s.positions.size() - count; i < s.positions.size(); ++i) s.positions_end[i] = s.positions[i] + offset;
}

Scene sliding_occluder() {
  Scene s;
  const uint32_t floor = s.add_material(make_diffuse(Rgb(kAlbedo)));
  const uint32_t black = s.add_material(make_diffuse(Rgb(0.f)));
  s.add_quad(Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), floor);
  const float x0 = kNearEdge, x1 = kNearEdge + kWidth, h = kOccluderHeight;
  s.add_quad(Vec3(x0, -1.2f, h), Vec3(x1, -1.2f, h), Vec3(x1, 1.2f, h), Vec3(x0, 1.2f, h), black);
  move_last_vertices(s, 6, Vec3(kTravel, 0, 0));
  s.add_directional_light(Vec3(0, 0, -1), Rgb(1.f));
  s.camera = make_perspective_camera(Vec3(0.f, 0.f, kCameraHeight), Vec3(0, 0, -1), Vec3(0, 1, 0), 40.f, 16, 16);
  s.finalize();
  return s;
}

// The closed form of the file comment, averaged over each pixel's footprint (64 x 64 rays through
// the floor alone).
Image expected_sliding_occluder() {
  Scene floor_only = sliding_occluder();
  floor_only.triangles.resize(2);
  floor_only.positions_end.clear();
  floor_only.finalize();
  const Vec3 eye(0.f, 0.f, kCameraHeight);
  auto covered = [](float x) { return std::clamp((x - kNearEdge) / kTravel, 0.f, 1.f); };
  return testing::footprint_average(floor_only, Accel(floor_only), 64, [&](const SurfaceHit* hit) {
    if (!hit) return Rgb();
    const Vec3 q = eye + (hit->p - eye) * ((kCameraHeight - kOccluderHeight) / kCameraHeight);
    return Rgb(kAlbedo * kInvPi * (1.f - std::max(covered(q.x), covered(hit->p.x))));
  });
}

// PT, LT and BPT must match `expected` in every pixel; SPPM and PCLT may miss it on the few pixels
// their radius blurs. Seeds from `seed` on. The expected image must vary by `min_range`: the motion
// has to show in the view.
void expect_every_integrator_matches(const Scene& scene, const Image& expected, uint64_t seed, float min_range) {
  float lo = 1.f, hi = 0.f;
  for (const Rgb& c : expected.pixels) lo = std::min(lo, c.r), hi = std::max(hi, c.r);
  EXPECT_GT(hi - lo, min_range) << "the blur must span the view";
  const Accel accel(scene);
  auto check = [&](const RenderConfig& config, uint32_t passes, const char* what, bool whole_image) {
    testing::expect_matches_exact(testing::render_integrator(scene, accel, config, passes), expected, what, kAlphaImage,
                                  whole_image);
  };
  check(testing::default_config("pt", testing::test_seed(seed)), 256, "pt", true);
  LtSettings lt;
  lt.light_paths = 16384;
  check(make_render_config("lt", lt, testing::test_seed(seed + 1)), 256, "lt", true);
  check(testing::default_config("bpt", testing::test_seed(seed + 2)), 128, "bpt", true);
  SppmSettings sppm;
  sppm.photons = 16384;
  check(make_render_config("sppm", sppm, testing::test_seed(seed + 3)), 256, "sppm", false);
  PcltSettings pclt;
  pclt.light_paths = 16384;
  check(make_render_config("pclt", pclt, testing::test_seed(seed + 4)), 256, "pclt", false);
}

TEST(MotionBlurRender, SlidingOccluderMatchesTheClosedForm) {
  const Scene scene = sliding_occluder();
  ASSERT_NE(scene.view().positions_end, nullptr);
  expect_every_integrator_matches(scene, expected_sliding_occluder(), 601, 0.1f);
}

// A one-sided emitter (0.4 x 0.4, facing down) 0.5 above the floor, sliding from x = -0.5 to 0.5.
Scene sliding_emitter() {
  Scene s;
  const uint32_t floor = s.add_material(make_diffuse(Rgb(kAlbedo)));
  const uint32_t black = s.add_material(make_diffuse(Rgb(0.f)));
  s.add_quad(Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), floor);
  const float h = 0.5f;
  s.add_quad(Vec3(-0.7f, -0.2f, h), Vec3(-0.7f, 0.2f, h), Vec3(-0.3f, 0.2f, h), Vec3(-0.3f, -0.2f, h), black, Rgb(4.f));
  move_last_vertices(s, 6, Vec3(1.f, 0, 0));
  s.camera = make_perspective_camera(Vec3(0.f, 0.f, kCameraHeight), Vec3(0, 0, -1), Vec3(0, 1, 0), 50.f, 16, 16);
  s.finalize();
  return s;
}

TEST(MotionBlurRender, SlidingEmitterLightsTheFloorAlikeInEveryIntegrator) {
  const Scene scene = sliding_emitter();
  const Accel accel(scene);
  const testing::Rendered pt = testing::render_integrator(scene, accel, testing::default_config("pt", testing::test_seed(611)), 512);
  PtSettings nee_only;
  nee_only.bsdf_sampling = false;
  const testing::Rendered pt_nee = testing::render_integrator(scene, accel, make_render_config("pt", nee_only, testing::test_seed(612)), 512);
  PtSettings bsdf_only;
  bsdf_only.nee = false;
  const testing::Rendered pt_bsdf =
      testing::render_integrator(scene, accel, make_render_config("pt", bsdf_only, testing::test_seed(613)), 2048);
  LtSettings lt;
  lt.light_paths = 16384;
  const testing::Rendered lt_image = testing::render_integrator(scene, accel, make_render_config("lt", lt, testing::test_seed(614)), 256);
  const testing::Rendered bpt = testing::render_integrator(scene, accel, testing::default_config("bpt", testing::test_seed(615)), 256);
  testing::expect_same_image(pt_nee, pt_bsdf, "pt nee only vs bsdf only", kAlphaImage);
  testing::expect_same_image(lt_image, pt, "lt vs pt", kAlphaImage);
  testing::expect_same_image(bpt, pt, "bpt vs pt", kAlphaImage);
}

// Every pixel sees the edge pass during the shutter (a pixel that stays white would have a constant
// PT estimate, whose zero variance no z-test can judge).
constexpr float kCameraTravel = 1.2f;

// Left half x < 0 white, right half black, camera 1.5 above it moving by kCameraTravel in +x: it sees
// x in [-1.1, 0] at shutter open.
Scene sliding_camera() {
  Scene s;
  const uint32_t white = s.add_material(make_diffuse(Rgb(kAlbedo)));
  const uint32_t black = s.add_material(make_diffuse(Rgb(0.f)));
  s.add_quad(Vec3(-1.5f, -1, 0), Vec3(0, -1, 0), Vec3(0, 1, 0), Vec3(-1.5f, 1, 0), white);
  s.add_quad(Vec3(0, -1, 0), Vec3(1.5f, -1, 0), Vec3(1.5f, 1, 0), Vec3(0, 1, 0), black);
  s.add_directional_light(Vec3(0, 0, -1), Rgb(1.f));
  s.camera = make_perspective_camera(Vec3(-0.55f, 0.f, kCameraHeight), Vec3(0, 0, -1), Vec3(0, 1, 0), 40.f, 16, 16);
  PerspectiveCamera end = s.camera;
  end.position += Vec3(kCameraTravel, 0, 0);
  s.camera_moves = true;
  s.camera_end = end.pose();
  s.finalize();
  return s;
}

Image expected_sliding_camera() {
  Scene still = sliding_camera();  // the shutter-open camera's rays; the motion is in the closed form
  still.camera_moves = false;
  still.finalize();
  return testing::footprint_average(still, Accel(still), 64, [&](const SurfaceHit* hit) {
    if (!hit) return Rgb();
    return Rgb(kAlbedo * kInvPi * std::clamp(-hit->p.x / kCameraTravel, 0.f, 1.f));
  });
}

TEST(MotionBlurRender, SlidingCameraMatchesTheClosedForm) {
  const Scene scene = sliding_camera();
  ASSERT_TRUE(scene.view().camera_moves);
  ASSERT_EQ(scene.view().positions_end, nullptr);
  expect_every_integrator_matches(scene, expected_sliding_camera(), 621, 0.2f);
}

constexpr float kLightHeight = 0.6f, kLightIntensity = 0.5f;
const Vec3 kLightStart(-0.5f, 0.f, kLightHeight), kLightEnd(0.5f, 0.1f, kLightHeight);

Scene sliding_point_light() {
  Scene s;
  const uint32_t floor = s.add_material(make_diffuse(Rgb(kAlbedo)));
  s.add_quad(Vec3(-2, -2, 0), Vec3(2, -2, 0), Vec3(2, 2, 0), Vec3(-2, 2, 0), floor);
  s.add_point_light(kLightStart, Rgb(kLightIntensity));
  s.lights.back().moves = true;
  s.lights.back().position_end = kLightEnd;
  s.camera = make_perspective_camera(Vec3(0.f, 0.f, kCameraHeight), Vec3(0, 0, -1), Vec3(0, 1, 0), 40.f, 16, 16);
  s.finalize();
  return s;
}

// rho / pi times the irradiance I cos / r^2 = I h / r^3 averaged over the shutter (midpoint rule in
// time, 64 steps: the integrand is smooth, the rule's error is far below the renders' noise).
Image expected_sliding_point_light() {
  Scene still = sliding_point_light();
  still.lights.back().moves = false;
  still.finalize();
  constexpr int kSteps = 64;
  return testing::footprint_average(still, Accel(still), 16, [&](const SurfaceHit* hit) {
    if (!hit) return Rgb();
    double e = 0.0;
    for (int k = 0; k < kSteps; ++k) {
      const float t = (float(k) + 0.5f) / float(kSteps);
      const Vec3 d = kLightStart * (1.f - t) + kLightEnd * t - hit->p;
      const double r = double(length(d));
      e += double(kLightIntensity) * double(kLightHeight) / (r * r * r);
    }
    return Rgb(float(double(kAlbedo) * kInvPi * e / kSteps));
  });
}

TEST(MotionBlurRender, SlidingPointLightMatchesTheClosedForm) {
  const Scene scene = sliding_point_light();
  ASSERT_TRUE(scene.view().lights_move);
  ASSERT_EQ(scene.view().positions_end, nullptr);
  expect_every_integrator_matches(scene, expected_sliding_point_light(), 631, 0.05f);
}

}  // namespace
}  // namespace pathspace
