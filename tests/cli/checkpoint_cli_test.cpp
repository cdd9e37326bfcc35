// Checkpoints, resume and interruption of `pathspace render` (docs/checkpoints.md), with the
// real binary:
//  - 3 passes + checkpoint + resume to 8 equals 8 passes straight, byte for byte (image, variance),
//    for pt, pt + hashed filter, pt + consistent filter (its radius follows the paths so far), lt, bpt,
//    sppm and pclt, resumed at 1 and at 2 threads; and
//    2 + 3 + 3 (resumed twice) too;
//  - SIGINT to a running render (a real process): exit 130, the outputs, --stats and the checkpoint
//    hold the same passes, the image equals a straight render of that many passes, and resuming it
//    continues bit for bit; SIGTERM exits 143;
//  - a changed image option, another scene, another format version, a truncated file and a flipped
//    byte are clear errors that write nothing and leave the checkpoint as it was;
//  - `pathspace info FILE` describes a checkpoint; --write-every and --checkpoint-every write while
//    rendering; two outputs naming one file are a usage error.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_process.h"

namespace {

namespace fs = std::filesystem;
using pathspace::testing::read_all;

struct Result {
  int exit_code = -1;
  std::string out, err;
};

void write_bytes(const fs::path& p, const std::string& bytes) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << bytes;
}

class Checkpoints : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    for (char& c : name)
      if (c == '/') c = '_';
    dir_ = fs::temp_directory_path() / ("pathspace-ckpt-" + std::to_string(::getpid()) + "-" + name);
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  Result run(const std::string& args) {
    const fs::path out = dir_.string() + ".stdout", err = dir_.string() + ".stderr";
    const std::string cmd = "cd '" + dir_.string() + "' && '" PATHSPACE_BINARY "' " + args + " >'" + out.string() + "' 2>'" + err.string() + "'";
    const int status = std::system(cmd.c_str());
    Result r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_all(out);
    r.err = read_all(err);
    fs::remove(out);
    fs::remove(err);
    return r;
  }
  void ok(const std::string& args) {
    const Result r = run(args);
    ASSERT_EQ(r.exit_code, 0) << args << "\n" << r.err;
  }
  std::string file(const std::string& name) const { return read_all(dir_ / name); }
  // The passes a checkpoint holds, as `pathspace info --json` reads them.
  uint32_t checkpoint_passes(const std::string& name) {
    const Result r = run("info --json " + name);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.exit_code == 0 ? nlohmann::json::parse(r.out).at("passes").get<uint32_t>() : 0;
  }
  bool exists(const std::string& name) const { return fs::exists(dir_ / name); }
  // Every file in the folder, for "nothing was written".
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  void expect_same_files(const std::string& a, const std::string& b) {
    const std::string x = file(a), y = file(b);
    EXPECT_FALSE(x.empty()) << a;
    EXPECT_TRUE(x == y) << a << " and " << b << " differ";
  }

  fs::path dir_;
};

constexpr const char* kScene = "cornell-box -r 24x16 --seed 11 --quiet";

struct ResumeCase {
  const char* name;
  const char* options;
};

void PrintTo(const ResumeCase& c, std::ostream* os) { *os << c.name; }

class ResumeEqualsStraight : public Checkpoints, public ::testing::WithParamInterface<ResumeCase> {};

TEST_P(ResumeEqualsStraight, ThreePlusFiveAndTwoPlusThreePlusThree) {
  const std::string base = std::string(kScene) + " " + GetParam().options;
  ok("render " + base + " -s 8 -j 2 -o straight.exr --variance-out straight-var.exr");
  for (const char* threads : {"1", "2"}) {
    SCOPED_TRACE(std::string("resumed with -j ") + threads);
    ok("render " + base + " -s 3 -j 2 -o a.exr --checkpoint a.ckpt");
    // The resume repeats none of the image options: they come from the checkpoint.
    ok(std::string("render --resume a.ckpt -s 8 -j ") + threads + " --quiet -o b.exr --variance-out b-var.exr");
    expect_same_files("b.exr", "straight.exr");
    expect_same_files("b-var.exr", "straight-var.exr");
  }
  ok("render " + base + " -s 2 -j 1 -o c.exr --checkpoint c.ckpt");
  ok("render --resume c.ckpt -s 5 -j 2 --quiet -o c.exr --checkpoint c.ckpt");
  ok("render --resume c.ckpt -s 8 -j 1 --quiet -o c.exr --variance-out c-var.exr --checkpoint c.ckpt");
  expect_same_files("c.exr", "straight.exr");
  expect_same_files("c-var.exr", "straight-var.exr");
}

