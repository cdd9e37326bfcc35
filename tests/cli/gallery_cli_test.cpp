// `pathspace study gallery DIR`: scenes with a reference beside them are rendered at the
// reference's resolution and compared; a scene that cannot be loaded is listed with its error and
// does not stop the others; a folder without references, or no folder, is a usage error.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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

class CliGallery : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pathspace-cli-gallery-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "scenes");
  }
  void TearDown() override { fs::remove_all(dir_); }

  int run(const std::string& args) {
    const std::string cmd = "cd '" + dir_.string() + "' && '" PATHSPACE_BINARY "' " + args + " >/dev/null 2>stderr.txt";
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  void write(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
  }

  fs::path dir_;
};

TEST_F(CliGallery, RendersAtTheReferencesSizeAndMatchesItsOwnReference) {
  write(dir_ / "scenes/box/scene.pbrt", kScene);
  // The reference: the same scene, 256 spp of PT at 32x24 (not the file's 64x64).
  ASSERT_EQ(run("render scenes/box/scene.pbrt -r 32x24 -s 256 --seed 11 -o scenes/box/TungstenRender.exr"), 0);
  write(dir_ / "scenes/broken/scene.pbrt", "WorldBegin\nShape \"sphere\" \"float radius\" [\n");
  ASSERT_EQ(run("render scenes/box/scene.pbrt -r 8x8 -s 1 -o scenes/broken/TungstenRender.exr"), 0);
  ASSERT_EQ(run("study gallery scenes -i pt -t 1 -o out -q"), 0);
  std::ifstream in(dir_ / "out/gallery.json");
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
    EXPECT_TRUE(fs::is_regular_file(dir_ / "out" / box[key].get<std::string>())) << key;
  const nlohmann::json& broken = doc["scenes"][1];
  EXPECT_EQ(broken["name"], "broken");
  ASSERT_TRUE(broken.contains("error"));
  EXPECT_NE(broken["error"].get<std::string>().find("scene.pbrt:"), std::string::npos) << broken["error"];
  EXPECT_TRUE(fs::is_regular_file(dir_ / "out/gallery.html"));
}

TEST_F(CliGallery, NoFolderOrNoReferenceIsAUsageError) {
  EXPECT_EQ(run("study gallery missing-folder -o out -q"), 2);
  write(dir_ / "scenes/box/scene.pbrt", kScene);  // a scene, but no reference beside it
  EXPECT_EQ(run("study gallery scenes -o out -q"), 2);
  EXPECT_EQ(run("study gallery scenes -i no-such-integrator -o out -q"), 2);
  EXPECT_FALSE(fs::exists(dir_ / "out/gallery.json"));
}

}  // namespace
