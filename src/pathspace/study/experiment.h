// Experiment: what a study measures, as data: scenes x configurations x seeds, each rendered for a
// budget (passes, checkpoints of passes, or seconds) and measured against a reference (relMSE, MSE,
// means), plus the typed statistics each configuration must report and custom image metrics. The
// runner (experiment_runner.h) renders every cell through a RenderSession; experiment_output.h
// writes CSV, JSON and a self-contained HTML page. `pathspace study pclt` and the programs of studies/ are
// defined on it (docs/architecture.md, "8. Experiments").
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pathspace/film/image.h"
#include "pathspace/options/option_values.h"
#include "pathspace/session/render_config.h"
#include "pathspace/session/render_session.h"
#include "pathspace/study/record.h"

namespace pathspace::study {

struct PreparedScene;

// A built-in scene (name or id, builtin_scenes.h) or a scene file (io/scene_loader.h), at a size.
struct SceneSpec {
  std::string name;
  int width = 128, height = 128;
};

// How long each cell renders. Either whole passes until `seconds` of wall time (equal time), or
// `passes`: checkpoints in increasing order; one session runs to each in turn and is measured there
// (one result row per checkpoint), so {1, 2, 4, ..., 64} is a convergence curve of one render.
struct Budget {
  std::vector<uint32_t> passes;
  double seconds = 0.0;

  static Budget for_passes(uint32_t n) { return {{n}, 0.0}; }
  static Budget at_passes(std::vector<uint32_t> checkpoints) { return {std::move(checkpoints), 0.0}; }
  static Budget for_seconds(double s) { return {{}, s}; }
  bool timed() const { return seconds > 0.0; }
};

// How the HTML page prints a metric.
enum class MetricFormat { number, seconds, bytes, percent };

// A statistic (stats/statistics.h) a configuration must report, as a metric of its results. A
// statistic that is not reported is an error (pathspace::Error), never a 0.
struct StatisticMetric {
  std::string statistic;  // "pclt.memory_bytes"
  std::string column;     // metric name in the results; empty: the statistic's name
  double scale = 1.0;     // applied to the number; 1 keeps counters and byte sizes integers
  MetricFormat format = MetricFormat::number;
  const std::string& name() const { return column.empty() ? statistic : column; }
};

struct Configuration {
  std::string label;     // column title / CSV value, e.g. "PCLT plane"
  RenderConfig render;   // integrator, settings, filter; seed and threads are the runner's
  Record settings;       // what this configuration is about (JSON "settings", HTML, CSV columns)
  std::vector<StatisticMetric> statistics;
  std::optional<Budget> budget;  // replaces the experiment's
};

// A configuration from typed settings: configuration("SPPM", make_render_config("sppm", SppmSettings{...})).
Configuration configuration(std::string label, RenderConfig render, Record settings = {});
// A configuration from options given by name, as a CLI or a study definition gives them
// (configure_render: throws OptionError for an unknown or misplaced option); the options become
// its settings record (filter included when one is chosen).
Configuration configuration(std::string label, const std::string& integrator, const std::string& filter,
                            const OptionValues& options);

// The reference must not share random numbers with the runs it judges: with the same seed a BPT
// run would be correlated with a BPT reference and its error would look too small.
inline constexpr uint64_t kReferenceSeedOffset = 0x5EEDF00DULL;

// A config with the integrator's default settings and seed kReferenceSeedOffset.
inline RenderConfig reference_render_config(std::string integrator) {
  RenderConfig c;
  c.integrator = std::move(integrator);
  c.seed = kReferenceSeedOffset;
  return c;
}

// The image each cell is measured against: rendered (integrator, budget, its own seed), or read
// from an image file with an optional variance-of-the-mean image (debiased relMSE).
struct ReferenceSpec {
  RenderConfig render = reference_render_config("bpt");
  Budget budget = Budget::for_seconds(10.0);
  std::string image_file, variance_file;  // image_file set: read it instead of rendering
};

// What a custom metric sees of a finished cell.
struct MeasureContext {
  const PreparedScene& scene;
  const Image& image;              // the cell's mean image
  const RenderSnapshot& snapshot;  // its statistics and AOVs
};
// Adds metrics of its own (e.g. the error over an image region) to `metrics`.
using ImageMetric = std::function<void(const MeasureContext& context, Record* metrics)>;

struct Experiment {
  std::string name;  // file and image names, JSON "experiment"
  std::vector<SceneSpec> scenes;
  std::vector<Configuration> configurations;
  std::vector<uint64_t> seeds = {0};
  Budget budget = Budget::for_passes(1);
  ReferenceSpec reference;
  std::vector<ImageMetric> metrics;
};

// Throws pathspace::Error (or OptionError) for an experiment the runner cannot run: no scenes,
// configurations or seeds, an unknown integrator or filter, a budget with neither passes nor
// seconds (or both), checkpoints not increasing.
void check_experiment(const Experiment& experiment);
void check_budget(const Budget& budget, const std::string& what);

}  // namespace pathspace::study
