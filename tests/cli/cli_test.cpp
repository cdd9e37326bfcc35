// Runs the pathspace binary as a user would: bad input must give a non-zero exit, one clear line on
// stderr and no output file; a good run must write every requested file and a parsable --stats JSON.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

struct CliResult {
  int exit_code = -1;
  std::string out, err;
};

std::string read_all(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pathspace-cli-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs `pathspace ARGS` inside the test's own folder.
  CliResult run(const std::string& args) {
    const std::string cmd = "cd '" + dir_.string() + "' && '" PATHSPACE_BINARY "' " + args + " >stdout.txt 2>stderr.txt";
    const int status = std::system(cmd.c_str());
    CliResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_all(dir_ / "stdout.txt");
    r.err = read_all(dir_ / "stderr.txt");
    fs::remove(dir_ / "stdout.txt");
    fs::remove(dir_ / "stderr.txt");
    return r;
  }

  // Files the run left in the test folder (recursively).
  int file_count() const {
    int n = 0;
    for (const auto& e : fs::recursive_directory_iterator(dir_)) n += e.is_regular_file();
    return n;
  }

  void expect_usage_error(const std::string& args, const std::string& message_part) {
    SCOPED_TRACE(args);
    const CliResult r = run(args);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(message_part), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("run '"), std::string::npos) << "no usage hint: " << r.err;
    EXPECT_EQ(file_count(), 0) << "a failed run left files behind";
  }

  fs::path dir_;
};

constexpr const char* kSmall = "--resolution 16x12 --spp 2 --quiet";

TEST_F(CliTest, UnknownSceneIsAUsageError) { expect_usage_error(std::string("render no-such-scene ") + kSmall, "no-such-scene"); }

TEST_F(CliTest, UnknownIntegratorIsAUsageError) {
  expect_usage_error(std::string("render --integrator nope ") + kSmall, "unknown integrator 'nope'");
}

TEST_F(CliTest, BadNumbersAreUsageErrors) {
  expect_usage_error("render --spp 0", "--spp");
  expect_usage_error("render --spp abc", "--spp");
  expect_usage_error("render --spp -3", "--spp");
  expect_usage_error("render --time 0", "--time");
  expect_usage_error("render --resolution 64", "--resolution");
  expect_usage_error("render --resolution 64x0", "--resolution");
  expect_usage_error("render --resolution 64x64x2", "--resolution");
  expect_usage_error("render --threads -1", "--threads");
  expect_usage_error("render --max-depth 0", "--max-depth");
  expect_usage_error("render --spp 4 --time 3", "excludes");
  expect_usage_error("render --mis bogus", "--mis");
  expect_usage_error("render --no-such-flag", "no-such-flag");
  expect_usage_error("render -i lt --filter hashed", "--filter");
  expect_usage_error("render --filter bogus", "--filter");
  expect_usage_error("render --filter hashed --psf-scale 0", "--psf-scale");
  expect_usage_error("render --filter hashed --psf-scale nan", "--psf-scale");
  expect_usage_error("render --aov", "--aov applies to --filter hashed");
  expect_usage_error("render --filter hashed --psf-caustic-photons 0 --psf-one-bounce-photons", "needs --psf-caustic-photons");
  // Options belong to integrators: another integrator's option names where it applies.
  expect_usage_error("render -i lt --pclt-alpha 0.5", "--pclt-alpha applies to --integrator pclt");
  expect_usage_error("render -i sppm --mis balance", "--mis applies to --integrator bpt, pt");
  expect_usage_error("render -i pclt --pclt-hash-map stochastic --pclt-stochastic-slots 3", "power of two");
}

TEST_F(CliTest, HashedFilterWritesAovsAndReportsTheTable) {
  const CliResult r = run(std::string("render e_c --filter hashed --aov -o f.exr --stats s.json ") + kSmall);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* aov : {"voxel", "count", "level", "probes"})
    EXPECT_TRUE(fs::exists(dir_ / (std::string("f.aov-") + aov + ".exr"))) << aov;
  const auto json = nlohmann::json::parse(read_all(dir_ / "s.json"));
  EXPECT_EQ(json.at("filter").get<std::string>(), "hashed");
  EXPECT_EQ(json.at("statistics").at("hashed.probe_limit_fallbacks").get<uint64_t>(), 0u);
  EXPECT_GT(json.at("statistics").at("hashed.occupancy").get<double>(), 0.0);
  EXPECT_NE(json.at("outputs").get<std::string>().find("f.aov-voxel.exr"), std::string::npos);
}

