#include "pathspace/study/experiment_runner.h"

#include <cstdio>

#include <fmt/format.h>

#include "pathspace/base/error.h"
#include "pathspace/film/block_metrics.h"
#include "pathspace/film/flip.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/io/image_io.h"
#include "pathspace/session/render_session.h"
#include "pathspace/study/image_files.h"
#include "pathspace/study/statistic_metrics.h"

namespace pathspace::study {

namespace {

RunLimit limit_for(const Budget& budget, size_t checkpoint, uint32_t passes_done) {
  if (budget.timed()) return RunLimit::for_seconds(budget.seconds);
  return RunLimit::for_passes(budget.passes[checkpoint] - passes_done);
}

std::string budget_text(const Budget& b) {
  return b.timed() ? fmt::format("{:.3g} s", b.seconds) : fmt::format("{} passes", b.passes.back());
}

}  // namespace

ExperimentRunner::ExperimentRunner(RunnerOptions options) : options_(std::move(options)) {}

PreparedScene ExperimentRunner::prepare(const SceneSpec& spec, const ReferenceSpec& reference) const {
  PreparedScene p = load_prepared_scene(spec);
  Record& info = p.summary.reference;
  if (!reference.image_file.empty()) {
    p.reference = read_image(reference.image_file);
    if (!reference.variance_file.empty()) p.reference_variance = read_image(reference.variance_file);
    if (p.reference.width != p.summary.width || p.reference.height != p.summary.height)
      throw Error(fmt::format("study: reference '{}' is {}x{}, the scene {}x{}", reference.image_file, p.reference.width,
                              p.reference.height, p.summary.width, p.summary.height));
    if (!reference.variance_file.empty() && p.reference_variance.size() != p.reference.size())
      throw Error("study: reference variance '" + reference.variance_file + "' differs in size from the reference");
    info.set("image_file", reference.image_file);
    if (!reference.variance_file.empty()) {
      info.set("variance_file", reference.variance_file);
      info.set("noise_rel_mse", reference_noise(p.reference, p.reference_variance));
    }
  } else {
    check_budget(reference.budget, "reference");
    RenderConfig config = reference.render;
    config.threads = options_.threads;
    if (!options_.quiet) {
      fmt::print("{}: {} reference, {} for {}\n", options_.log_prefix, p.id(), config.integrator, budget_text(reference.budget));
      std::fflush(stdout);
    }
    RenderSession session(p.scene, p.accel, config);
    const size_t runs = reference.budget.timed() ? 1 : reference.budget.passes.size();
    for (size_t i = 0; i < runs; ++i) session.run(limit_for(reference.budget, i, session.passes_done()));
    RenderSnapshot snap = session.snapshot();
    p.reference = std::move(snap.mean);
    p.reference_variance = std::move(snap.variance);
    info.set("integrator", config.integrator);
    if (config.filter.active()) info.set("filter", config.filter.name);
    if (reference.budget.timed()) info.set("time_budget_s", reference.budget.seconds);
    info.set("time_s", snap.stats.wall_s);
    info.set("iterations", snap.stats.spp);
    info.set("seed", config.seed);
    info.set("noise_rel_mse", reference_noise(p.reference, p.reference_variance));
  }
  if (!options_.out_dir.empty()) {
    create_image_folder(options_.out_dir);
    const ImageFiles files = write_images(options_.out_dir, "images/" + p.id() + "-reference", p.reference, Image(),
                                          options_.write_exr);
    p.summary.reference_png = files.png;
    info.set("image_png", files.png);
    if (!files.exr.empty()) info.set("image_exr", files.exr);
  }
  if (options_.on_reference) options_.on_reference(p);
  return p;
}

std::vector<Measurement> ExperimentRunner::run_cell(const PreparedScene& scene, const Experiment& experiment,
                                                    const Configuration& configuration, uint64_t seed) const {
  const Budget& budget = configuration.budget ? *configuration.budget : experiment.budget;
  check_budget(budget, "experiment '" + experiment.name + "' '" + configuration.label + "'");
  RenderConfig config = configuration.render;
  config.seed = seed;
  config.threads = options_.threads;
  RenderSession session(scene.scene, scene.accel, config);

  std::vector<Measurement> out;
  const size_t checkpoints = budget.timed() ? 1 : budget.passes.size();
  for (size_t i = 0; i < checkpoints; ++i) {
    session.run(limit_for(budget, i, session.passes_done()));
    RenderSnapshot snap = session.snapshot();
    Measurement m;
    m.experiment = experiment.name;
    m.scene_id = scene.id();
    m.label = configuration.label;
    m.integrator = config.integrator;
    m.filter = config.filter.name;
    m.settings = configuration.settings;
    m.seed = seed;
    m.time_budget_s = budget.seconds;
    m.time_s = snap.stats.wall_s;
    m.iterations = snap.stats.spp;
    collect_statistics(snap.stats.details, configuration.statistics, &m.metrics);
    for (const ImageMetric& metric : experiment.metrics) metric(MeasureContext{scene, snap.mean, snap}, &m.metrics);
    std::string base = fmt::format("images/{}-{}-{}", scene.id(), slug(experiment.name), slug(configuration.label));
    if (experiment.seeds.size() > 1) base += fmt::format("-s{}", seed);
    if (checkpoints > 1) base += fmt::format("-p{}", m.iterations);
    finish_measurement(scene, base, experiment.seeds.size() > 1 ? fmt::format(" (seed {})", seed) : std::string(), std::move(snap.mean),
                       &m);
    out.push_back(std::move(m));
  }
  return out;
}

void ExperimentRunner::finish_measurement(const PreparedScene& scene, const std::string& image_base, const std::string& note,
                                          Image image, Measurement* m) const {
  m->error = image_error(image, scene.reference);
  const ImageError debiased =
      scene.reference_variance.size() > 0 ? image_error(image, scene.reference, &scene.reference_variance) : m->error;
  m->rel_mse_debiased = debiased.rel_mse;
  m->mse_debiased = debiased.mse;
  // What a viewer sees besides the per-pixel noise (pathspace compare's metrics, docs/cli.md).
  const BlockError blocks = block_error(image, scene.reference);
  m->metrics.set("block_rel_mse", blocks.block_rel_mse);
  m->metrics.set("blotched_share", blocks.blotched_share);
  m->metrics.set("flip", flip(image, scene.reference).mean);
  if (!options_.out_dir.empty()) {
    const ImageFiles files = write_images(options_.out_dir, image_base, image, scene.reference, options_.write_exr);
    m->image_png = files.png;
    m->error_png = files.error_png;
    m->image_exr = files.exr;
  }
  if (!options_.quiet) {
    fmt::print("{}: {} {} {}{}: {:.2f} s, {} iterations, relMSE {:.4g}\n", options_.log_prefix, scene.id(), m->experiment, m->label,
               note, m->time_s, m->iterations, m->error.rel_mse);
    std::fflush(stdout);
  }
  m->image = std::move(image);
  if (options_.on_measurement) options_.on_measurement(*m);
  if (!options_.keep_images) m->image = Image();
}

Measurement ExperimentRunner::measure_post_process(const PreparedScene& scene, const Measurement& source,
                                                   const std::string& experiment, const std::string& label, Image image,
                                                   double extra_seconds) const {
  Measurement m = source;
  m.experiment = experiment;
  m.label = label;
  m.time_s = source.time_s + extra_seconds;
  m.same_render_as.clear();
  m.image_png.clear(), m.error_png.clear(), m.image_exr.clear();
  finish_measurement(scene, fmt::format("images/{}-{}-{}", scene.id(), slug(experiment), slug(label)), "", std::move(image), &m);
  return m;
}

std::vector<Measurement> ExperimentRunner::run_scene(const PreparedScene& scene, const Experiment& experiment) const {
  std::vector<Measurement> out;
  for (const Configuration& c : experiment.configurations)
    for (uint64_t seed : experiment.seeds) {
      std::vector<Measurement> cell = run_cell(scene, experiment, c, seed);
      for (Measurement& m : cell) out.push_back(std::move(m));
    }
  return out;
}

ExperimentResult ExperimentRunner::run(const Experiment& experiment) const {
  check_experiment(experiment);
  if (!options_.out_dir.empty()) create_image_folder(options_.out_dir);
  ExperimentResult result;
  result.name = experiment.name;
  for (const SceneSpec& spec : experiment.scenes) {
    // One scene at a time: its geometry, acceleration structure and reference are freed before the next.
    const PreparedScene scene = prepare(spec, experiment.reference);
    result.scenes.push_back(scene.summary);
    std::vector<Measurement> ms = run_scene(scene, experiment);
    for (Measurement& m : ms) result.measurements.push_back(std::move(m));
  }
  return result;
}

}  // namespace pathspace::study
