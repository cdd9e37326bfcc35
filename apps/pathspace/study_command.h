// `pathspace study pclt` and `pathspace study psf`: reproduce a paper's figures on built-in scenes and
// write the images (PNG, optionally EXR), false-colour error maps, study.json with every run's
// numbers and one self-contained study.html showing them side by side (docs/cli.md, docs/pclt.md,
// docs/consistent-filter.md, docs/hashed-filter.md).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "studies/common/study_options.h"

namespace pathspace::cli {

struct StudyCommandOptions {
  std::string study;  // the subcommand given: "pclt", "psf" or "gallery"
  // Designated: a field added to StudyOptions cannot take another's value.
  studies::StudyOptions pclt{.out = "pathspace-out/study-pclt",
                             .resolution = "128x128",
                             .time_s = 5.0,
                             .reference_dir = {},
                             .scenes = {"bs_c", "gbs_c"}};
  studies::StudyOptions psf{
      .out = "pathspace-out/study-psf", .resolution = "128x128", .time_s = 3.0, .reference_dir = {}, .scenes = {"bs_c"}};
  studies::PsfStudyOptions psf_only;
  studies::GalleryOptions gallery;
};

// Adds `study` with its `pclt` and `psf` subcommands; returns the `study` command.
CLI::App* add_study_command(CLI::App& app, StudyCommandOptions* options);
// Runs the study. Throws UsageError for invalid options, pathspace::Error for failures.
int run_study_command(const StudyCommandOptions& options);

}  // namespace pathspace::cli
