// `pathspace study gallery DIR`: scenes with a reference beside them are rendered at the
// reference's resolution and compared; a scene that cannot be loaded is listed with its error and
// does not stop the others; a folder without references, or no folder, is a usage error.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_process.h"
#include "support/temp_dir.h"

namespace {

namespace fs = std::filesystem;

// A floor, a sphere and a small ceiling light, in pbrt-v4's format.
constexpr const char* kScene = R"(LookAt 0 1 -3  0 0.5 0  0 1 0
Camera "perspective" "float fov" [50]
Film "rgb" "integer xresolution" [64] "integer yresolution" [64] "string filename" "unused.exr"
WorldBegin
AttributeBegin
AreaLightSource "diffuse" "rgb L" [20 20 20]
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-0.5 1.99 -0.5  0.5 1.99 -0.5  0.5 1.99 0.5  -0.5 1.99 0.5]
AttributeEnd
Material "diffuse" "rgb reflectance" [0.6 0.4 0.2]
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-2 0 -2  2 0 -2  2 0 2  -2 0 2]
Shape "sphere" "float radius" [0.4]
)";

// A folder of scenes and the gallery's output, with paths for the command line.
class CliGallery : public ::testing::Test {
 protected:
  int run(const std::string& args) { return pathspace::testing::run_pathspace(args).exit_code; }
  void write(const std::string& relative, const std::string& text) {
    const fs::path path = dir_.path / relative;
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
  }
  // Quoted for the shell; appended piecewise (GCC 12 warns falsely, -Wrestrict, on "'" + s + "'").
  std::string at(const std::string& relative) const {
    std::string quoted = "'";
    quoted += dir_.file(relative);
    quoted += "'";
    return quoted;
  }

  pathspace::testing::TempDir dir_{"cli-gallery"};
};

TEST_F(CliGallery, RendersAtTheReferencesSizeAndMatchesItsOwnReference) {
  write("scenes/box/scene.pbrt", kScene);
  // The reference: the same scene, 256 spp of PT at 32x24 (not the file's 64x64).
  ASSERT_EQ(run("render " + at("scenes/box/scene.pbrt") + " -r 32x24 -s 256 --seed 11 -o " + at("scenes/box/TungstenRender.exr")), 0);
  write("scenes/broken/scene.pbrt", "WorldBegin\nShape \"sphere\" \"float radius\" [\n");
  ASSERT_EQ(run("render " + at("scenes/box/scene.pbrt") + " -r 8x8 -s 1 -o " + at("scenes/broken/TungstenRender.exr")), 0);
  ASSERT_EQ(run("study gallery " + at("scenes") + " -i pt -t 1 -o " + at("out") + " -q"), 0);
  std::ifstream in(dir_.path / "out/gallery.json");
  const nlohmann::json doc = nlohmann::json::parse(in);
  ASSERT_EQ(doc["scenes"].size(), 2u);
  const nlohmann::json& box = doc["scenes"][0];
  EXPECT_EQ(box["name"], "box");
  EXPECT_EQ(box["width"], 32);
  EXPECT_EQ(box["height"], 24);
  EXPECT_GE(box["passes"].get<int>(), 1);
  // Two independent unbiased renders of the same scene: the channel means agree. The image mean
  // over 768 pixels of a 256-spp reference and >= 1 pass is within ~1% (seen: 0.3%); 5% leaves room
  // for a slow machine's single pass.
  for (int c = 0; c < 3; ++c) {
    const double r = box["mean_ratio"][c].get<double>();
    EXPECT_GT(r, 0.95) << "channel " << c;
    EXPECT_LT(r, 1.05) << "channel " << c;
  }
  for (const char* key : {"image", "error_map", "reference_image"})
    EXPECT_TRUE(fs::is_regular_file(dir_.path / "out" / box[key].get<std::string>())) << key;
  const nlohmann::json& broken = doc["scenes"][1];
  EXPECT_EQ(broken["name"], "broken");
  ASSERT_TRUE(broken.contains("error"));
  EXPECT_NE(broken["error"].get<std::string>().find("scene.pbrt:"), std::string::npos) << broken["error"];
  EXPECT_TRUE(fs::is_regular_file(dir_.path / "out/gallery.html"));
}

TEST_F(CliGallery, NoFolderOrNoReferenceIsAUsageError) {
  const std::string out = " -o " + at("out") + " -q";
  EXPECT_EQ(run("study gallery " + at("missing-folder") + out), 2);
  write("scenes/box/scene.pbrt", kScene);  // a scene, but no reference beside it
  EXPECT_EQ(run("study gallery " + at("scenes") + out), 2);
  EXPECT_EQ(run("study gallery " + at("scenes") + " -i no-such-integrator" + out), 2);
  EXPECT_FALSE(fs::exists(dir_.path / "out/gallery.json"));
}

}  // namespace