// --lens-radius/--focus-distance give any scene a thin lens; a lens needs a focus distance, and
// a focus distance needs a lens.
TEST_F(CliTest, ThinLensOptions) {
  expect_usage_error(std::string("render --lens-radius 0.2 ") + kSmall, "--focus-distance");
  expect_usage_error(std::string("render --focus-distance 4 ") + kSmall, "--lens-radius");
  expect_usage_error(std::string("render --lens-radius -1 --focus-distance 4 ") + kSmall, "--lens-radius");
  const CliResult r = run(std::string("render -i bpt --lens-radius 0.2 --focus-distance 4 -o lens.pfm ") + kSmall);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "lens.pfm"));
}

// --pixel-filter and its radius replace the scene's filter (camera/pixel_filter.h): unknown kinds and
// radii out of range are usage errors; `info` names the filter; a filtered render differs from the box.
TEST_F(CliTest, PixelFilterOptions) {
  expect_usage_error(std::string("render --pixel-filter sinc ") + kSmall, "--pixel-filter");
  expect_usage_error(std::string("render --pixel-filter tent --pixel-filter-radius 0 ") + kSmall, "pixel-filter-radius");
  expect_usage_error(std::string("render --pixel-filter-radius 17 ") + kSmall, "pixel-filter-radius");
  CliResult r = run(std::string("render -o box.pfm ") + kSmall);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run(std::string("render --pixel-filter gaussian -o gaussian.pfm ") + kSmall);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run(std::string("render --pixel-filter-radius 1 -o wide-box.pfm ") + kSmall);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto bytes = [&](const char* name) {
    std::ifstream in(dir_ / name, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_NE(bytes("box.pfm"), bytes("gaussian.pfm"));
  EXPECT_NE(bytes("box.pfm"), bytes("wide-box.pfm"));
  r = run("info cornell-box");
  EXPECT_NE(r.out.find("pixel filter box 0.5"), std::string::npos) << r.out;
}

TEST_F(CliTest, UnsupportedOutputFormatIsAUsageError) { expect_usage_error(std::string("render -o out.jpg ") + kSmall, "out.jpg"); }

TEST_F(CliTest, UnwritableOutputFailsBeforeRendering) {
  for (const std::string out : {"missing-folder/out.exr", "blocker/out.png"}) {
    SCOPED_TRACE(out);
    std::ofstream(dir_ / "blocker") << "a file where a folder should be";
    const CliResult r = run(std::string("render -o ") + out + " " + kSmall);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(out), std::string::npos) << r.err;
    EXPECT_EQ(file_count(), 1) << "only the blocker file may exist";
    fs::remove(dir_ / "blocker");
  }
}

TEST_F(CliTest, UnwritableStatsFileFailsBeforeRendering) {
  const CliResult r = run(std::string("render -o img.exr --stats missing/stats.json ") + kSmall);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(file_count(), 0);
}

TEST_F(CliTest, RendersRequestedFilesAndStats) {
  const CliResult r = run(std::string("render e_c -o a.exr -o a.pfm -o a.png --stats s.json --seed 7 --threads 2 ") + kSmall);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  for (const char* f : {"a.exr", "a.pfm", "a.png", "s.json"}) EXPECT_GT(fs::file_size(dir_ / f), 0u) << f;
  EXPECT_EQ(file_count(), 4) << "temporary files left behind";
  const auto json = nlohmann::json::parse(read_all(dir_ / "s.json"));
  EXPECT_EQ(json.at("scene"), "cornell-empty-area");
  EXPECT_EQ(json.at("integrator"), "pt");
  EXPECT_EQ(json.at("spp"), 2);
  EXPECT_EQ(json.at("seed"), 7);
  EXPECT_EQ(json.at("threads"), 2);
  EXPECT_GT(json.at("rays").get<uint64_t>(), 16u * 12u * 2u);
  for (const char* key : {"wall_time_s", "mrays_per_s", "paths_per_s", "dropped_nan_inf_samples", "build_type"})
    EXPECT_TRUE(json.contains(key)) << key;
}

TEST_F(CliTest, DefaultOutputIsExrAndPngInPathspaceOut) {
  const CliResult r = run(kSmall);  // no subcommand arguments beyond options: must still be `render`
  EXPECT_EQ(r.exit_code, 2);        // options without a command are a usage error
  const CliResult ok = run(std::string("render ") + kSmall);
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(fs::exists(dir_ / "pathspace-out/cornell-box.exr"));
  EXPECT_TRUE(fs::exists(dir_ / "pathspace-out/cornell-box.png"));
}

TEST_F(CliTest, ProgressWithoutTerminalIsPlainLines) {
  const CliResult r = run("render --resolution 16x16 --spp 8 -o a.exr");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find('\r'), std::string::npos) << "a progress bar was drawn into a pipe";
  EXPECT_NE(r.out.find("100.0%"), std::string::npos) << r.out;
  EXPECT_LE(count_lines(r.out), 8);
}

