// glTF node animations (io/gltf/gltf_animation.h, docs/animation.md): a triangle node moved by
// translation, rotation and scale channels with LINEAR, STEP and CUBICSPLINE samplers, checked at
// keys, between keys and outside them; an animated camera and light; the still scene is the one at
// 0 s; malformed animation data is a pathspace::Error naming the file.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "pathspace/base/error.h"
#include "pathspace/io/gltf/gltf_interpolation.h"
#include "pathspace/io/scene_loader.h"
#include "support/gltf_test_files.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

using testing::GltfBuilder;

const float kHalfSqrt2 = std::sqrt(0.5f);

// A unit triangle (0,0,0), (1,0,0), (0,1,0) on node 0 with rest transform `node_trs`, and a point
// light (so no white environment is added). `animations` is the JSON array of animations.
std::string triangle_file(GltfBuilder& b, const std::string& animations, const std::string& node_trs = "") {
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  return b.gltf(R"("scenes":[{"nodes":[0,1]}],"nodes":[{"mesh":0)" + node_trs + R"(},{"extensions":{"KHR_lights_punctual":{"light":0}}}],)"
                R"("meshes":[{"primitives":[{"attributes":{"POSITION":)" + std::to_string(pos) + R"(}}]}],)"
                R"("extensionsUsed":["KHR_lights_punctual"],"extensions":{"KHR_lights_punctual":{"lights":[{"type":"point"}]}})" +
                (animations.empty() ? "" : ",\"animations\":" + animations));
}

// One animation of one channel on `node`.`path` whose sampler reads accessors `input` and `output`.
std::string one_channel(int node, const std::string& path, int input, int output, const std::string& interpolation) {
  return R"([{"channels":[{"sampler":0,"target":{"node":)" + std::to_string(node) + R"(,"path":")" + path + R"("}}],)"
         R"("samplers":[{"input":)" + std::to_string(input) + ",\"output\":" + std::to_string(output) + ",\"interpolation\":\"" +
         interpolation + "\"}]}]";
}

struct Animated {
  std::function<Scene(double)> scene_at;
  std::vector<std::string> warnings;
  bool warned(const std::string& part) const {
    for (const std::string& w : warnings)
      if (w.find(part) != std::string::npos) return true;
    return false;
  }
};

Animated load(const testing::TempDir& dir, const std::string& name, const std::string& text) {
  testing::write_bytes(dir.file(name), text);
  Animated a;
  a.scene_at = load_scene_animation(dir.file(name), {}, &a.warnings);
  return a;
}

Vec3 vertex(const Scene& s, int k) { return s.positions[s.triangles.at(0).v[k]]; }
void expect_near(const Vec3& a, const Vec3& b, const std::string& note = "") {
  EXPECT_NEAR(a.x, b.x, 1e-5f) << note;
  EXPECT_NEAR(a.y, b.y, 1e-5f) << note;
  EXPECT_NEAR(a.z, b.z, 1e-5f) << note;
}

TEST(GltfAnimation, TranslationLinearAtKeysBetweenAndOutside) {
  testing::TempDir dir("gltf-anim");
  GltfBuilder b;
  const int in = b.floats({1, 3}, "SCALAR"), out = b.floats({0, 0, 0, 4, 2, 0}, "VEC3");
  // The rest translation (9,9,9) is replaced by the channel's at every time, 0 s included.
  const Animated a = load(dir, "t.gltf", triangle_file(b, one_channel(0, "translation", in, out, "LINEAR"), R"(,"translation":[9,9,9])"));
  ASSERT_TRUE(a.scene_at);
  expect_near(vertex(a.scene_at(1.0), 0), Vec3(0, 0, 0));
  expect_near(vertex(a.scene_at(2.0), 0), Vec3(2, 1, 0));
  expect_near(vertex(a.scene_at(2.5), 1), Vec3(4, 1.5f, 0));
  expect_near(vertex(a.scene_at(3.0), 0), Vec3(4, 2, 0));
  expect_near(vertex(a.scene_at(0.0), 0), Vec3(0, 0, 0), "before the first key: clamped");
  expect_near(vertex(a.scene_at(7.0), 0), Vec3(4, 2, 0), "after the last key: clamped");
  // The still scene (load_scene, a still render and frame 0) is the animation's at 0 s.
  std::vector<std::string> w;
  const Scene still = load_scene(dir.file("t.gltf"), {}, &w);
  expect_near(vertex(still, 0), Vec3(0, 0, 0));
  EXPECT_EQ(still.positions, a.scene_at(0.0).positions);
}