INSTANTIATE_TEST_SUITE_P(Integrators, ResumeEqualsStraight,
                         ::testing::Values(ResumeCase{"pt", "-i pt"}, ResumeCase{"pt_hashed", "-i pt --filter hashed --psf-scale 4"},
                                           ResumeCase{"pt_hashed_caustics_clamp", "-i pt --filter hashed --psf-caustic-photons 2 --psf-clamp 4"},
                                           ResumeCase{"pt_hashed_one_bounce", "-i pt --filter hashed --psf-one-bounce-photons"},
                                           ResumeCase{"pt_consistent", "-i pt --filter consistent --psf-iterations 2 --psf-batch-memory 0.01"},
                                           ResumeCase{"pt_consistent_caustics_aa",
                                                      "-i pt --filter consistent --psf-aa-paths 1 --psf-caustic-photons 2 --psf-batch-memory 0.05"},
                                           ResumeCase{"lt", "-i lt"}, ResumeCase{"bpt", "-i bpt"},
                                           ResumeCase{"sppm", "-i sppm --photons 2000"}, ResumeCase{"pclt", "-i pclt --pclt-light-paths 2000"}),
                         [](const ::testing::TestParamInfo<ResumeCase>& info) { return std::string(info.param.name); });

// Starts `pathspace ARGS` in the test folder and returns its pid (output to log.txt).
pid_t spawn(const fs::path& dir, const std::string& args) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const std::string cmd = "cd '" + dir.string() + "' && exec '" PATHSPACE_BINARY "' " + args + " >log.txt 2>&1";
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

