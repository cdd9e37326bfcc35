// SceneSources (scene/scene_sources.h): which statement made which element, and the scene file for
// the rest; scene validation puts the location in front of its message.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/scene/scene.h"
#include "pathspace/scene/scene_validation.h"

namespace pathspace {
namespace {

TEST(SceneSources, FindsTheRangeOfAnElement) {
  SceneSources s;
  s.mark(SceneSources::kVertex, 0, 3, FileLoc{"a.pbrt", 4, 1});
  s.mark(SceneSources::kVertex, 5, 9, FileLoc{"b.pbrt", 7, 3});
  s.mark(SceneSources::kVertex, 9, 9, FileLoc{"c.pbrt", 1, 1});  // empty: nothing recorded
  s.mark(SceneSources::kVertex, 2, 12, FileLoc{"d.pbrt", 1, 1});  // overlaps: ignored
  ASSERT_NE(s.find(SceneSources::kVertex, 2), nullptr);
  EXPECT_EQ(s.find(SceneSources::kVertex, 2)->to_string(), "a.pbrt:4:1");
  EXPECT_EQ(s.find(SceneSources::kVertex, 3), nullptr);  // between the ranges, no fallback
  EXPECT_EQ(s.find(SceneSources::kVertex, 8)->to_string(), "b.pbrt:7:3");
  EXPECT_EQ(s.find(SceneSources::kVertex, 9), nullptr);
  EXPECT_EQ(s.find(SceneSources::kSphere, 0), nullptr);
  s.set_fallback(FileLoc{"scene.pbrt"});
  EXPECT_EQ(s.find(SceneSources::kVertex, 3)->to_string(), "scene.pbrt");
  EXPECT_EQ(s.find(SceneSources::kSphere, 0)->to_string(), "scene.pbrt");
  EXPECT_EQ(s.camera()->to_string(), "scene.pbrt");
  s.set_camera(FileLoc{"scene.pbrt", 2, 1});
  EXPECT_EQ(s.camera()->to_string(), "scene.pbrt:2:1");
}

TEST(SceneSources, ValidationErrorsStartWithTheLocation) {
  Scene scene;
  scene.camera = make_perspective_camera(Vec3(0, 0, 5), Vec3(0, 0, -1), Vec3(0, 1, 0), 40.f, 8, 8);
  const uint32_t good = scene.add_material(Material{});
  Material bad;
  bad.diffuse = Rgb(-1.f, 0.f, 0.f);
  const auto before = SceneSizes::of(scene);
  scene.add_material(bad);
  before.mark_since(&scene, FileLoc{"s.pbrt", 9, 1});
  scene.add_sphere(Vec3(), 1.f, good);
  scene.add_point_light(Vec3(0, 0, 4), Rgb(1.f));
  std::vector<std::string> warnings;
  try {
    validate_scene(scene, &warnings);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("s.pbrt:9:1: material 1: diffuse reflectance", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace pathspace
