// The experiment harness (src/pathspace/study/): a tiny experiment (2 configurations x 2 seeds x 2
// passes on a 16x16 cornell-box against an 8-pass reference) gives the expected rows in CSV and JSON
// and an HTML page; a statistic a configuration requires that its integrator does not report is an
// error; pass checkpoints give one row each; configurations by option name are validated.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathspace/base/error.h"
#include "pathspace/options/option_spec.h"
#include "pathspace/study/experiment_output.h"
#include "pathspace/study/experiment_runner.h"
#include "support/temp_dir.h"

namespace {

using namespace pathspace;
using pathspace::testing::TempDir;

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::istringstream cs(line);
    for (std::string cell; std::getline(cs, cell, ',');) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.push_back("");
    rows.push_back(cells);
  }
  return rows;
}

study::Experiment tiny_experiment() {
  study::Experiment e;
  e.name = "tiny";
  e.scenes = {{"cornell-box", 16, 16}};
  e.reference.render = study::reference_render_config("pt");
  e.reference.budget = study::Budget::for_passes(8);
  RenderConfig pt;
  pt.integrator = "pt";
  e.configurations.push_back(study::configuration("PT", pt));
  RenderConfig pclt;
  pclt.integrator = "pclt";
  study::Configuration c = study::configuration("PCLT", pclt);
  c.statistics = {{"pclt.memory_bytes", "memory_bytes", 1.0, study::MetricFormat::bytes},
                  {"pclt.cache_fill", "cache_fill_percent", 100.0, study::MetricFormat::percent}};
  e.configurations.push_back(c);
  e.seeds = {1, 2};
  e.budget = study::Budget::for_passes(2);
  return e;
}

study::RunnerOptions quiet_options(const std::string& out_dir) {
  study::RunnerOptions o;
  o.out_dir = out_dir;
  o.write_exr = false;
  o.threads = 2;
  o.quiet = true;
  return o;
}