TEST(GltfAnimation, RotationLinearSlerpsAlongTheShorterArc) {
  testing::TempDir dir("gltf-anim");
  for (const float sign : {1.f, -1.f}) {  // q and -q are the same 90 degree turn about +z
    GltfBuilder b;
    const int in = b.floats({0, 1}, "SCALAR"), out = b.floats({0, 0, 0, 1, 0, 0, sign * kHalfSqrt2, sign * kHalfSqrt2}, "VEC4");
    const Animated a = load(dir, "r.gltf", triangle_file(b, one_channel(0, "rotation", in, out, "LINEAR")));
    ASSERT_TRUE(a.scene_at);
    // Halfway: 45 degrees, (1,0,0) -> (cos 45, sin 45, 0).
    expect_near(vertex(a.scene_at(0.5), 1), Vec3(kHalfSqrt2, kHalfSqrt2, 0), "sign " + std::to_string(sign));
    expect_near(vertex(a.scene_at(0.25), 1), Vec3(std::cos(3.14159265f / 8), std::sin(3.14159265f / 8), 0), "sign " + std::to_string(sign));
    expect_near(vertex(a.scene_at(1.0), 1), Vec3(0, 1, 0), "sign " + std::to_string(sign));
  }
}

TEST(GltfAnimation, SlerpOfUnitQuaternions) {
  const gltf::Quaternion a{0, 0, 0, 1}, b{0, 0, kHalfSqrt2, kHalfSqrt2};
  const gltf::Quaternion m = gltf::slerp(a, b, 0.5);
  // A 45 degree turn about z: (0, 0, sin 22.5, cos 22.5).
  EXPECT_NEAR(m[2], std::sin(3.14159265358979 / 8), 1e-7);
  EXPECT_NEAR(m[3], std::cos(3.14159265358979 / 8), 1e-7);
  const gltf::Quaternion same = gltf::slerp(a, a, 0.3);  // parallel keys: no division by sin 0
  EXPECT_DOUBLE_EQ(same[3], 1.0);
}

TEST(GltfAnimation, StepHoldsTheKeyAtOrBefore) {
  testing::TempDir dir("gltf-anim");
  GltfBuilder b;
  const int in = b.floats({0, 1, 2}, "SCALAR"), out = b.floats({0, 0, 0, 1, 0, 0, 2, 0, 0}, "VEC3");
  const Animated a = load(dir, "s.gltf", triangle_file(b, one_channel(0, "translation", in, out, "STEP")));
  ASSERT_TRUE(a.scene_at);
  EXPECT_NEAR(vertex(a.scene_at(0.99), 0).x, 0.f, 1e-6f);
  EXPECT_NEAR(vertex(a.scene_at(1.0), 0).x, 1.f, 1e-6f);
  EXPECT_NEAR(vertex(a.scene_at(1.5), 0).x, 1.f, 1e-6f);
  EXPECT_NEAR(vertex(a.scene_at(9.0), 0).x, 2.f, 1e-6f);
}

