// Mitsuba's animated transforms (io/mitsuba/mitsuba_object.h, mitsuba_shapes.cpp): a shape's
// <animation name="to_world"> with <transform time=...> keys, over the sensor's shutter_open and
// shutter_close, gives the shape its vertices at shutter open and close (motion blur,
// scene/motion.h); keys in between are interpolated; a moving sphere becomes a mesh; a still shutter
// (Mitsuba 3's default 0, 0) leaves the scene still; an animated sensor moves the camera, an animated
// point, spot or projector emitter moves; other animated emitters keep their first key.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/io/mitsuba/mitsuba_loader.h"
#include "support/mitsuba_text.h"

namespace pathspace {
namespace {

using Loaded = testing::LoadedMitsuba;

Loaded load(const std::string& body, const std::string& shutter = "") {
  return testing::load_mitsuba_text("<scene version=\"3.0.0\">\n<sensor type=\"perspective\">" + shutter +
                                    "<transform name=\"to_world\"><lookat origin=\"0,0,5\" target=\"0,0,0\"/></transform>"
                                    "</sensor>\n" + body + "\n</scene>\n");
}

bool any_warning(const Loaded& l, const std::string& part) {
  for (const std::string& w : l.warnings)
    if (w.find(part) != std::string::npos) return true;
  return false;
}

const std::string kShutter = "<float name=\"shutter_open\" value=\"0\"/><float name=\"shutter_close\" value=\"1\"/>";

std::string sliding_rectangle(const std::string& extra_key = "") {
  return "<shape type=\"rectangle\"><animation name=\"to_world\">"
         "<transform time=\"0\"><translate x=\"0\"/></transform>" + extra_key +
         "<transform time=\"1\"><translate x=\"2\"/></transform></animation></shape>";
}

TEST(MitsubaMotion, AnAnimatedShapeMovesOverTheShutter) {
  const Loaded l = load(sliding_rectangle(), kShutter);
  const Scene& s = l.scene;
  ASSERT_EQ(s.positions.size(), 4u);
  ASSERT_EQ(s.positions_end.size(), 4u);
  for (size_t i = 0; i < 4; ++i) EXPECT_NEAR(s.positions_end[i].x - s.positions[i].x, 2.f, 1e-6f);
}

TEST(MitsubaMotion, ThePartOfTheAnimationInTheShutterIsUsed) {
  const Loaded l = load(sliding_rectangle(), "<float name=\"shutter_open\" value=\"0.25\"/><float name=\"shutter_close\" value=\"0.75\"/>");
  ASSERT_EQ(l.scene.positions_end.size(), 4u);
  EXPECT_NEAR(l.scene.positions[0].x, -1.f + 0.5f, 1e-6f);  // the rectangle's corner (-1, -1) a quarter of the way
  EXPECT_NEAR(l.scene.positions_end[0].x, -1.f + 1.5f, 1e-6f);
  // A key inside the shutter cannot be followed by two time steps: a warning says so.
  const Loaded inner = load(sliding_rectangle("<transform time=\"0.5\"><translate x=\"3\"/></transform>"), kShutter);
  EXPECT_TRUE(any_warning(inner, "lies inside the shutter interval"));
}

TEST(MitsubaMotion, MitsubasDefaultShutterIsStill) {
  const Loaded l = load(sliding_rectangle());
  EXPECT_TRUE(l.scene.positions_end.empty());
  EXPECT_NEAR(l.scene.positions[0].x, -1.f, 1e-6f);  // the scene at time 0
}

TEST(MitsubaMotion, AMovingSphereBecomesAMovingMesh) {
  const Loaded l = load("<shape type=\"sphere\"><float name=\"radius\" value=\"0.5\"/><animation name=\"to_world\">"
                        "<transform time=\"0\"/><transform time=\"1\"><translate z=\"1\"/></transform></animation></shape>",
                        kShutter);
  EXPECT_TRUE(l.scene.spheres.empty());
  ASSERT_FALSE(l.scene.triangles.empty());
  ASSERT_EQ(l.scene.positions_end.size(), l.scene.positions.size());
  for (size_t i = 0; i < l.scene.positions.size(); ++i)
    EXPECT_NEAR(l.scene.positions_end[i].z - l.scene.positions[i].z, 1.f, 1e-5f);
  EXPECT_TRUE(any_warning(l, "moving sphere"));
}

TEST(MitsubaMotion, AnimatedPointEmittersMoveDirectionalOnesKeepTheirFirstKey) {
  const Loaded l = load("<emitter type=\"point\"><animation name=\"to_world\"><transform time=\"0\"/>"
                        "<transform time=\"2\"><translate x=\"1\"/></transform></animation></emitter>\n"
                        "<emitter type=\"directional\"><animation name=\"to_world\"><transform time=\"0\"/>"
                        "<transform time=\"1\"><rotate y=\"1\" angle=\"30\"/></transform></animation></emitter>",
                        kShutter);
  ASSERT_EQ(l.scene.lights.size(), 2u);
  const Light& point = l.scene.lights[0];
  EXPECT_TRUE(point.moves);
  EXPECT_EQ(point.position.x, 0.f);
  EXPECT_NEAR(point.position_end.x, 0.5f, 1e-6f);  // the shutter [0, 1] holds half of the keys' motion
  EXPECT_TRUE(l.scene.view().lights_move);
  EXPECT_TRUE(any_warning(l, "keeps its first key"));  // the directional emitter
  const Loaded still = load("<emitter type=\"point\"><animation name=\"to_world\"><transform time=\"0\"/>"
                            "<transform time=\"1\"><translate x=\"1\"/></transform></animation></emitter>");
  EXPECT_FALSE(still.scene.lights[0].moves) << "Mitsuba's default shutter (0, 0) is still";
}

TEST(MitsubaMotion, AnAnimatedSensorMovesTheCamera) {
  auto scene = [](const std::string& shutter, std::vector<std::string>* warnings) {
    LoadWarnings w(warnings);
    return mitsuba::load_mitsuba_string(
        "<scene version=\"3.0.0\">\n<sensor type=\"perspective\">" + shutter +
            "<animation name=\"to_world\"><transform time=\"0\"><lookat origin=\"0,0,5\" target=\"0,0,0\"/></transform>"
            "<transform time=\"2\"><lookat origin=\"2,0,5\" target=\"2,0,0\"/></transform></animation></sensor>\n"
            "<shape type=\"rectangle\"/>\n</scene>\n",
        "scene.xml", ".", {}, &w, nullptr);
  };
  std::vector<std::string> warnings;
  const Scene s = scene(kShutter, &warnings);  // shutter [0, 1]: half of the key interval
  ASSERT_TRUE(s.camera_moves);
  EXPECT_NEAR(distance(s.camera.position, Vec3(0, 0, 5)), 0.f, 1e-5f);
  EXPECT_NEAR(distance(s.camera_end.position, Vec3(1, 0, 5)), 0.f, 1e-5f);
  EXPECT_NEAR(distance(s.camera_end.forward, s.camera.forward), 0.f, 1e-6f);
  EXPECT_TRUE(s.positions_end.empty()) << "only the camera moves";
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  // Mitsuba's default shutter (0, 0): the first key, still.
  const Scene still = scene("", &warnings);
  EXPECT_FALSE(still.camera_moves);
  EXPECT_NEAR(distance(still.camera.position, Vec3(0, 0, 5)), 0.f, 1e-5f);
}

TEST(MitsubaMotion, MalformedAnimationsAreErrors) {
  EXPECT_THROW(load("<shape type=\"rectangle\"><animation name=\"to_world\"><translate x=\"1\"/></animation></shape>", kShutter), Error);
  EXPECT_THROW(load("<shape type=\"rectangle\"><animation name=\"to_world\"><transform/></animation></shape>", kShutter), Error);
  EXPECT_THROW(load("<shape type=\"rectangle\"><animation name=\"to_world\"><transform time=\"0\"/><transform time=\"0\"/>"
                    "</animation></shape>",
                    kShutter),
               Error);
  EXPECT_THROW(load(sliding_rectangle(), "<float name=\"shutter_open\" value=\"1\"/><float name=\"shutter_close\" value=\"0\"/>"), Error);
}

}  // namespace
}  // namespace pathspace
