// `pathspace info SCENE_FILE` (apps/pathspace/scene_summary.h): counts of what the scene file holds
// as pathspace reads it (also for a built-in scene by name or id), and what the loader approximated or ignored with its file:line:column; a
// scene that does not load is the same error as for `render`.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

#include "cli_process.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

const std::string kRoom = std::string(PATHSPACE_SOURCE_DIR) + "/scenes/textured-room/scene.pbrt";

TEST(InfoScene, CountsAndWarningsWithTheirLocation) {
  const testing::Run r = testing::run_pathspace("info '" + kRoom + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("32 triangles (64 vertices), 0 spheres"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("area (triangles)           2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("environment                1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("the file suggests 64 spp"), std::string::npos) << r.out;
  // The room's sky map is a pbrt-v3 lat-long map: approximated, at the statement's line.
  EXPECT_NE(r.out.find("scene.pbrt:22:3: warning: environment map"), std::string::npos) << r.out;

  const testing::Run j = testing::run_pathspace("info --json '" + kRoom + "'");
  ASSERT_EQ(j.exit_code, 0) << j.out;
  const nlohmann::json parsed = nlohmann::json::parse(j.out.substr(j.out.find('{')));
  EXPECT_EQ(parsed["triangles"], 32);
  EXPECT_EQ(parsed["lights"]["area (triangles)"], 2);
  EXPECT_EQ(parsed["materials"]["diffuse"], 4);
  EXPECT_EQ(parsed["warnings"].size(), 1u);
  // Texture memory as rendered: the room's PNG textures 3 bytes a texel (8-bit kept as 8-bit), its
  // environment image 12 (float RGB).
  const size_t env = parsed["environment_image"].is_null() ? 0 : size_t(parsed["environment_image"][0]) * size_t(parsed["environment_image"][1]);
  EXPECT_EQ(parsed["texture_bytes"], size_t(parsed["texels"]) * 3 + env * 12);
  EXPECT_NE(r.out.find("MiB in memory"), std::string::npos) << r.out;
}

// Layered materials count under their own kind, not under their base's lobes.
TEST(InfoScene, CoatedMaterialsHaveTheirOwnKind) {
  const testing::TempDir dir("info-coated");
  const std::string file = (dir.path / "coated.pbrt").string();
  std::ofstream(file) << "Camera \"perspective\"\nWorldBegin\nMaterial \"coateddiffuse\"\nShape \"sphere\"\n"
                         "Material \"coatedconductor\"\nShape \"sphere\" \"float radius\" 0.5\n"
                         "Material \"diffuse\"\nShape \"sphere\" \"float radius\" 0.25\n"
                         "LightSource \"point\" \"rgb I\" [ 1 1 1 ]\n";
  const testing::Run j = testing::run_pathspace("info --json '" + file + "'");
  ASSERT_EQ(j.exit_code, 0) << j.out;
  const nlohmann::json parsed = nlohmann::json::parse(j.out.substr(j.out.find('{')));
  EXPECT_EQ(parsed["materials"]["coated diffuse"], 1) << j.out;
  EXPECT_EQ(parsed["materials"]["coated conductor"], 1) << j.out;
  EXPECT_EQ(parsed["materials"]["diffuse"], 1) << j.out;
}

TEST(InfoScene, BuiltInScenesByNameOrId) {
  const testing::Run r = testing::run_pathspace("info cornell-box");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("built-in scene cornell-box"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("camera       512x512"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("area (triangles)"), std::string::npos) << r.out;
  const testing::Run j = testing::run_pathspace("info --json gbs_p");  // by id
  ASSERT_EQ(j.exit_code, 0) << j.out;
  const nlohmann::json parsed = nlohmann::json::parse(j.out.substr(j.out.find('{')));
  EXPECT_EQ(parsed["builtin"], "cornell-glossy-point");
  EXPECT_TRUE(parsed["file"].is_null());
  EXPECT_EQ(parsed["lights"]["point"], 1);
  // Neither a file nor a built-in scene: a usage error naming it.
  const testing::Run missing = testing::run_pathspace("info no-such-scene");
  EXPECT_EQ(missing.exit_code, 2) << missing.out;
  EXPECT_NE(missing.out.find("no-such-scene"), std::string::npos) << missing.out;
}

TEST(InfoScene, ABadSceneIsAnInputError) {
  testing::TempDir dir("info-scene");
  const std::string file = dir.file("bad.pbrt");
  {
    std::ofstream(file) << "LookAt 0 0 5 0 0 0 0 1 0\nCamera \"perspective\"\nWorldBegin\n"
                           "LightSource \"point\" \"rgb I\" [1 1 1]\nShape \"sphere\" \"float radius\" 1e20\n";
  }
  const testing::Run r = testing::run_pathspace("info '" + file + "'");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("bad.pbrt:5:1: the radius of sphere 0"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace pathspace