int wait_exit_code(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Interrupts a render once its first periodic checkpoint exists (so passes are done).
int interrupt_render(const fs::path& dir, const std::string& args, int sig) {
  const pid_t pid = spawn(dir, args);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(dir / "run.ckpt") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  ::kill(pid, sig);
  return wait_exit_code(pid);
}

TEST_F(Checkpoints, SigintWritesTheCompletedPassesAndResumesBitForBit) {
  const std::string scene = "cornell-box -r 32x24 --seed 3";
  const int code = interrupt_render(dir_, "render " + scene + " -s 1000000 -o run.exr --stats run.json --checkpoint run.ckpt --checkpoint-every 0.01", SIGINT);
  EXPECT_EQ(code, 130) << file("log.txt");
  EXPECT_NE(file("log.txt").find("interrupted by SIGINT"), std::string::npos) << file("log.txt");
  const uint32_t passes = checkpoint_passes("run.ckpt");
  ASSERT_GT(passes, 0u);
  const nlohmann::json stats = nlohmann::json::parse(file("run.json"));
  EXPECT_EQ(stats.at("spp").get<uint32_t>(), passes) << "the outputs and the checkpoint hold different passes";
  ok("render " + scene + " --quiet -s " + std::to_string(passes) + " -o straight.exr");
  expect_same_files("run.exr", "straight.exr");
  ok("render --resume run.ckpt --quiet -s " + std::to_string(passes + 3) + " -o resumed.exr");
  ok("render " + scene + " --quiet -s " + std::to_string(passes + 3) + " -o straight3.exr");
  expect_same_files("resumed.exr", "straight3.exr");
  for (const std::string& name : listing()) EXPECT_EQ(name.find(".tmp-"), std::string::npos) << name;
}

TEST_F(Checkpoints, SigtermExits143WithTheOutputs) {
  const int code = interrupt_render(dir_, "render cornell-box -r 32x24 -s 1000000 -o run.exr --checkpoint run.ckpt --checkpoint-every 0.01", SIGTERM);
  EXPECT_EQ(code, 143) << file("log.txt");
  EXPECT_TRUE(exists("run.exr"));
  EXPECT_GT(checkpoint_passes("run.ckpt"), 0u);
}

class CheckpointErrors : public Checkpoints {
 protected:
  void SetUp() override {
    Checkpoints::SetUp();
    ok(std::string("render ") + kScene + " -i sppm --sppm-alpha 0.6 -s 2 -o a.exr --checkpoint a.ckpt");
    original_ = file("a.ckpt");
  }
  // The resume fails with `code` and a message containing `part`, writes nothing, keeps a.ckpt.
  void expect_refused(const std::string& args, int code, const std::string& part) {
    SCOPED_TRACE(args);
    const std::vector<std::string> before = listing();
    const Result r = run("render --resume a.ckpt -s 4 --quiet -o b.exr --checkpoint a.ckpt " + args);
    EXPECT_EQ(r.exit_code, code) << r.err;
    EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(listing(), before) << "a refused resume wrote files";
    EXPECT_TRUE(file("a.ckpt") == original_) << "a refused resume changed the checkpoint";
  }
  std::string original_;
};

TEST_F(CheckpointErrors, ChangedImageOptionNamesIt) {
  expect_refused("--sppm-alpha 0.7", 2, "--sppm-alpha was '0.6' in the checkpoint, this render gives '0.7'");
  expect_refused("--seed 12", 2, "--seed was '11'");
  expect_refused("-r 32x32", 2, "--resolution was '24x16'");
  expect_refused("-i pt", 2, "--integrator was 'sppm'");
  expect_refused("--max-depth 4", 2, "--max-depth");
}

TEST_F(CheckpointErrors, OtherSceneIsRefused) { expect_refused("cornell-glossy", 2, "the checkpoint was made for the scene cornell-box"); }

TEST_F(CheckpointErrors, OtherFormatVersionIsRefused) {
  std::string bytes = original_;
  bytes[8] = 2;  // the version follows the 8 magic bytes
  write_bytes(dir_ / "a.ckpt", bytes);
  original_ = bytes;
  expect_refused("", 1, "format version 2, this pathspace");
}

TEST_F(CheckpointErrors, TruncatedFileIsRefused) {
  const std::string full = original_;
  for (const size_t size : {size_t(0), size_t(5), size_t(30), full.size() / 2, full.size() - 1}) {
    original_ = full.substr(0, size);
    write_bytes(dir_ / "a.ckpt", original_);
    expect_refused("", 1, size < 8 ? "does not start like a pathspace checkpoint" : "truncated");
  }
}

TEST_F(CheckpointErrors, FlippedByteIsRefused) {
  const std::string full = original_;
  for (const size_t at : {size_t(20), full.size() / 3, full.size() / 2, full.size() - 2}) {
    original_ = full;
    original_[at] = char(original_[at] ^ 0x10);
    write_bytes(dir_ / "a.ckpt", original_);
    expect_refused("", 1, "a.ckpt: not a usable checkpoint");
  }
}

TEST_F(CheckpointErrors, InfoDescribesIt) {
  const Result r = run("info a.ckpt");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string& text = r.out;
  for (const char* part : {"scene        cornell-box", "integrator   sppm", "24x16, seed 11", "passes       2", "--sppm-alpha", "0.6"})
    EXPECT_NE(text.find(part), std::string::npos) << part << "\n" << text;
  const Result json = run("info --json a.ckpt");
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const nlohmann::json j = nlohmann::json::parse(json.out);
  EXPECT_EQ(j.at("integrator"), "sppm");
  EXPECT_EQ(j.at("passes"), 2);
  EXPECT_EQ(j.at("options").at("sppm-alpha"), "0.6");
  EXPECT_EQ(run("info missing.ckpt").exit_code, 2);
  write_bytes(dir_ / "bad.ckpt", "PSCKPT\r\n");
  EXPECT_EQ(run("info bad.ckpt").exit_code, 1);
}

TEST_F(Checkpoints, PeriodicWritesEndInTheFinalOutputs) {
  ok(std::string("render ") + kScene + " -s 40 -o a.exr -o a.png --stats a.json --checkpoint a.ckpt --checkpoint-every 0.001 --write-every 0.001");
  ok(std::string("render ") + kScene + " -s 40 -o b.exr");
  expect_same_files("a.exr", "b.exr");
  EXPECT_EQ(checkpoint_passes("a.ckpt"), 40u);
  EXPECT_EQ(nlohmann::json::parse(file("a.json")).at("spp"), 40);
  for (const std::string& name : listing()) EXPECT_EQ(name.find(".tmp-"), std::string::npos) << name;
}

TEST_F(Checkpoints, OutputsNamingOneFileAreUsageErrors) {
  EXPECT_EQ(run(std::string("render ") + kScene + " -s 1 -o x.exr --stats x.exr").exit_code, 2);
  EXPECT_EQ(run(std::string("render ") + kScene + " -s 1 -o x.exr --variance-out ./x.exr").exit_code, 2);
  EXPECT_EQ(run(std::string("render ") + kScene + " -s 1 -o x.exr --checkpoint x.exr").exit_code, 2);
  EXPECT_EQ(run(std::string("render ") + kScene + " -s 1 -o x.exr --checkpoint-every 1").exit_code, 2) << "needs --checkpoint";
  EXPECT_EQ(run("render --resume none.ckpt -s 2 -o x.exr").exit_code, 1);
  EXPECT_TRUE(listing().empty());
}

TEST_F(Checkpoints, ResumeNeedsATotalOrATime) {
  ok(std::string("render ") + kScene + " -s 3 -o a.exr --checkpoint a.ckpt");
  EXPECT_EQ(run("render --resume a.ckpt -o b.exr").exit_code, 2);
  EXPECT_EQ(run("render --resume a.ckpt -s 2 -o b.exr").exit_code, 2) << "fewer passes than the checkpoint holds";
  ok("render --resume a.ckpt -s 3 --quiet -o b.exr");
  expect_same_files("a.exr", "b.exr");
  ok("render --resume a.ckpt -t 0.2 --quiet -o c.exr --checkpoint c.ckpt");
  EXPECT_GT(checkpoint_passes("c.ckpt"), 3u);
}

TEST_F(Checkpoints, DebugImagesAreOfTheLastPassRenderedHere) {
  ok(std::string("render ") + kScene + " --filter hashed --aov -s 2 -o a.exr --checkpoint a.ckpt");
  EXPECT_TRUE(exists("a.aov-count.exr"));
  ok("render --resume a.ckpt -s 2 --quiet -o b.exr");  // no new pass: no debug images to write
  expect_same_files("a.exr", "b.exr");
  EXPECT_FALSE(exists("b.aov-count.exr"));
  ok("render --resume a.ckpt -s 3 --quiet -o c.exr");
  EXPECT_TRUE(exists("c.aov-count.exr"));
}

}  // namespace
