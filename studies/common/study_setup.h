// What every `pathspace study` subcommand does around its figures: checking the common options
// before any render, the runner and the reference, the settings record, and writing study.json and
// study.html (atomically, io/atomic_file.h). The pclt and psf studies differ only in their figures.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathspace/study/experiment_runner.h"
#include "pathspace/study/figure.h"
#include "studies/common/study_options.h"

namespace pathspace::studies {

struct StudySetup {
  int width = 0, height = 0;
  std::vector<std::string> scene_names;  // canonical names, no repeats
  double reference_time_s = 0.0;
  std::string reference_integrator;
};

// "WxH" with 1 <= W, H <= 4096; throws UsageError naming `option`.
void parse_resolution(const std::string& text, const std::string& option, int* width, int* height);
// Checks the options (UsageError), creates the output folder and checks it is writable.
StudySetup prepare_study(const StudyOptions& options);
study::ExperimentRunner make_study_runner(const StudyOptions& options, bool keep_images);
// The reference of one scene (a canonical name): read from --reference-dir when it holds
// <scene>.exr, else rendered for the study's reference time.
study::ReferenceSpec study_reference(const StudyOptions& options, const StudySetup& setup, const std::string& scene);
// width, height, time_s, reference_time_s, reference_integrator, reference_dir, seed, threads,
// build_type, integrators.
nlohmann::ordered_json study_settings(const StudyOptions& options, const StudySetup& setup);

// What a study produced, written as study.json and study.html.
struct StudyDocument {
  std::string id, paper, title;
  nlohmann::ordered_json settings;
  std::vector<study::SceneSummary> scenes;
  std::vector<study::Figure> figures;
};
// A document with its identity and the settings of study_settings, no scenes or figures yet.
StudyDocument study_document(const StudyOptions& options, const StudySetup& setup, std::string id, std::string paper,
                             std::string title);
void write_study(const StudyOptions& options, const StudyDocument& document);

}  // namespace pathspace::studies
