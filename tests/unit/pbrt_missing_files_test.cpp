// Missing files referenced by a pbrt scene: without options, one Error lists every missing file with
// the file:line:column that names it; with SceneLoadOptions::substitute_missing_textures, images get
// neutral stand-ins (mid-grey texture, white environment) with one warning each. Checked on a small
// scene in a temp folder and on the Bitterli living room, which lacks three of its images.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "pathspace/base/error.h"
#include "pathspace/io/scene_loader.h"
#include "support/shared_data.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

namespace fs = std::filesystem;
using pathspace::testing::TempDir;

const char* kScene =
    "Camera \"perspective\"\nWorldBegin\n"
    "Texture \"a\" \"spectrum\" \"imagemap\" \"string filename\" \"textures/gone.tga\"\n"  // line 3, column 35
    "Texture \"b\" \"float\" \"imagemap\"\n  \"string filename\" [ \"gone too.png\" ]\n"   // line 5, column 3
    "Material \"diffuse\" \"texture reflectance\" \"a\"\nShape \"sphere\"\n"
    "LightSource \"infinite\" \"float scale\" 3 \"string filename\" \"sky.pfm\"\n";    // line 8, column 40

std::string error_message(const std::string& path, const SceneLoadOptions& o = {}) {
  try {
    load_scene(path, o, nullptr);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

bool has_warning(const std::vector<std::string>& w, const std::string& part) {
  for (const std::string& s : w)
    if (s.find(part) != std::string::npos) return true;
  return false;
}

TEST(PbrtMissingFiles, OneErrorListsEveryFileWithItsLocation) {
  const TempDir dir("missing");
  const std::string path = dir.file("scene.pbrt");
  std::ofstream(path) << kScene << "Shape \"plymesh\" \"string filename\" \"models/gone.ply\"\n";  // line 9, column 17
  const std::string m = error_message(path);
  EXPECT_EQ(m.rfind(path + ":3:35: 4 referenced files are missing: ", 0), 0u) << m;
  EXPECT_NE(m.find("texture file 'textures/gone.tga' at " + path + ":3:35"), std::string::npos) << m;
  EXPECT_NE(m.find("texture file 'gone too.png' at " + path + ":5:3"), std::string::npos) << m;
  EXPECT_NE(m.find("environment map 'sky.pfm' at " + path + ":8:40"), std::string::npos) << m;
  EXPECT_NE(m.find("PLY mesh 'models/gone.ply' at " + path + ":9:17"), std::string::npos) << m;
  EXPECT_NE(m.find("--substitute-missing-textures"), std::string::npos) << m;
  EXPECT_EQ(m.find('\n'), std::string::npos) << "the CLI prints errors on one line";
}

TEST(PbrtMissingFiles, SubstitutesGreyTexturesAndWhiteEnvironmentWithWarnings) {
  const TempDir dir("missing");
  const std::string path = dir.file("scene.pbrt");
  std::ofstream(path) << kScene;
  SceneLoadOptions o;
  o.substitute_missing_textures = true;
  std::vector<std::string> w;
  const Scene s = load_scene(path, o, &w);
  ASSERT_EQ(s.spheres.size(), 1u);
  EXPECT_EQ(s.materials[s.spheres[0].material].diffuse, Rgb(0.5f));
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].type, LightType::environment);
  EXPECT_EQ(s.lights[0].value, Rgb(3.f));  // radiance 1 times the light's scale
  EXPECT_TRUE(has_warning(w, path + ":3:35: warning: texture file 'textures/gone.tga' not found")) << w.size();
  EXPECT_TRUE(has_warning(w, path + ":5:3: warning: texture file 'gone too.png' not found"));
  EXPECT_TRUE(has_warning(w, path + ":8:40: warning: environment map 'sky.pfm' not found"));
  EXPECT_TRUE(has_warning(w, "substituted by a constant mid grey (0.5)"));
  // A missing mesh is not substituted: still an error.
  std::ofstream(path, std::ios::app) << "Shape \"plymesh\" \"string filename\" \"gone.ply\"\n";
  EXPECT_NE(error_message(path, o).find("1 referenced file is missing: PLY mesh 'gone.ply'"), std::string::npos);
}

const std::string kLivingRoom = std::string(PATHSPACE_SHARED_SCENES_DIR) + "/bitterli/living-room/scene-v4.pbrt";

TEST(PbrtLivingRoom, StopsNamingEachMissingImage) {
  PATHSPACE_REQUIRE_SHARED_DATA(kLivingRoom);
  const std::string m = error_message(kLivingRoom);
  EXPECT_NE(m.find("3 referenced files are missing"), std::string::npos) << m;
  EXPECT_NE(m.find("texture file 'textures/wood.tga' at " + kLivingRoom + ":21:5"), std::string::npos) << m;
  EXPECT_NE(m.find("texture file 'textures/wood5.tga' at " + kLivingRoom + ":24:5"), std::string::npos) << m;
  EXPECT_NE(m.find("environment map 'textures/Sky 19.pfm' at " + kLivingRoom + ":311:9"), std::string::npos) << m;
}

TEST(PbrtLivingRoom, LoadsWithSubstitutedImages) {
  PATHSPACE_REQUIRE_SHARED_DATA(kLivingRoom);
  SceneLoadOptions o;
  o.substitute_missing_textures = true;
  o.width = 64, o.height = 36;
  std::vector<std::string> w;
  const Scene s = load_scene(kLivingRoom, o, &w);
  EXPECT_GT(s.triangles.size(), 10000u);
  EXPECT_TRUE(has_warning(w, ":21:5: warning: texture file 'textures/wood.tga' not found"));
  EXPECT_TRUE(has_warning(w, ":24:5: warning: texture file 'textures/wood5.tga' not found"));
  EXPECT_TRUE(has_warning(w, ":311:9: warning: environment map 'textures/Sky 19.pfm' not found"));
  bool environment = false;
  for (const Light& l : s.lights) environment |= l.type == LightType::environment && l.value == Rgb(1.f);
  EXPECT_TRUE(environment);
}

}  // namespace
}  // namespace pathspace