TEST_F(CliTest, InfoListsEveryBuiltinSceneById) {
  const CliResult r = run("info --scenes");
  ASSERT_EQ(r.exit_code, 0);
  for (const char* id : {"e_c", "e_p", "bs_c", "gbs_c", "glm_c", "gbs_p", "gbs_b", "gbs_s"})
    EXPECT_NE(r.out.find(id), std::string::npos) << id;
}

TEST_F(CliTest, HelpOnEveryCommand) {
  for (const char* args : {"--help", "render --help", "info --help", "compare --help", "study --help", "study pclt --help", "study psf --help"}) {
    const CliResult r = run(args);
    EXPECT_EQ(r.exit_code, 0) << args;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << args;
  }
}

// A tiny `study pclt` run: every figure's runs are listed in study.json with their numbers, and every
// image the JSON names exists; study.html names every figure.
TEST_F(CliTest, StudyPcltWritesJsonHtmlAndEveryImage) {
  const CliResult r = run("study pclt --scenes bs_c --resolution 16x12 --time 0.02 --reference-time 0.2 --no-exr --quiet -o st");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(read_all(dir_ / "st/study.json"));
  EXPECT_EQ(json.at("settings").at("width"), 16);
  EXPECT_TRUE(json.at("scenes").contains("bs_c"));
  const std::string html = read_all(dir_ / "st/study.html");
  for (const char* fig : {"fig1", "fig5", "fig6", "fig7", "fig8", "fig9"}) {
    SCOPED_TRACE(fig);
    const auto& f = json.at("figures").at(fig);
    EXPECT_NE(html.find(f.at("title").get<std::string>()), std::string::npos);
    if (std::string(fig) == "fig9") continue;  // explained, not rendered
    ASSERT_FALSE(f.at("runs").empty());
    for (const auto& run : f.at("runs")) {
      EXPECT_GT(run.at("iterations").get<int>(), 0);
      EXPECT_GE(run.at("rel_mse").get<double>(), 0.0);
      for (const char* key : {"image_png", "error_png"}) EXPECT_TRUE(fs::exists(dir_ / "st" / run.at(key).get<std::string>())) << run.at(key);
    }
  }
  std::vector<std::string> fig1;
  for (const auto& run : json.at("figures").at("fig1").at("runs")) fig1.push_back(run.at("integrator"));
  EXPECT_EQ(fig1, (std::vector<std::string>{"pt", "lt", "bpt", "sppm", "pclt"}));
}