TEST(GltfAnimation, CubicSplineIsTheSpecsHermite) {
  testing::TempDir dir("gltf-anim");
  GltfBuilder b;
  // Keys at 0 and 2 s (interval 2). Per key: in-tangent, value, out-tangent.
  //   key 0: a0 = (9,9,9) (unused), v0 = (0,0,0), b0 = (1,0,0); key 1: a1 = (0,4,0), v1 = (1,0,0), b1 unused.
  const int in = b.floats({0, 2}, "SCALAR");
  const int out = b.floats({9, 9, 9, 0, 0, 0, 1, 0, 0, 0, 4, 0, 1, 0, 0, 9, 9, 9}, "VEC3");
  const Animated a = load(dir, "c.gltf", triangle_file(b, one_channel(0, "translation", in, out, "CUBICSPLINE")));
  ASSERT_TRUE(a.scene_at);
  // p(s) = (2s^3 - 3s^2 + 1) v0 + dt (s^3 - 2s^2 + s) b0 + (-2s^3 + 3s^2) v1 + dt (s^3 - s^2) a1, dt = 2.
  // s = 0.5: x = 2 * 0.125 * 1 + 0.5 * 1 = 0.75, y = 2 * (-0.125) * 4 = -1.
  expect_near(vertex(a.scene_at(1.0), 0), Vec3(0.75f, -1.f, 0));
  // s = 0.25: x = 2 * 0.140625 + 0.15625 = 0.4375, y = 2 * (-0.046875) * 4 = -0.375.
  expect_near(vertex(a.scene_at(0.5), 0), Vec3(0.4375f, -0.375f, 0));
  expect_near(vertex(a.scene_at(2.0), 0), Vec3(1, 0, 0));
  expect_near(vertex(a.scene_at(-1.0), 0), Vec3(0, 0, 0), "clamped to the first key's value, not its tangent");
}

TEST(GltfAnimation, CubicSplineRotationsAreNormalised) {
  testing::TempDir dir("gltf-anim");
  GltfBuilder b;
  const int in = b.floats({0, 1}, "SCALAR");
  // Zero tangents: a Hermite blend of the two values, not of unit length until normalised.
  const int out = b.floats({0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0}, "VEC4");
  const Animated a = load(dir, "cr.gltf", triangle_file(b, one_channel(0, "rotation", in, out, "CUBICSPLINE")));
  ASSERT_TRUE(a.scene_at);
  // Halfway between identity and a half turn about z the blend is (0,0,0.5,0.5): 90 degrees.
  const Scene s = a.scene_at(0.5);
  expect_near(vertex(s, 1), Vec3(0, 1, 0));
  EXPECT_NEAR(length(vertex(s, 2)), 1.f, 1e-5f) << "a unit rotation keeps lengths";
}

TEST(GltfAnimation, ScaleLinear) {
  testing::TempDir dir("gltf-anim");
  GltfBuilder b;
  const int in = b.floats({0, 1}, "SCALAR"), out = b.floats({1, 1, 1, 3, 5, 1}, "VEC3");
  const Animated a = load(dir, "sc.gltf", triangle_file(b, one_channel(0, "scale", in, out, "LINEAR"), R"(,"translation":[0,0,1])"));
  ASSERT_TRUE(a.scene_at);
  const Scene s = a.scene_at(0.5);
  expect_near(vertex(s, 1), Vec3(2, 0, 1), "T * R * S: the rest translation stays");
  expect_near(vertex(s, 2), Vec3(0, 3, 1));
}

TEST(GltfAnimation, AnimatedParentMovesCameraLightAndChildren) {
  testing::TempDir dir("gltf-anim");
  GltfBuilder b;
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int in = b.floats({0, 1}, "SCALAR"), out = b.floats({0, 0, 0, 0, 0, 5}, "VEC3");
  // Node 0 (animated along +z) holds the camera (node 1, 4 units behind) and the light (node 2);
  // the triangle (node 3) stands still.
  const std::string text = b.gltf(
      R"("scenes":[{"nodes":[0,3]}],"nodes":[{"children":[1,2]},{"camera":0,"translation":[0,0,4]},)"
      R"({"extensions":{"KHR_lights_punctual":{"light":0}},"translation":[1,0,0]},{"mesh":0}],)"
      R"("cameras":[{"type":"perspective","perspective":{"yfov":0.7,"znear":0.1}}],)"
      R"("meshes":[{"primitives":[{"attributes":{"POSITION":)" + std::to_string(pos) + R"(}}]}],)"
      R"("extensionsUsed":["KHR_lights_punctual"],"extensions":{"KHR_lights_punctual":{"lights":[{"type":"point"}]}},)"
      "\"animations\":" + one_channel(0, "translation", in, out, "LINEAR"));
  const Animated a = load(dir, "cam.gltf", text);
  ASSERT_TRUE(a.scene_at);
  const Scene s0 = a.scene_at(0.0), s1 = a.scene_at(1.0);
  expect_near(s0.camera.position, Vec3(0, 0, 4));
  expect_near(s1.camera.position, Vec3(0, 0, 9));
  expect_near(s1.camera.forward, Vec3(0, 0, -1));
  expect_near(s1.lights.at(0).position, Vec3(1, 0, 5));
  EXPECT_EQ(s0.positions, s1.positions) << "the triangle is not below the animated node";

  // --camera-pos places the camera: it then stays where the option puts it.
  SceneLoadOptions o;
  o.camera_position = Vec3(0, 0, 20);
  std::vector<std::string> w;
  const auto fixed = load_scene_animation(dir.file("cam.gltf"), o, &w);
  ASSERT_TRUE(fixed);
  expect_near(fixed(1.0).camera.position, Vec3(0, 0, 20));
}

