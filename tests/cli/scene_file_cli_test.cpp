// `pathspace render` on a scene with missing images (the Bitterli living room; fails when the
// shared scenes are absent, support/shared_data.h): without options one error line names every missing file and its line
// and nothing is written; --substitute-missing-textures renders with a warning per file.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "support/shared_data.h"

namespace {

namespace fs = std::filesystem;

const std::string kLivingRoom = std::string(PATHSPACE_SHARED_SCENES_DIR) + "/bitterli/living-room/scene-v4.pbrt";

struct RunResult {
  int exit_code = -1;
  std::string err;
};

class CliSceneFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pathspace-cli-scenes-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  RunResult run(const std::string& args) {
    const std::string cmd = "cd '" + dir_.string() + "' && '" PATHSPACE_BINARY "' " + args + " >/dev/null 2>stderr.txt";
    const int status = std::system(cmd.c_str());
    RunResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(dir_ / "stderr.txt");
    std::stringstream ss;
    ss << in.rdbuf();
    r.err = ss.str();
    return r;
  }

  fs::path dir_;
};

size_t count_substrings(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST_F(CliSceneFiles, MissingImagesAreOneErrorOrSubstituted) {
  PATHSPACE_REQUIRE_SHARED_DATA(kLivingRoom);
  const std::string args = "render '" + kLivingRoom + "' --spp 1 --resolution 16x9 --quiet -o out.png";
  RunResult r = run(args);
  EXPECT_EQ(r.exit_code, 1);
  // One error line; the warnings gathered before it (unsupported statements) come first.
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1 + count_substrings(r.err, ": warning: ")) << r.err;
  EXPECT_EQ(count_substrings(r.err, "error:"), 1) << r.err;
  for (const char* part : {"textures/wood.tga' at ", "scene-v4.pbrt:21:5", "textures/wood5.tga' at ", "scene-v4.pbrt:24:5",
                           "textures/Sky 19.pfm' at ", "scene-v4.pbrt:311:9", "--substitute-missing-textures"})
    EXPECT_NE(r.err.find(part), std::string::npos) << part << "\n" << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.png"));

  r = run(args + " --substitute-missing-textures");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  for (const char* part : {"scene-v4.pbrt:21:5: warning: texture file 'textures/wood.tga' not found",
                           "scene-v4.pbrt:24:5: warning: texture file 'textures/wood5.tga' not found",
                           "scene-v4.pbrt:311:9: warning: environment map 'textures/Sky 19.pfm' not found"})
    EXPECT_NE(r.err.find(part), std::string::npos) << part << "\n" << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "out.png"));
}

TEST_F(CliSceneFiles, SubstituteFlagIsForSceneFilesOnly) {
  const RunResult r = run("render cornell-box --substitute-missing-textures --spp 1 -r 8x8 -q -o out.png");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("apply to scene files only"), std::string::npos) << r.err;
}

}  // namespace
