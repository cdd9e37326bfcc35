// `pathspace render --frames`: numbered outputs, per-frame statistics, the animation options' usage
// errors, and --video with and without ffmpeg (docs/animation.md).
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_process.h"
#include "pathspace/io/image_io.h"
#include "support/gltf_test_files.h"

namespace {

namespace fs = std::filesystem;
using pathspace::testing::read_all;
using pathspace::testing::run_pathspace;

class FramesCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pathspace-frames-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(FramesCli, WritesOneFilePerFrameAndOneStatsEntryPerFrame) {
  const auto r = run_pathspace("render cornell-moving-light -r 24x24 --frames 2:5 --filter hashed --temporal integrate -q -o " +
                               path("f-%03d.exr") + " --stats " + path("s.json"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  for (int f = 2; f <= 5; ++f) EXPECT_TRUE(fs::exists(path("f-00" + std::to_string(f) + ".exr"))) << f;
  EXPECT_FALSE(fs::exists(path("f-001.exr")));
  const nlohmann::json j = nlohmann::json::parse(read_all(path("s.json")));
  ASSERT_EQ(j["frames"].size(), 4u);
  EXPECT_EQ(j["frames"][0]["frame"], 2);
  EXPECT_EQ(j["frames"][3]["statistics"]["hashed.temporal.steps"], 4);
  EXPECT_GT(j["frames"][3]["statistics"]["hashed.temporal.mean_alpha_last"].get<double>(), 0.5);
}

// Frames are written on a thread of their own while the next renders: a frame that cannot be
// written still ends the sequence with an error naming its file, the frames before it are on disk,
// and --stats, which describes a finished sequence, is not written.
TEST_F(FramesCli, AFrameThatCannotBeWrittenEndsTheSequenceNamingItsFile) {
  fs::create_directories(path("w-0001.png"));  // a folder where frame 1's file would go
  for (const char* frames : {"0:5", "0:1"}) {  // frame 1 in the middle, and last (its error comes after the loop)
    fs::remove(path("w-0000.png"));
    const auto r = run_pathspace("render cornell-box -r 16x16 --frames " + std::string(frames) + " -q -o " + path("w-%04d.png") +
                                 " --stats " + path("w.json"));
    EXPECT_EQ(r.exit_code, 1) << frames << "\n" << r.out;
    EXPECT_NE(r.out.find(path("w-0001.png")), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(path("w-0000.png"))) << frames;
    EXPECT_TRUE(fs::is_directory(path("w-0001.png")));
    EXPECT_FALSE(fs::exists(path("w.json"))) << frames;
  }
}

// A sequence computes each frame's variance only for --variance-out, and then writes it per frame.
TEST_F(FramesCli, VarianceOutWritesEachFramesVariance) {
  const auto r = run_pathspace("render cornell-box -r 16x16 --frames 0:1 -s 4 -q -o " + path("m-%d.exr") + " --variance-out " +
                               path("v-%d.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  for (const char* name : {"v-0.exr", "v-1.exr"}) {
    const pathspace::Image v = pathspace::read_image(path(name));
    ASSERT_EQ(v.width, 16) << name;
    double sum = 0.0;
    for (const pathspace::Rgb& c : v.pixels) sum += double(c.r) + c.g + c.b;
    EXPECT_GT(sum, 0.0) << name;  // 4 passes a frame: a variance where paths differ
  }
}

TEST_F(FramesCli, CameraPathAndOrbitMoveTheCamera) {
  std::ofstream(path("cam.json")) << R"({"keyframes": [
    {"time": 0, "position": [0, -4, 0.2], "target": [0, 0, 0], "up": [0, 0, 1], "fov": 40},
    {"time": 1, "position": [1, -4, 0.2], "target": [0, 0, 0], "up": [0, 0, 1]}]})";
  auto r = run_pathspace("render cornell-box -r 16x16 --frames 0:1 -q --camera-path " + path("cam.json") + " -o " + path("c-%d.png"));
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(fs::exists(path("c-1.png")));
  r = run_pathspace("render cornell-box -r 16x16 --frames 0:1 -q --orbit 10 -o " + path("o-%d.png"));
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(read_all(path("o-0.png")), read_all(path("o-1.png")));
}

TEST_F(FramesCli, BadCameraPathNamesFileLineAndColumn) {
  std::ofstream(path("bad.json")) << "{\"keyframes\": [\n  {\"time\": 0,, }]}";
  const auto r = run_pathspace("render cornell-box -r 16x16 --frames 0:1 -q --camera-path " + path("bad.json") + " -o " + path("b-%d.png"));
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find(path("bad.json") + ":2:"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(path("b-0.png")));
}

TEST_F(FramesCli, MisuseIsAUsageError) {
  for (const std::string& args :
       {"--frames 0:1 -o " + path("no-number.exr"), "--frames 3:1 -o " + path("a-%d.exr"), "--frames x -o " + path("a-%d.exr"),
        "--orbit 5 -o " + path("a.exr"), "--frames 0:1 --checkpoint " + path("c.ckpt") + " -o " + path("a-%d.exr"),
        "--frames 0:1 -o " + path("a-%d-%d.exr"),
        "--frames 0:1 --filter hashed --temporal integrate --temporal-rectify -o " + path("a-%d.exr")}) {
    const auto r = run_pathspace("render cornell-box -r 8x8 -q " + args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.out;
  }
}

// A glTF file whose triangle slides out of the camera's view in its first second (docs/animation.md).
TEST_F(FramesCli, GltfAnimationMovesTheScene) {
  pathspace::testing::GltfBuilder b;
  const int pos = b.floats({-1, -1, 0, 1, -1, 0, 0, 1, 0}, "VEC3");
  const int times = b.floats({0, 1}, "SCALAR"), moves = b.floats({0, 0, 0, 50, 0, 0}, "VEC3");
  std::ofstream(path("slide.gltf")) << b.gltf(
      R"("scenes":[{"nodes":[0,1]}],"nodes":[{"mesh":0},{"camera":0,"translation":[0,0,3]}],)"
      R"("cameras":[{"type":"perspective","perspective":{"yfov":0.8,"znear":0.1}}],)"
      R"("meshes":[{"primitives":[{"attributes":{"POSITION":)" + std::to_string(pos) + R"(},"material":0}]}],)"
      R"("materials":[{"pbrMetallicRoughness":{"baseColorFactor":[0.2,0.2,0.2,1],"metallicFactor":0}}],)"
      R"("animations":[{"channels":[{"sampler":0,"target":{"node":0,"path":"translation"}}],)"
      R"("samplers":[{"input":)" + std::to_string(times) + R"(,"output":)" + std::to_string(moves) + "}]}]");
  const auto r = run_pathspace("render " + path("slide.gltf") + " -r 16x16 --frames 0:1 --fps 1 -q -o " + path("g-%d.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const pathspace::Image f0 = pathspace::read_image(path("g-0.exr")), f1 = pathspace::read_image(path("g-1.exr"));
  // The centre pixel sees the dark triangle under the white environment in frame 0 and the
  // environment itself (radiance 1) in frame 1.
  EXPECT_LT(f0.at(8, 8).g, 0.6f);
  EXPECT_NEAR(f1.at(8, 8).g, 1.f, 1e-3f);
}

TEST_F(FramesCli, VideoWithoutFfmpegNamesIt) {
  // Without ffmpeg on PATH (an empty PATH keeps the shell's builtins only).
  const std::string cmd = "PATH= '" PATHSPACE_BINARY "' render cornell-box -r 8x8 -q --frames 0:1 -o " + path("w-%d.png") +
                          " --video " + path("w.mp4") + " > " + path("log") + " 2>&1";
  const int status = std::system(cmd.c_str());
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_NE(read_all(path("log")).find("ffmpeg"), std::string::npos) << read_all(path("log"));
  EXPECT_FALSE(fs::exists(path("w-0.png")));
}

TEST_F(FramesCli, VideoIsEncodedWithFfmpeg) {
  if (std::system("command -v ffmpeg > /dev/null 2>&1") != 0) GTEST_SKIP() << "ffmpeg is not installed (scripts/install-deps installs it)";
  const auto r = run_pathspace("render cornell-moving-sphere -r 33x17 -q --frames 0:4 -o " + path("v-%04d.exr") + " --video " + path("v.mp4"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_GT(fs::file_size(path("v.mp4")), 100u);
  EXPECT_FALSE(fs::exists(path(".v.frames")));  // the temporary PNG frames are gone
}

}  // namespace
