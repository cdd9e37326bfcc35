// `pathspace study pclt`: reproduces the PCLT paper's figures 1 and 5-8 on built-in scenes and writes
// the images (PNG, optionally EXR), false-colour error maps, study.json with every run's numbers and
// one self-contained study.html showing them side by side (docs/cli.md, docs/pclt.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace pathspace::cli {

struct StudyOptions {
  std::string out = "pathspace-out/study-pclt";
  std::string resolution = "128x128";
  double time_s = 5.0;            // equal-time budget per image (fig. 1)
  double reference_time_s = 0.0;  // 0: 20 x time_s
  std::vector<std::string> scenes = {"bs_c", "gbs_c"};
  uint64_t seed = 0;
  int threads = 0;
  bool no_exr = false;
  bool quiet = false;
};

// Adds `study` with its `pclt` subcommand; returns the `study` command.
CLI::App* add_study_command(CLI::App& app, StudyOptions* options);
// Runs the study. Throws UsageError for invalid options, pathspace::Error for failures.
int run_study_command(const StudyOptions& options);

}  // namespace pathspace::cli
