// pbrt-v4 motion (io/pbrt/pbrt_builder.cpp and its lights and shapes, pbrt_animated_transform.h): ActiveTransform
// StartTime / EndTime / All, TransformTimes and the camera's shutter give a shape its vertices at
// shutter open (Scene::positions) and close (Scene::positions_end); transforms in between are
// interpolated as pbrt-v4's AnimatedTransform does (translation and stretch linearly, rotation by
// slerp); a moving sphere becomes a mesh; the camera moves with its animated CameraTransform, point
// and spot lights with theirs; distant light motion is reported.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "pathspace/io/pbrt/pbrt_animated_transform.h"
#include "pathspace/io/pbrt/pbrt_scene_builder.h"
#include "pathspace/scene/motion.h"

namespace pathspace {
namespace {

struct Loaded {
  Scene scene;
  std::vector<std::string> warnings;
};

Loaded load(const std::string& camera, const std::string& world) {
  Loaded l;
  LoadWarnings lw(&l.warnings);
  l.scene = pbrt::load_pbrt_string("LookAt 0 0 5  0 0 0  0 1 0\n" + camera + "\nWorldBegin\n" + world, "m.pbrt", ".", {}, &lw, nullptr);
  return l;
}

bool any_warning(const Loaded& l, const std::string& part) {
  for (const std::string& w : l.warnings)
    if (w.find(part) != std::string::npos) return true;
  return false;
}

const std::string kTriangle =
    "Shape \"trianglemesh\" \"point3 P\" [ 0 0 0  1 0 0  0 1 0 ] \"integer indices\" [ 0 1 2 ]\n";

TEST(PbrtMotion, ActiveTransformEndTimeMovesTheShapeAtShutterClose) {
  const Loaded l = load("Camera \"perspective\"",
                        "AttributeBegin\nActiveTransform EndTime\nTranslate 2 0 0\nActiveTransform All\n" + kTriangle + "AttributeEnd\n");
  const Scene& s = l.scene;
  ASSERT_EQ(s.positions.size(), 3u);
  ASSERT_EQ(s.positions_end.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_FLOAT_EQ(s.positions_end[i].x, s.positions[i].x + 2.f);
    EXPECT_FLOAT_EQ(s.positions_end[i].y, s.positions[i].y);
  }
  EXPECT_FLOAT_EQ(s.positions[1].x, 1.f);  // the start transform is the identity
  EXPECT_NE(s.view().positions_end, nullptr);
}

TEST(PbrtMotion, StartTimeOnlyMovesTheStartAndStaticShapesStandStill) {
  const Loaded l = load("Camera \"perspective\"",
                        kTriangle + "AttributeBegin\nActiveTransform StartTime\nTranslate 0 -1 0\nActiveTransform All\n" + kTriangle +
                            "AttributeEnd\n" + kTriangle);
  const Scene& s = l.scene;
  ASSERT_EQ(s.positions.size(), 9u);
  ASSERT_EQ(s.positions_end.size(), 9u);  // finalize pads the last, static mesh
  for (size_t i = 0; i < 3; ++i) EXPECT_EQ(s.positions_end[i].y, s.positions[i].y) << "static before";
  for (size_t i = 3; i < 6; ++i) EXPECT_FLOAT_EQ(s.positions_end[i].y, s.positions[i].y + 1.f) << "moving";
  for (size_t i = 6; i < 9; ++i) EXPECT_EQ(s.positions_end[i].y, s.positions[i].y) << "static after";
}

TEST(PbrtMotion, StillScenesHaveNoEndPositions) {
  const Loaded l = load("Camera \"perspective\"", "Translate 1 0 0\n" + kTriangle);
  EXPECT_TRUE(l.scene.positions_end.empty());
  EXPECT_EQ(l.scene.view().positions_end, nullptr);
}

TEST(PbrtMotion, TheShutterSelectsPartOfTheMotion) {
  // TransformTimes 0 2, shutter [0.5, 1.5]: the shape is a quarter and three quarters of the way.
  const Loaded l = load("Camera \"perspective\" \"float shutteropen\" 0.5 \"float shutterclose\" 1.5",
                        "TransformTimes 0 2\nActiveTransform EndTime\nTranslate 4 0 0\nActiveTransform All\n" + kTriangle);
  const Scene& s = l.scene;
  ASSERT_EQ(s.positions_end.size(), 3u);
  EXPECT_NEAR(s.positions[0].x, 1.f, 1e-6f);
  EXPECT_NEAR(s.positions_end[0].x, 3.f, 1e-6f);
  // A shutter after the motion: the shape stands at its end.
  const Loaded after = load("Camera \"perspective\" \"float shutteropen\" 3 \"float shutterclose\" 4",
                            "TransformTimes 0 2\nActiveTransform EndTime\nTranslate 4 0 0\nActiveTransform All\n" + kTriangle);
  EXPECT_TRUE(after.scene.positions_end.empty());
  EXPECT_NEAR(after.scene.positions[0].x, 4.f, 1e-6f);
}

TEST(PbrtMotion, InterpolatedRotationsFollowTheArc) {
  pbrt::Mat4 out;
  ASSERT_TRUE(pbrt::interpolate_transform(pbrt::Mat4(), *pbrt::Mat4::rotate(90, 0, 0, 1), 0.5, &out));
  const pbrt::Mat4 expected = *pbrt::Mat4::rotate(45, 0, 0, 1);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(out.m[i][j], expected.m[i][j], 1e-9) << i << "," << j;
  // Translation and scale blend linearly, each with the rotation.
  const pbrt::Mat4 a = pbrt::Mat4::translate(1, 2, 3) * pbrt::Mat4::scale(2, 2, 2);
  const pbrt::Mat4 b = pbrt::Mat4::translate(3, 2, 1) * *pbrt::Mat4::rotate(60, 1, 0, 0) * pbrt::Mat4::scale(4, 4, 4);
  ASSERT_TRUE(pbrt::interpolate_transform(a, b, 0.5, &out));
  const pbrt::Mat4 mid = pbrt::Mat4::translate(2, 2, 2) * *pbrt::Mat4::rotate(30, 1, 0, 0) * pbrt::Mat4::scale(3, 3, 3);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(out.m[i][j], mid.m[i][j], 1e-9) << i << "," << j;
  EXPECT_NEAR(pbrt::rotation_between_degrees(a, b), 60.0, 1e-9);
  // The ends are the matrices themselves.
  ASSERT_TRUE(pbrt::interpolate_transform(a, b, 0.0, &out));
  EXPECT_EQ(out.m[0][3], a.m[0][3]);
}

TEST(PbrtMotion, LargeRotationsWarnThatVerticesMoveOnChords) {
  const Loaded l = load("Camera \"perspective\"", "ActiveTransform EndTime\nRotate 90 0 0 1\nActiveTransform All\n" + kTriangle);
  EXPECT_FALSE(l.scene.positions_end.empty());
  EXPECT_TRUE(any_warning(l, "turns 90 degrees")) << (l.warnings.empty() ? "" : l.warnings[0]);
  const Loaded small = load("Camera \"perspective\"", "ActiveTransform EndTime\nRotate 5 0 0 1\nActiveTransform All\n" + kTriangle);
  EXPECT_FALSE(any_warning(small, "turns"));
}

TEST(PbrtMotion, AMovingSphereBecomesAMovingMesh) {
  const Loaded l = load("Camera \"perspective\"",
                        "ActiveTransform EndTime\nTranslate 0 0 1\nActiveTransform All\nShape \"sphere\" \"float radius\" 0.5\n");
  const Scene& s = l.scene;
  EXPECT_TRUE(s.spheres.empty());
  ASSERT_GT(s.triangles.size(), 1000u);
  ASSERT_EQ(s.positions_end.size(), s.positions.size());
  for (size_t i = 0; i < s.positions.size(); ++i) {
    EXPECT_NEAR(length(s.positions[i]), 0.5f, 1e-5f);
    EXPECT_NEAR(s.positions_end[i].z - s.positions[i].z, 1.f, 1e-5f);
  }
  EXPECT_TRUE(any_warning(l, "moving sphere"));
}

TEST(PbrtMotion, AnAnimatedCameraTransformMovesTheCamera) {
  // pbrt-v4's CameraTransform: the CTM's end transform at shutter close. Camera space moved by +1 in
  // x puts the camera at x = -1.
  const Loaded cam = load("ActiveTransform EndTime\nTranslate 1 0 0\nActiveTransform All\nCamera \"perspective\"", kTriangle);
  const Scene& s = cam.scene;
  ASSERT_TRUE(s.camera_moves);
  EXPECT_NEAR(distance(s.camera.position, Vec3(0, 0, 5)), 0.f, 1e-5f);
  EXPECT_NEAR(distance(s.camera_end.position, Vec3(-1, 0, 5)), 0.f, 1e-5f);
  EXPECT_NEAR(distance(s.camera_end.forward, s.camera.forward), 0.f, 1e-6f);
  EXPECT_TRUE(s.positions_end.empty()) << "only the camera moves";
  EXPECT_TRUE(scene_moves(s.view())) << "so paths sample a time";
  EXPECT_FALSE(any_warning(cam, "camera")) << cam.warnings.size();
  // Half the motion inside a shutter of [0, 0.5] of TransformTimes [0, 1].
  const Loaded half = load("ActiveTransform EndTime\nTranslate 1 0 0\nActiveTransform All\n"
                           "Camera \"perspective\" \"float shutteropen\" 0 \"float shutterclose\" 0.5", kTriangle);
  EXPECT_NEAR(distance(half.scene.camera_end.position, Vec3(-0.5f, 0, 5)), 0.f, 1e-5f);
  // A turn beyond what a linear blend follows is reported.
  const Loaded turn = load("ActiveTransform EndTime\nRotate 40 0 1 0\nActiveTransform All\nCamera \"perspective\"", kTriangle);
  EXPECT_TRUE(turn.scene.camera_moves);
  EXPECT_TRUE(any_warning(turn, "the camera turns 40 degrees"));
}

TEST(PbrtMotion, PointAndSpotLightsMoveDistantLightsAreReported) {
  const Loaded light = load("Camera \"perspective\" \"float shutteropen\" 0 \"float shutterclose\" 0.5",
                            "ActiveTransform EndTime\nTranslate 1 0 0\nActiveTransform All\n"
                            "LightSource \"point\" \"point3 from\" [0 2 0]\n"
                            "LightSource \"spot\" \"point3 from\" [0 2 0] \"point3 to\" [0 0 0]\n" + kTriangle);
  ASSERT_EQ(light.scene.lights.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    const Light& l = light.scene.lights[size_t(i)];
    EXPECT_TRUE(l.moves) << i;
    EXPECT_NEAR(distance(l.position, Vec3(0, 2, 0)), 0.f, 1e-6f) << i;
    EXPECT_NEAR(distance(l.position_end, Vec3(0.5f, 2, 0)), 0.f, 1e-6f) << i;  // half the motion in the shutter
    EXPECT_NEAR(distance(light_position(l, 0.5f), Vec3(0.25f, 2, 0)), 0.f, 1e-6f) << i;
  }
  EXPECT_TRUE(light.scene.view().lights_move);
  EXPECT_TRUE(scene_moves(light.scene.view()));
  EXPECT_FALSE(any_warning(light, "animated transform")) << light.warnings.size();
  const Loaded turning = load("Camera \"perspective\"", "ActiveTransform EndTime\nRotate 30 0 0 1\nActiveTransform All\n"
                                                        "LightSource \"spot\" \"point3 from\" [1 0 0] \"point3 to\" [0 0 0]\n" + kTriangle);
  EXPECT_TRUE(any_warning(turning, "keeps its orientation"));
  const Loaded distant = load("Camera \"perspective\"", "ActiveTransform EndTime\nRotate 30 0 0 1\nActiveTransform All\n"
                                                        "LightSource \"distant\"\n" + kTriangle);
  EXPECT_TRUE(any_warning(distant, "LightSource \"distant\" under an animated transform"));
}

}  // namespace
}  // namespace pathspace