TEST(GltfAnimation, FirstAnimationPlaysOthersAreAWarning) {
  testing::TempDir dir("gltf-anim");
  GltfBuilder b;
  const int in = b.floats({0, 1}, "SCALAR"), a_out = b.floats({0, 0, 0, 1, 0, 0}, "VEC3"), b_out = b.floats({0, 0, 0, 0, 7, 0}, "VEC3");
  const std::string first = one_channel(0, "translation", in, a_out, "LINEAR"), second = one_channel(0, "translation", in, b_out, "LINEAR");
  const Animated a = load(dir, "two.gltf", triangle_file(b, first.substr(0, first.size() - 1) + "," + second.substr(1)));
  ASSERT_TRUE(a.scene_at);
  EXPECT_TRUE(a.warned("animations[0] ('') is played; the other 1 are not (--animation N or NAME chooses one)"));
  expect_near(vertex(a.scene_at(1.0), 0), Vec3(1, 0, 0));
}

// render --animation: another animation by index or by name; an unknown one is an error listing them.
TEST(GltfAnimation, AnotherAnimationByIndexOrName) {
  testing::TempDir dir("gltf-anim");
  GltfBuilder b;
  const int in = b.floats({0, 1}, "SCALAR"), a_out = b.floats({0, 0, 0, 1, 0, 0}, "VEC3"), b_out = b.floats({0, 0, 0, 0, 7, 0}, "VEC3");
  const std::string first = one_channel(0, "translation", in, a_out, "LINEAR"), second = one_channel(0, "translation", in, b_out, "LINEAR");
  const std::string animations = first.substr(0, first.size() - 1) + ",{\"name\":\"lift\"," + second.substr(2);
  testing::write_bytes(dir.file("two.gltf"), triangle_file(b, animations));
  for (const std::string& wanted : {std::string("1"), std::string("lift")}) {
    SceneLoadOptions o;
    o.animation = wanted;
    std::vector<std::string> warnings;
    const auto scene_at = load_scene_animation(dir.file("two.gltf"), o, &warnings);
    ASSERT_TRUE(scene_at) << wanted;
    expect_near(vertex(scene_at(1.0), 0), Vec3(0, 7, 0), wanted);
    EXPECT_TRUE(warnings.empty()) << wanted << ": " << warnings.front();
  }
  SceneLoadOptions o;
  o.animation = "5";
  std::vector<std::string> warnings;
  try {
    load_scene_animation(dir.file("two.gltf"), o, &warnings);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("--animation 5: no such animation (the file has 0 '', 1 'lift')"), std::string::npos) << e.what();
  }
}

// The unit triangle with one morph target that lifts every vertex by (0, 0, 1) and one that moves
// vertex 1 by (1, 0, 0); `mesh_extra` and `node_extra` add to the mesh and node objects.
std::string morph_file(GltfBuilder& b, const std::string& animations, const std::string& mesh_extra = "", const std::string& node_extra = "") {
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int lift = b.floats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3"), stretch = b.floats({0, 0, 0, 1, 0, 0, 0, 0, 0}, "VEC3");
  return b.gltf(R"("scenes":[{"nodes":[0,1]}],"nodes":[{"mesh":0)" + node_extra + R"(},{"extensions":{"KHR_lights_punctual":{"light":0}}}],)"
                R"("meshes":[{"primitives":[{"attributes":{"POSITION":)" + std::to_string(pos) + R"(},"targets":[{"POSITION":)" +
                std::to_string(lift) + R"(},{"POSITION":)" + std::to_string(stretch) + "}]}]" + mesh_extra + "}],"
                R"("extensionsUsed":["KHR_lights_punctual"],"extensions":{"KHR_lights_punctual":{"lights":[{"type":"point"}]}})" +
                (animations.empty() ? "" : ",\"animations\":" + animations));
}