TEST(StudyHarness, TinyExperimentWritesCsvJsonAndHtml) {
  TempDir dir("study");
  const study::Experiment e = tiny_experiment();
  const study::ExperimentResult result = study::ExperimentRunner(quiet_options(dir.path.string())).run(e);
  ASSERT_EQ(result.measurements.size(), 4u);
  const char* labels[] = {"PT", "PT", "PCLT", "PCLT"};
  const uint64_t seeds[] = {1, 2, 1, 2};
  for (size_t i = 0; i < 4; ++i) {
    const study::Measurement& m = result.measurements[i];
    EXPECT_EQ(m.label, labels[i]);
    EXPECT_EQ(m.seed, seeds[i]);
    EXPECT_EQ(m.iterations, 2u);
    EXPECT_EQ(m.scene_id, "bs_c");
    EXPECT_GT(m.error.rel_mse, 0.0);
    EXPECT_TRUE(m.image.pixels.empty());  // not kept
    EXPECT_TRUE(std::filesystem::exists(dir.path / m.image_png)) << m.image_png;
    EXPECT_TRUE(std::filesystem::exists(dir.path / m.error_png)) << m.error_png;
  }
  EXPECT_FALSE(result.measurements[0].metrics.has("memory_bytes"));
  const study::Value* bytes = result.measurements[2].metrics.find("memory_bytes");
  ASSERT_NE(bytes, nullptr);
  ASSERT_TRUE(std::holds_alternative<int64_t>(*bytes));  // a byte count stays an integer
  EXPECT_GT(std::get<int64_t>(*bytes), 0);
  const double fill = result.measurements[2].metrics.number("cache_fill_percent");
  EXPECT_GT(fill, 0.0);
  EXPECT_LE(fill, 100.0);
  EXPECT_EQ(result.measurements[0].image_png, "images/bs_c-tiny-pt-s1.png");

  const study::OutputFiles files = study::write_results(result, dir.path.string(), &e);
  // CSV: a header and one row per configuration x seed.
  const auto rows = csv_rows(read_all(files.csv));
  ASSERT_EQ(rows.size(), 5u);
  const std::vector<std::string>& header = rows[0];
  auto col = [&](const std::string& name) {
    for (size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return i;
    ADD_FAILURE() << "no column " << name;
    return size_t(0);
  };
  for (size_t i = 0; i < 4; ++i) {
    const std::vector<std::string>& r = rows[i + 1];
    ASSERT_EQ(r.size(), header.size()) << i;
    EXPECT_EQ(r[col("experiment")], "tiny");
    EXPECT_EQ(r[col("scene")], "bs_c");
    EXPECT_EQ(r[col("label")], labels[i]);
    EXPECT_EQ(r[col("seed")], std::to_string(seeds[i]));
    EXPECT_EQ(r[col("iterations")], "2");
    EXPECT_FALSE(r[col("rel_mse")].empty());
    EXPECT_EQ(r[col("memory_bytes")].empty(), i < 2);  // PT does not report it, and was not asked to
  }
  // JSON: the scene with its reference and every run.
  const auto json = nlohmann::json::parse(read_all(files.json));
  EXPECT_EQ(json.at("experiment"), "tiny");
  EXPECT_EQ(json.at("scenes").at("bs_c").at("iterations"), 8);
  EXPECT_EQ(json.at("scenes").at("bs_c").at("integrator"), "pt");
  ASSERT_EQ(json.at("runs").size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    const auto& run = json.at("runs")[i];
    EXPECT_EQ(run.at("label"), labels[i]);
    EXPECT_EQ(run.at("seed"), seeds[i]);
    EXPECT_EQ(run.at("iterations"), 2);
    EXPECT_GT(run.at("rel_mse").get<double>(), 0.0);
  }
  EXPECT_TRUE(json.at("runs")[2].at("metrics").at("memory_bytes").is_number_integer());
  // HTML: one self-contained page with the images embedded.
  const std::string html = read_all(files.html);
  EXPECT_NE(html.find("<table>"), std::string::npos);
  EXPECT_NE(html.find("data:image/png;base64,"), std::string::npos);
  EXPECT_NE(html.find("memory_bytes"), std::string::npos);
}

TEST(StudyHarness, MissingStatisticIsAnError) {
  study::Experiment e = tiny_experiment();
  e.configurations.resize(1);  // PT
  e.configurations[0].statistics = {{"pclt.memory_bytes", "memory_bytes"}};
  e.seeds = {1};
  try {
    study::ExperimentRunner(quiet_options("")).run(e);
    ADD_FAILURE() << "no error for a statistic pt does not report";
  } catch (const pathspace::Error& error) {
    EXPECT_NE(std::string(error.what()).find("pclt.memory_bytes"), std::string::npos) << error.what();
  }
}

TEST(StudyHarness, CheckpointsMeasureOneSessionAtEachPassCount) {
  study::Experiment e = tiny_experiment();
  e.configurations.resize(1);
  e.seeds = {3};
  e.budget = study::Budget::at_passes({1, 3});
  study::RunnerOptions o = quiet_options("");
  o.keep_images = true;
  const study::ExperimentRunner runner(o);
  const study::ExperimentResult r = runner.run(e);
  ASSERT_EQ(r.measurements.size(), 2u);
  EXPECT_EQ(r.measurements[0].iterations, 1u);
  EXPECT_EQ(r.measurements[1].iterations, 3u);
  // The 3-pass checkpoint continues the 1-pass render: the same image as 3 passes in one go.
  e.budget = study::Budget::for_passes(3);
  const study::ExperimentResult once = runner.run(e);
  ASSERT_EQ(once.measurements.size(), 1u);
  EXPECT_EQ(once.measurements[0].image.pixels, r.measurements[1].image.pixels);

  e.budget = study::Budget::at_passes({2, 2});
  EXPECT_THROW(runner.run(e), pathspace::Error);
}

TEST(StudyHarness, ConfigurationsByOptionName) {
  OptionValues options;
  options.set("psf-scale", "6");
  const study::Configuration c = study::configuration("hashed 6", "pt", "hashed", options);
  EXPECT_EQ(c.render.integrator, "pt");
  EXPECT_EQ(c.render.filter.name, "hashed");
  ASSERT_NE(c.settings.find("psf-scale"), nullptr);
  EXPECT_EQ(std::get<std::string>(*c.settings.find("psf-scale")), "6");
  OptionValues wrong;
  wrong.set("pclt-alpha", "0.5");
  EXPECT_THROW(study::configuration("x", "pt", "none", wrong), OptionError);
}

TEST(StudyHarness, TableCsvQuotesAndFormats) {
  study::Table t;
  t.column("name").column("x", "{:.2f}").column("n");
  study::Record r;
  r.set("name", "a, \"b\"").set("x", 1.0 / 3.0).set("n", uint64_t(7));
  t.rows.push_back(r);
  t.rows.push_back(study::Record().set("name", "only"));
  EXPECT_EQ(study::to_csv(t), "name,x,n\n\"a, \"\"b\"\"\",0.33,7\nonly,,\n");
}

}  // namespace