// A tiny `study psf` run: every rendered figure lists runs whose images exist, fig. 7 runs on the
// fence, the hash table figures carry their data, and the page has the SVG plots.
TEST_F(CliTest, StudyPsfWritesJsonHtmlPlotsAndEveryImage) {
  const CliResult r = run("study psf --scenes bs_c --resolution 16x12 --time 0.05 --reference-time 0.2 --max-spp 4 "
                          "--vertex-set-resolution 32x24 --temporal-frames 4 --eviction-frames 6 --equal-time-spp 1,2 --no-exr --quiet -o sp");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(read_all(dir_ / "sp/study.json"));
  EXPECT_EQ(json.at("study"), "psf");
  const std::string html = read_all(dir_ / "sp/study.html");
  for (const char* fig :
       {"2014-fig2", "2014-fig3", "2014-fig4", "2014-fig7", "2014-sec2.3", "2021-fig1", "2021-fig4", "2021-fig10", "equal-time-1spp",
        "equal-time-2spp"}) {
    SCOPED_TRACE(fig);
    const auto& f = json.at("figures").at(fig);
    EXPECT_NE(html.find("id=\"" + std::string(fig) + "\""), std::string::npos);
    ASSERT_FALSE(f.at("runs").empty());
    for (const auto& run : f.at("runs")) {
      EXPECT_GT(run.at("iterations").get<int>(), 0);
      for (const char* key : {"image_png", "error_png"}) EXPECT_TRUE(fs::exists(dir_ / "sp" / run.at(key).get<std::string>())) << run.at(key);
    }
  }
  EXPECT_EQ(json.at("figures").at("2014-fig7").at("runs").at(0).at("scene"), "f_f");
  EXPECT_FALSE(json.at("figures").at("2019-fig7").at("data").at("psf_fig7").at("rows").empty());
  EXPECT_FALSE(json.at("figures").at("2019-fig8").at("data").at("psf_fig8").at("rows").empty());
  size_t svgs = 0;
  for (size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1)) ++svgs;
  // 2014 fig. 3, 2021 fig. 4, 2019 fig. 7 (4), 2019 fig. 8, sec. 3.4.1 (one per scene), fig. 9 (2), sec. 3.4.3 (3)
  EXPECT_EQ(svgs, 14u);
  // The temporal figures (2021 sec. 3.4): runs of the first and last orbit frame per scene and mode
  // against that frame's reference, fig. 9's modes (twice) at its last frame, the eviction flight's
  // table per policy; each shown as an HTML table.
  const auto& figures = json.at("figures");
  for (const char* fig : {"2021-sec3.4.1", "2021-fig9", "2021-sec3.4.3"}) {
    SCOPED_TRACE(fig);
    EXPECT_TRUE(figures.at(fig).at("reproduced").get<bool>());
    EXPECT_NE(html.find("id=\"" + std::string(fig) + "\""), std::string::npos);
    EXPECT_FALSE(figures.at(fig).at("findings").at("").get<std::string>().empty());
    for (const auto& run : figures.at(fig).at("runs"))
      for (const char* key : {"image_png", "error_png"}) EXPECT_TRUE(fs::exists(dir_ / "sp" / run.at(key).get<std::string>())) << run.at(key);
  }
  // Modes (studies/psf2021/temporal_figures.cpp, orbit_configurations): integrate and off at the defaults and at
  // s = 4 px with texture footprints, and integrate with query paths too.
  EXPECT_EQ(figures.at("2021-sec3.4.1").at("runs").size(), 20u);  // 2 scenes x 5 modes x frames 1 and 4
  const auto& orbit = figures.at("2021-sec3.4.1").at("data").at("temporal_orbit").at("rows");
  EXPECT_EQ(orbit.size(), 30u);  // 2 scenes x 5 modes x frames 1, 2, 4
  EXPECT_EQ(orbit.at(0).at("frame"), 1);
  EXPECT_EQ(json.at("scenes").at("bs_c-orbit-f4").at("integrator"), "pt");
  const auto& fig9 = figures.at("2021-fig9").at("runs");
  ASSERT_EQ(fig9.size(), 8u);  // ema, integrate, hybrid, rectified; at the defaults and with s = 4 px and query paths
  EXPECT_EQ(fig9.at(7).at("scene"), "ml_c-f4");
  EXPECT_TRUE(fig9.at(7).at("metrics").contains("band_rel_mse"));
  const auto& eviction = figures.at("2021-sec3.4.3").at("data").at("temporal_eviction_summary").at("rows");
  ASSERT_EQ(eviction.size(), 3u);
  for (const auto& row : eviction) {
    EXPECT_LE(row.at("max occupancy").get<double>(), 1.0);
    EXPECT_GT(row.at("RSS last (MiB)").get<double>(), 0.0);
  }
  EXPECT_EQ(eviction.at(2).at("policy"), "stale");
  EXPECT_NE(html.find("<caption>"), std::string::npos);
  // Each equal-time figure: PT, the hashed filter for that many passes, the others for its time.
  for (const int spp : {1, 2}) {
    const auto& equal_time = json.at("figures").at(fmt::format("equal-time-{}spp", spp)).at("runs");
    ASSERT_EQ(equal_time.size(), 4u);
    EXPECT_EQ(equal_time.at(0).at("label"), "PT");
    EXPECT_EQ(equal_time.at(1).at("label"), "PT + hashed");
    EXPECT_EQ(equal_time.at(1).at("iterations"), spp);
    EXPECT_EQ(equal_time.at(2).at("time_budget_s"), equal_time.at(1).at("time_s"));
    EXPECT_EQ(equal_time.back().at("label"), "PT + à-trous");
  }
}