TEST(GltfAnimation, MorphTargetsBlendByTheWeights) {
  testing::TempDir dir("gltf-anim");
  std::vector<std::string> w;
  // Still: the mesh's weights, or the node's in their place.
  GltfBuilder b1;
  testing::write_bytes(dir.file("m.gltf"), morph_file(b1, "", R"(,"weights":[0.5,2])"));
  const Scene m = load_scene(dir.file("m.gltf"), {}, &w);
  expect_near(vertex(m, 0), Vec3(0, 0, 0.5f));
  expect_near(vertex(m, 1), Vec3(3, 0, 0.5f));
  GltfBuilder b2;
  testing::write_bytes(dir.file("n.gltf"), morph_file(b2, "", R"(,"weights":[0.5,2])", R"(,"weights":[0.25,0])"));
  expect_near(vertex(load_scene(dir.file("n.gltf"), {}, &w), 1), Vec3(1, 0, 0.25f));
  // Animated: two weights per key, LINEAR between keys at 0 s and 2 s; the mesh moves, so its
  // triangles are the moving part of each frame.
  GltfBuilder b;
  const int in = b.floats({0, 2}, "SCALAR"), out = b.floats({0, 0, 1, 0.5f}, "SCALAR");
  const Animated a = load(dir, "a.gltf", morph_file(b, one_channel(0, "weights", in, out, "LINEAR")));
  ASSERT_TRUE(a.scene_at);
  const Scene half = a.scene_at(1.0);
  expect_near(vertex(half, 0), Vec3(0, 0, 0.5f));
  expect_near(vertex(half, 1), Vec3(1.25f, 0, 0.5f));
  EXPECT_EQ(half.first_moving_triangle, 0u);
  expect_near(vertex(a.scene_at(5.0), 1), Vec3(1.5f, 0, 1), "after the last key: clamped");
  // STEP holds the first key's weights until the second.
  GltfBuilder bs;
  const int ins = bs.floats({0, 2}, "SCALAR"), outs = bs.floats({0, 0, 1, 0.5f}, "SCALAR");
  expect_near(vertex(load(dir, "s.gltf", morph_file(bs, one_channel(0, "weights", ins, outs, "STEP"))).scene_at(1.9), 0), Vec3(0, 0, 0));
}

// A triangle skinned to two joints (glTF sec. 3.7.3): vertex 0 to joint 0 (node 1, at rest), vertex
// 1 to joint 1 (node 2, whose translation is animated from (1,0,0) to (1,0,2) over 2 s; its inverse
// bind matrix undoes the rest translation), vertex 2 half to each. The mesh node's own translation
// (5,5,5) must not apply.
std::string skinned_file(GltfBuilder& b, const std::string& animations) {
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int joints = b.uints({0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0}, "VEC4");
  const int weights = b.floats({1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0}, "VEC4");
  const int ibm = b.floats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,  // column-major: identity
                            1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 1},  // translate (-1, 0, 0)
                           "MAT4");
  return b.gltf(R"("scenes":[{"nodes":[0,1,2,3]}],"nodes":[{"mesh":0,"skin":0,"translation":[5,5,5]},{},{"translation":[1,0,0]},)"
                R"({"extensions":{"KHR_lights_punctual":{"light":0}}}],"skins":[{"joints":[1,2],"inverseBindMatrices":)" +
                std::to_string(ibm) + R"(}],"meshes":[{"primitives":[{"attributes":{"POSITION":)" + std::to_string(pos) +
                R"(,"JOINTS_0":)" + std::to_string(joints) + R"(,"WEIGHTS_0":)" + std::to_string(weights) + "}}]}],"
                R"("extensionsUsed":["KHR_lights_punctual"],"extensions":{"KHR_lights_punctual":{"lights":[{"type":"point"}]}})" +
                (animations.empty() ? "" : ",\"animations\":" + animations));
}

