// ExperimentRunner: renders an Experiment cell by cell through RenderSession (one session per
// configuration x seed, shared scene and acceleration structure), measures each result against the
// scene's reference and collects the required statistics. run() does everything, one scene at a
// time; prepare() and run_scene() let a study whose later configurations depend on earlier results
// (the PCLT study's figs. 5-8 use fig. 1's iteration count) run it in steps on one prepared scene.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "pathspace/study/experiment.h"
#include "pathspace/study/experiment_result.h"
#include "pathspace/study/measurement.h"
#include "pathspace/study/prepared_scene.h"

namespace pathspace::study {

struct RunnerOptions {
  std::string out_dir;      // images go to <out_dir>/images/; empty: no image files
  bool write_exr = true;    // besides PNG (renders and references)
  int threads = 0;          // every session's; <= 0: all cores
  bool keep_images = false; // keep Measurement::image in the results
  bool quiet = false;       // no progress lines on stdout
  std::string log_prefix = "study";
  // After each measurement (with its image) and each reference, e.g. for a benchmark's own lines.
  std::function<void(const Measurement&)> on_measurement;
  std::function<void(const PreparedScene&)> on_reference;
};

class ExperimentRunner {
 public:
  explicit ExperimentRunner(RunnerOptions options);

  // Checks the experiment, then for each scene: prepare, every configuration x seed, release.
  ExperimentResult run(const Experiment& experiment) const;

  // The scene with its reference (rendered, or read from experiment.reference's files).
  PreparedScene prepare(const SceneSpec& scene, const ReferenceSpec& reference) const;
  // Every configuration x seed of the experiment on one prepared scene (its `scenes` are ignored),
  // in that order, one measurement per checkpoint.
  std::vector<Measurement> run_scene(const PreparedScene& scene, const Experiment& experiment) const;
  // One configuration with one seed.
  std::vector<Measurement> run_cell(const PreparedScene& scene, const Experiment& experiment,
                                    const Configuration& configuration, uint64_t seed) const;

  // An image computed from a run's image after rendering (a post-process such as a screen-space
  // filter), measured and written like a rendered cell: `source` with its errors, image files and
  // label replaced, `extra_seconds` added to its time. The image is kept only with keep_images.
  Measurement measure_post_process(const PreparedScene& scene, const Measurement& source, const std::string& experiment,
                                   const std::string& label, Image image, double extra_seconds) const;

  const RunnerOptions& options() const { return options_; }

 private:
  // Errors against the scene's reference, image files (image_base: "images/SCENE-..."), the progress
  // line (with `note` after the label) and on_measurement.
  void finish_measurement(const PreparedScene& scene, const std::string& image_base, const std::string& note, Image image,
                          Measurement* m) const;

  RunnerOptions options_;
};

}  // namespace pathspace::study
