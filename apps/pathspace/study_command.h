// `pathspace study pclt` and `pathspace study psf`: reproduce a paper's figures on built-in scenes and
// write the images (PNG, optionally EXR), false-colour error maps, study.json with every run's
// numbers and one self-contained study.html showing them side by side (docs/cli.md, docs/pclt.md,
// docs/consistent-filter.md, docs/hashed-filter.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "study_gallery.h"

namespace pathspace::cli {

// The options every study has.
struct StudyOptions {
  std::string out;
  std::string resolution = "128x128";
  double time_s = 5.0;            // equal-time budget per image
  double reference_time_s = 0.0;  // 0: 20 x time_s
  std::vector<std::string> scenes;
  uint64_t seed = 0;
  int threads = 0;
  bool no_exr = false;
  bool quiet = false;
};

// `study psf`'s own options.
struct PsfStudyOptions {
  uint32_t max_spp = 64;                         // last checkpoint of the 2014 paper's fig. 3
  std::string vertex_set_resolution = "1920x1080";  // the hash table figures' vertex sets (2019 figs. 7, 8)
  // The hashed filter across frames (2021 sec. 3.4, study_psf_temporal.cpp); 0 skips that part.
  uint32_t temporal_frames = 64;     // orbit frames of sec. 3.4.1 (fig. 9 uses min(32, this))
  uint32_t eviction_frames = 10000;  // frames of the eviction flight (sec. 3.4.3)
  std::string room_scene = "scenes/textured-room/scene.pbrt";  // relative: to the working folder, else to the repository of the binary
};

struct StudyCommandOptions {
  std::string study;  // the subcommand given: "pclt", "psf" or "gallery"
  StudyOptions pclt{"pathspace-out/study-pclt", "128x128", 5.0, 0.0, {"bs_c", "gbs_c"}};
  StudyOptions psf{"pathspace-out/study-psf", "128x128", 3.0, 0.0, {"bs_c"}};
  PsfStudyOptions psf_only;
  GalleryOptions gallery;
};

// Adds `study` with its `pclt` and `psf` subcommands; returns the `study` command.
CLI::App* add_study_command(CLI::App& app, StudyCommandOptions* options);
// Runs the study. Throws UsageError for invalid options, pathspace::Error for failures.
int run_study_command(const StudyCommandOptions& options);

}  // namespace pathspace::cli