TEST(GltfAnimation, SkinsFollowTheirJoints) {
  testing::TempDir dir("gltf-anim");
  std::vector<std::string> w;
  GltfBuilder still;
  testing::write_bytes(dir.file("still.gltf"), skinned_file(still, ""));
  const Scene rest = load_scene(dir.file("still.gltf"), {}, &w);
  expect_near(vertex(rest, 0), Vec3(0, 0, 0), "the bind pose; the mesh node's translation does not apply");
  expect_near(vertex(rest, 1), Vec3(1, 0, 0));
  expect_near(vertex(rest, 2), Vec3(0, 1, 0));
  for (const std::string& m : w) EXPECT_EQ(m.find("JOINTS_0"), std::string::npos) << m;
  GltfBuilder b;
  const int in = b.floats({0, 2}, "SCALAR"), out = b.floats({1, 0, 0, 1, 0, 2}, "VEC3");
  const Animated a = load(dir, "skin.gltf", skinned_file(b, one_channel(2, "translation", in, out, "LINEAR")));
  ASSERT_TRUE(a.scene_at);
  const Scene s = a.scene_at(1.0);
  expect_near(vertex(s, 0), Vec3(0, 0, 0));
  expect_near(vertex(s, 1), Vec3(1, 0, 1), "moves with joint 1");
  expect_near(vertex(s, 2), Vec3(0, 1, 0.5f), "half with each joint");
  EXPECT_EQ(s.first_moving_triangle, 0u) << "a skinned mesh moves with its joints";
}

TEST(GltfAnimation, MorphTargetErrors) {
  testing::TempDir dir("gltf-anim");
  std::vector<std::string> w;
  GltfBuilder b1;
  testing::write_bytes(dir.file("count.gltf"), morph_file(b1, "", R"(,"weights":[0.5])"));
  EXPECT_THROW(load_scene(dir.file("count.gltf"), {}, &w), Error);  // two targets, one weight
  // A weights channel on a mesh without morph targets; with the wrong number of outputs.
  GltfBuilder b2;
  const int in = b2.floats({0, 1}, "SCALAR"), out = b2.floats({0, 1}, "SCALAR");
  testing::write_bytes(dir.file("none.gltf"), triangle_file(b2, one_channel(0, "weights", in, out, "LINEAR")));
  try {
    load_scene_animation(dir.file("none.gltf"), {}, &w);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("whose mesh has no morph targets"), std::string::npos) << e.what();
  }
  GltfBuilder b3;
  const int in3 = b3.floats({0, 1}, "SCALAR"), out3 = b3.floats({0, 1, 0}, "SCALAR");
  testing::write_bytes(dir.file("outputs.gltf"), morph_file(b3, one_channel(0, "weights", in3, out3, "LINEAR")));
  EXPECT_THROW(load_scene_animation(dir.file("outputs.gltf"), {}, &w), Error);
}

