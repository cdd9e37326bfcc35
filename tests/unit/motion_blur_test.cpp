// Motion blur's geometry (scene/motion.h): Embree intersects a moving triangle where it is at the
// ray's time, hits are filled at that time, light sampling and bounds follow the motion, finalize
// pads the end positions, and still scenes read no time (the BVH tracer against Embree on moving
// geometry: bvh_tracer_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/scene/animation.h"
#include "pathspace/scene/light_sampling.h"
#include "pathspace/scene/motion.h"
#include "pathspace/scene/scene.h"

namespace pathspace {
namespace {

// A unit square in z = 0 (x, y in [0, 1]) that moves by +2 in x while the shutter is open, and a
// still one at x in [5, 6]; the square emits when `emits`.
Scene moving_square(bool emits = false) {
  Scene s;
  const uint32_t m = s.add_material(make_diffuse(Rgb(0.5f)));
  s.add_quad(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), m, emits ? Rgb(1.f) : Rgb());
  s.positions_end = s.positions;
  for (Vec3& p : s.positions_end) p.x += 2.f;
  s.add_quad(Vec3(5, 0, 0), Vec3(6, 0, 0), Vec3(6, 1, 0), Vec3(5, 1, 0), m);
  s.camera = make_perspective_camera(Vec3(0, 0, 5), Vec3(0, 0, -1), Vec3(0, 1, 0), 40.f, 4, 4);
  s.finalize();
  return s;
}

Ray down_at(float x, float y, float time) {
  Ray r{Vec3(x, y, 1.f), Vec3(0, 0, -1)};
  r.time = time;
  return r;
}

TEST(MotionBlur, EmbreeHitsTheTriangleWhereItIsAtTheRaysTime) {
  const Scene s = moving_square();
  const Accel accel(s);
  SurfaceHit hit;
  // x = 1.5 is covered for t in [0.25, 0.75] only.
  EXPECT_FALSE(accel.intersect(down_at(1.5f, 0.5f, 0.f), &hit));
  EXPECT_FALSE(accel.intersect(down_at(1.5f, 0.5f, 0.9f), &hit));
  ASSERT_TRUE(accel.intersect(down_at(1.5f, 0.5f, 0.5f), &hit));
  EXPECT_NEAR(hit.p.x, 1.5f, 1e-5f);
  EXPECT_NEAR(hit.p.z, 0.f, 1e-5f);
  EXPECT_EQ(hit.time, 0.5f);
  EXPECT_TRUE(accel.occluded(down_at(1.5f, 0.5f, 0.3f)));
  EXPECT_FALSE(accel.occluded(down_at(1.5f, 0.5f, 0.2f)));
  // The still square is there at every time.
  for (float t : {0.f, 0.5f, 0.99f}) EXPECT_TRUE(accel.intersect(down_at(5.5f, 0.5f, t), &hit)) << t;
  // Barycentrics are the moving triangle's: the hit point lies where the ray is.
  ASSERT_TRUE(accel.intersect(down_at(2.2f, 0.3f, 0.75f), &hit));
  EXPECT_NEAR(hit.p.x, 2.2f, 1e-5f);
  EXPECT_NEAR(hit.p.y, 0.3f, 1e-5f);
}

TEST(MotionBlur, FinalizePadsEndPositionsAndBoundsCoverTheMotion) {
  const Scene s = moving_square();
  ASSERT_EQ(s.positions_end.size(), s.positions.size());
  EXPECT_EQ(s.positions_end.back().x, s.positions.back().x);  // the still square, padded
  EXPECT_GE(s.geometry_bounds().hi.x, 6.f);
  Scene too_many = moving_square();
  too_many.positions_end.push_back(Vec3());
  EXPECT_THROW(too_many.finalize(), Error);
}

TEST(MotionBlur, StillScenesReadNoTime) {
  Scene s = moving_square();
  s.positions_end.clear();
  s.finalize();
  const Sampler sampler(1, 2, 3);
  EXPECT_EQ(sample_time(s.view(), sampler, 7), 0.f);
  const Scene moving = moving_square();
  EXPECT_EQ(sample_time(moving.view(), sampler, 7), sampler.at(7));
}

TEST(MotionBlur, LightSamplesLieOnTheEmitterAtTheirTime) {
  const Scene s = moving_square(true);
  const SceneView v = s.view();
  ASSERT_EQ(s.lights.size(), 2u);  // one per triangle
  for (float t : {0.f, 0.3f, 1.f}) {
    for (int k = 0; k < 64; ++k) {
      LightSample ls;
      const Point2 u{(float(k % 8) + 0.5f) / 8.f, (float(k / 8) + 0.5f) / 8.f};
      if (!sample_light(v, s.lights[0], Vec3(0.5f + 2.f * t, 0.5f, 1.f), t, u, &ls)) continue;
      EXPECT_GE(ls.p.x, 2.f * t - 1e-5f);
      EXPECT_LE(ls.p.x, 1.f + 2.f * t + 1e-5f);
      EXPECT_NEAR(light_pdf(v, s.lights[0], Vec3(0.5f + 2.f * t, 0.5f, 1.f), ls.p, Vec3(0, 0, 1), t), ls.pdf_w, 1e-4f * ls.pdf_w);
    }
  }
  const std::optional<LightBounds> b = s.light_bounds(0);
  ASSERT_TRUE(b.has_value());
  EXPECT_GE(b->box.hi.x, 3.f - 1e-6f);
  EXPECT_LE(b->box.lo.x, 0.f);
}

// The light tree's normal cone: a sliding emitter keeps its one normal, a turning one gets every
// direction (the normals between its ends need not lie in a cone through theirs).
TEST(MotionBlur, LightBoundsOfMovingEmitters) {
  const Scene sliding = moving_square(true);
  EXPECT_GT(sliding.light_bounds(0)->cos_theta_o, 0.9999f);
  Scene turning = moving_square(true);
  turning.positions_end = turning.positions;
  for (int i = 0; i < 6; ++i) {  // the emitting quad turns 90 degrees about the x axis
    const Vec3 p = turning.positions[size_t(i)];
    turning.positions_end[size_t(i)] = Vec3(p.x, -p.z, p.y);
  }
  turning.finalize();
  EXPECT_EQ(turning.light_bounds(0)->cos_theta_o, -1.f);
}

TEST(MotionBlur, TheCameraMovesFromItsOpenToItsClosePose) {
  Scene s = moving_square();
  s.positions_end.clear();
  s.camera = make_perspective_camera(Vec3(0, 0, 5), Vec3(0, 0, -1), Vec3(0, 1, 0), 40.f, 8, 8);
  s.finalize();
  const PerspectiveCamera open = s.camera;
  EXPECT_FALSE(scene_moves(s.view()));
  // A still camera is returned as it is, bit for bit, at any time.
  const PerspectiveCamera same = camera_at(s.view(), 0.7f);
  EXPECT_EQ(same.position, open.position);
  EXPECT_EQ(same.forward, open.forward);
  EXPECT_EQ(same.up, open.up);
  // Moved 2 along x and turned 20 degrees about y by shutter close.
  s.camera_moves = true;
  s.camera_end = make_perspective_camera(open.position + Vec3(2, 0, 0),
                                         Vec3(std::sin(radians(20.f)), 0.f, -std::cos(radians(20.f))), Vec3(0, 1, 0), 40.f, 8, 8)
                     .pose();
  const SceneView v = s.view();
  EXPECT_TRUE(scene_moves(v)) << "a moving camera alone makes paths sample a time";
  const Sampler sampler(1, 2, 3);
  EXPECT_EQ(sample_time(v, sampler, 7), sampler.at(7));
  const PerspectiveCamera at0 = camera_at(v, 0.f), at1 = camera_at(v, 1.f), mid = camera_at(v, 0.5f);
  EXPECT_NEAR(distance(at0.position, open.position), 0.f, 1e-6f);
  EXPECT_NEAR(distance(at0.forward, open.forward), 0.f, 1e-6f);
  EXPECT_NEAR(distance(at1.position, s.camera_end.position), 0.f, 1e-6f);
  EXPECT_NEAR(distance(at1.forward, s.camera_end.forward), 0.f, 1e-6f);
  EXPECT_NEAR(distance(at1.right, s.camera_end.right), 0.f, 1e-6f);
  EXPECT_NEAR(distance(mid.position, open.position + Vec3(1, 0, 0)), 0.f, 1e-6f);
  // Halfway the view direction is halfway round (10 degrees), the axes orthonormal, the image intrinsics kept.
  EXPECT_NEAR(std::acos(std::clamp(dot(mid.forward, open.forward), -1.f, 1.f)), radians(10.f), 1e-4f);
  for (const Vec3& a : {mid.forward, mid.right, mid.up}) EXPECT_NEAR(length(a), 1.f, 1e-6f);
  EXPECT_NEAR(dot(mid.forward, mid.right), 0.f, 1e-6f);
  EXPECT_NEAR(dot(mid.forward, mid.up), 0.f, 1e-6f);
  EXPECT_EQ(mid.tan_x, open.tan_x);
  EXPECT_EQ(mid.width, open.width);
}

TEST(MotionBlur, AnimationsTurnAMovingCameraAtBothEndsAndACameraPathStillsIt) {
  // A frame of `render --frames`: the orbit turns the shutter-open and shutter-close poses alike; a
  // camera path places the camera absolutely and the file's motion within the frame is dropped.
  Scene base = moving_square();
  base.camera = make_perspective_camera(Vec3(0, 0, 5), Vec3(0, 0, -1), Vec3(0, 1, 0), 40.f, 8, 8);
  base.camera_moves = true;
  base.camera_end = make_perspective_camera(Vec3(1, 0, 5), Vec3(0, 0, -1), Vec3(0, 1, 0), 40.f, 8, 8).pose();
  base.finalize();
  Animation orbit;
  orbit.scene_at = [&](double) { return base; };
  orbit.orbit_degrees_per_frame = 90.f;
  const Scene turned = orbit.at_frame(1);
  ASSERT_TRUE(turned.camera_moves);
  const Vec3 centre = base.bounds().center;
  const PerspectiveCamera expected_end = orbit_camera(
      make_perspective_camera(Vec3(1, 0, 5), Vec3(0, 0, -1), Vec3(0, 1, 0), 40.f, 8, 8), centre, Vec3(0, 1, 0), 90.f);
  EXPECT_NEAR(distance(turned.camera_end.position, expected_end.position), 0.f, 1e-5f);
  EXPECT_NEAR(distance(turned.camera_end.forward, expected_end.forward), 0.f, 1e-5f);
  EXPECT_NEAR(distance(turned.camera_end.position, turned.camera.position), 1.f, 1e-5f) << "the motion turns with the orbit";
  Animation path;
  path.scene_at = [&](double) { return base; };
  CameraKeyframe key;
  key.position = Vec3(0, 3, 5);
  path.camera_path.keys.push_back(key);
  const Scene placed = path.at_frame(0);
  EXPECT_FALSE(placed.camera_moves);
  EXPECT_FALSE(placed.view().camera_moves);
}

}  // namespace
}  // namespace pathspace
