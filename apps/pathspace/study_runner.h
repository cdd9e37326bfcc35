// One render of `pathspace study` (docs/cli.md): a built-in scene with its long reference render,
// and a runner that renders one configuration (equal time or equal iterations, as the PCLT paper's
// figs. 1 and 5-8 compare them), writes the image, its false-colour error map and optionally EXR, and
// measures relMSE/MSE against the reference. Runs become JSON objects and table columns in the HTML.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "pathspace/accel/accel.h"
#include "pathspace/film/image.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/integrators/integrator.h"
#include "pathspace/scene/scene.h"

namespace pathspace::cli {

// A built-in scene prepared for a study: geometry, acceleration structure and reference image.
struct StudyScene {
  std::string name, id;  // "cornell-box", "bs_c"
  Scene scene;
  std::unique_ptr<Accel> accel;
  size_t light_count = 0;
  // The long reference (unbiased integrator, its own seed) and its variance of the mean.
  Image reference, reference_variance;
  std::string reference_png;             // relative to the study folder
  nlohmann::ordered_json reference_info;  // integrator, time, iterations, noise estimate, files
};

// What to render: an integrator with settings, for a number of iterations or a time budget.
struct RunSpec {
  std::string figure;  // "fig1"
  std::string label;   // column title, e.g. "PCLT plane"
  std::string integrator;
  IntegratorSettings settings;
  nlohmann::ordered_json settings_json;  // the settings this run is about (JSON and HTML)
  uint32_t iterations = 1;  // passes (spp / iterations) when time_s == 0
  double time_s = 0.0;      // > 0: equal-time run, whole passes until this budget has passed
};

// A finished run: numbers, files and the image (kept to compare runs with each other, fig. 6).
struct StudyRun {
  std::string figure, scene_id, label, integrator;
  nlohmann::ordered_json settings;
  double time_budget_s = 0.0;  // 0 for equal-iteration runs
  double time_s = 0.0;         // wall time of the passes
  uint32_t iterations = 0;
  ImageError error;            // against the scene's reference
  double rel_mse_debiased = 0.0;  // minus the reference's own variance (image_metrics.h)
  // Integrator-specific numbers parsed from its report (PCLT: memory_bytes, eye_s, light_s, ...) and
  // figure-specific comparisons added by the study (fig. 6: error against the shadow-ray image).
  nlohmann::ordered_json metrics = nlohmann::ordered_json::object();
  std::string image_png, error_png, image_exr;  // relative to the study folder; exr empty with --no-exr
  std::string reused_from;     // a figure whose identical run is shown again (same seed and settings)
  Image image;
};

struct StudyRunnerConfig {
  std::string out_dir;
  uint64_t seed = 0;
  int threads = 0;
  bool write_exr = true;
  bool quiet = false;
};

class StudyRunner {
 public:
  explicit StudyRunner(StudyRunnerConfig config) : config_(std::move(config)) {}

  // Builds the scene at width x height and renders its reference for time_s seconds with integrator.
  std::unique_ptr<StudyScene> prepare_scene(const std::string& name_or_id, int width, int height,
                                            const std::string& integrator, double time_s) const;
  // Renders spec on scene, writes its files and measures it against the reference.
  StudyRun run(const StudyScene& scene, const RunSpec& spec) const;
  // The same run listed again under another figure (no new render).
  static StudyRun reuse(const StudyRun& run, const std::string& figure, const std::string& label);

  const StudyRunnerConfig& config() const { return config_; }

 private:
  StudyRunnerConfig config_;
};

nlohmann::ordered_json to_json(const StudyRun& run);

// The settings a study varies, as JSON (for RunSpec::settings_json).
nlohmann::ordered_json pclt_settings_json(const PcltSettings& s);
nlohmann::ordered_json sppm_settings_json(const SppmSettings& s);

}  // namespace pathspace::cli