TEST(GltfAnimation, FilesWithoutAnimationStandStill) {
  testing::TempDir dir("gltf-anim");
  GltfBuilder b;
  EXPECT_FALSE(load(dir, "still.gltf", triangle_file(b, "")).scene_at);
  testing::write_bytes(dir.file("tri.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  std::vector<std::string> w;
  EXPECT_FALSE(load_scene_animation(dir.file("tri.obj"), {}, &w));
}

TEST(GltfAnimation, MalformedAnimationDataIsAnErrorNamingTheFile) {
  testing::TempDir dir("gltf-anim");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  struct Case {
    const char* what;
    std::vector<float> times, values;
    const char* path;
    const char* interpolation;
    int node;
    const char* node_trs;
    const char* message;
  };
  const Case cases[] = {
      {"count", {0, 1}, {0, 0, 0}, "translation", "LINEAR", 0, "", "has 1 values for 2 key times; expected 2"},
      {"cubic count", {0, 1}, {0, 0, 0, 1, 1, 1}, "translation", "CUBICSPLINE", 0, "", "expected 6 (CUBICSPLINE"},
      {"decreasing", {1, 0.5f}, {0, 0, 0, 1, 1, 1}, "translation", "LINEAR", 0, "", "key times must increase strictly"},
      {"repeated", {1, 1}, {0, 0, 0, 1, 1, 1}, "translation", "LINEAR", 0, "", "key times must increase strictly"},
      {"negative", {-1, 1}, {0, 0, 0, 1, 1, 1}, "translation", "LINEAR", 0, "", "is negative"},
      {"nan time", {0, nan}, {0, 0, 0, 1, 1, 1}, "translation", "LINEAR", 0, "", "NaN or infinite"},
      {"nan value", {0, 1}, {0, 0, 0, nan, 1, 1}, "scale", "LINEAR", 0, "", "NaN or infinite"},
      {"missing node", {0, 1}, {0, 0, 0, 1, 1, 1}, "translation", "LINEAR", 7, "", "target.node = 7 names nothing"},
      {"interpolation", {0, 1}, {0, 0, 0, 1, 1, 1}, "translation", "SMOOTH", 0, "", "interpolation 'SMOOTH' is not LINEAR, STEP or CUBICSPLINE"},
      {"zero quaternion", {0, 1}, {0, 0, 0, 1, 0, 0, 0, 0}, "rotation", "LINEAR", 0, "", "rotation key 1 is a zero quaternion"},
      {"matrix", {0, 1}, {0, 0, 0, 1, 1, 1}, "translation", "LINEAR", 0, R"(,"matrix":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1])", "which has a matrix"},
  };
  for (const Case& k : cases) {
    GltfBuilder b;
    const int in = b.floats(k.times, "SCALAR");
    const int out = b.floats(k.values, std::string(k.path) == "rotation" ? "VEC4" : "VEC3");
    testing::write_bytes(dir.file("bad.gltf"), triangle_file(b, one_channel(k.node, k.path, in, out, k.interpolation), k.node_trs));
    std::vector<std::string> w;
    for (const bool still : {true, false}) {
      try {
        if (still) load_scene(dir.file("bad.gltf"), {}, &w);
        else load_scene_animation(dir.file("bad.gltf"), {}, &w);
        ADD_FAILURE() << k.what << ": no error";
      } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find(dir.file("bad.gltf")), std::string::npos) << k.what << ": " << m;
        EXPECT_NE(m.find(k.message), std::string::npos) << k.what << ": " << m;
      }
    }
  }
}

TEST(GltfAnimation, ChannelsThatNameNothingAreErrors) {
  testing::TempDir dir("gltf-anim");
  // Accessor 0: key times, 1: VEC3 values (the triangle's positions come after them).
  const std::pair<std::string, std::string> cases[] = {
      {R"([{"channels":[{"sampler":3,"target":{"node":0,"path":"translation"}}],"samplers":[{"input":0,"output":1}]}])", "sampler = 3 names nothing"},
      {R"([{"channels":[{"sampler":0,"target":{"node":0,"path":"translation"}}],"samplers":[{"input":0,"output":9}]}])", "= 9 names nothing"},
      {R"([{"channels":[{"sampler":0,"target":{"node":0,"path":"translation"}}],"samplers":[{"input":1,"output":1}]}])", "has the wrong type"},
      {R"([{"channels":[{"sampler":0,"target":{"node":0,"path":"translation"}},{"sampler":0,"target":{"node":0,"path":"translation"}}],)"
       R"("samplers":[{"input":0,"output":1}]}])", "nodes[0].translation is animated twice"},
  };
  for (const auto& [animations, message] : cases) {
    GltfBuilder fresh;
    const int i = fresh.floats({0, 1}, "SCALAR"), o = fresh.floats({0, 0, 0, 1, 1, 1}, "VEC3");
    ASSERT_EQ(i, 0);
    ASSERT_EQ(o, 1);
    testing::write_bytes(dir.file("bad.gltf"), triangle_file(fresh, animations));
    std::vector<std::string> w;
    try {
      load_scene_animation(dir.file("bad.gltf"), {}, &w);
      ADD_FAILURE() << message << ": no error";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(dir.file("bad.gltf")), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace pathspace