// A pass longer than 2 s reports from inside once a second (progress_reporter.h): one pass of BPT
// at 1600x1600 takes several seconds on two cores, so its output has lines "pass 1: N% ...".
TEST_F(CliTest, LongPassReportsProgressFromInside) {
  const CliResult r = run("render cornell-box -i bpt -r 1600x1600 -s 1 -o big.exr");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("pass 1: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("% of its work so far"), std::string::npos) << r.out;
}

// An empty value names nothing: a usage error, never the option's default (cli_app.cpp,
// check_no_empty_values), for every command. (CLI11 drops empty items inside a list: "a,,b" is "a,b".)
TEST_F(CliTest, EmptyOptionValuesAreUsageErrors) {
  expect_usage_error("render cornell-box -r '' -s 1 -o x.exr", "--resolution has an empty value");
  expect_usage_error("render cornell-box --resume '' -s 1", "--resume has an empty value");
  expect_usage_error("render '' -s 1 -o x.exr", "has an empty value");
  expect_usage_error("study psf --scenes '' -o st", "--scenes has an empty value");
  expect_usage_error("compare a.exr '' ", "has an empty value");
}

// `study psf --figures` makes only the named figures, and --reference-dir supplies a scene's
// reference instead of rendering one (here a 4-spp PT image, read by its scene's name).
TEST_F(CliTest, StudyPsfMakesOnlyTheNamedFiguresAgainstGivenReferences) {
  fs::create_directories(dir_ / "refs");
  const CliResult ref = run("render cornell-box -r 16x12 -s 4 --quiet -o refs/cornell-box.exr");
  ASSERT_EQ(ref.exit_code, 0) << ref.err;
  const CliResult r = run("study psf --scenes bs_c --resolution 16x12 --time 0.05 --figures equal-time,2021-fig1 "
                          "--equal-time-spp 1 --reference-dir refs --no-exr --quiet -o sq");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(read_all(dir_ / "sq/study.json"));
  std::vector<std::string> figures;
  for (const auto& [id, figure] : json.at("figures").items()) {
    figures.push_back(id);
    EXPECT_FALSE(figure.at("runs").empty()) << id;
  }
  EXPECT_EQ(figures, (std::vector<std::string>{"2021-fig1", "equal-time-1spp"}));
  ASSERT_EQ(json.at("scenes").size(), 1u);  // no fence, no temporal scenes
  const auto& scene = json.at("scenes").begin().value();
  EXPECT_EQ(fs::path(scene.at("image_file").get<std::string>()).filename(), "cornell-box.exr");
  EXPECT_FALSE(scene.contains("integrator"));  // read, not rendered
}

TEST_F(CliTest, StudyMisuseIsAUsageError) {
  expect_usage_error("study psf --figures 2014-fig99 --quiet", "2014-fig99");
  expect_usage_error("study psf --reference-dir nowhere --quiet", "--reference-dir");
  expect_usage_error("study psf --vertex-set-resolution 0x3 --quiet", "--vertex-set-resolution");
  expect_usage_error("study psf --max-spp 0 --quiet", "--max-spp");
  expect_usage_error("study psf --room-scene nowhere.pbrt --quiet", "--room-scene");
  expect_usage_error("study psf --scenes nope --quiet", "nope");
  expect_usage_error("study pclt --resolution 16 --quiet", "--resolution");
  expect_usage_error("study pclt --scenes nope --quiet", "nope");
  expect_usage_error("study --quiet", "study");
}

}  // namespace
