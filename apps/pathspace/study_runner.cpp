// Renders, files and error numbers of one `pathspace study` run (study_runner.h): the measurement
// behind every column of the PCLT paper's figure reproductions.
#include "study_runner.h"

#include <cctype>
#include <regex>

#include <fmt/format.h>

#include "error_colormap.h"
#include "pathspace/integrators/render.h"
#include "pathspace/io/image_io.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace::cli {

namespace {

// The reference must not share random numbers with the runs it judges: with the same seed a BPT run
// would be correlated with a BPT reference and its error would look too small.
constexpr uint64_t kReferenceSeedOffset = 0x5EEDF00DULL;

std::string slug(const std::string& text) {
  std::string s;
  for (char c : text) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (std::isalnum(u))
      s += char(std::tolower(u));
    else if (!s.empty() && s.back() != '-')
      s += '-';
  }
  while (!s.empty() && s.back() == '-') s.pop_back();
  return s;
}

// Numbers from an integrator's human-readable report (integrator.h report()). The report is the
// integrators' only channel for these statistics; parsing it keeps the study out of their code.
void parse_report(const std::string& report, nlohmann::ordered_json* metrics) {
  const std::string num = "([0-9.eE+-]+)";
  std::smatch m;
  if (std::regex_search(report, m, std::regex("pclt: memory ([0-9]+) bytes")))
    (*metrics)["memory_bytes"] = std::stoull(m[1].str());
  if (std::regex_search(report, m, std::regex("pclt: cache " + num + "% of pixels")))
    (*metrics)["cache_fill_percent"] = std::stod(m[1].str());
  if (std::regex_search(report, m, std::regex("pclt: time eye " + num + " s, build " + num + " s, light " + num + " s"))) {
    (*metrics)["eye_s"] = std::stod(m[1].str());
    (*metrics)["build_s"] = std::stod(m[2].str());
    (*metrics)["light_s"] = std::stod(m[3].str());
  }
  if (std::regex_search(report, m, std::regex("per iteration " + num + " gather queries, " + num + " gathered entries, " + num +
                                              " visibility tests, " + num + " projections"))) {
    (*metrics)["gathered_per_iteration"] = std::stod(m[2].str());
    (*metrics)["projections_per_iteration"] = std::stod(m[4].str());
  }
  if (std::regex_search(report, m, std::regex("sppm: time eye " + num + " s.*grid " + num + " s, photons " + num + " s"))) {
    (*metrics)["eye_s"] = std::stod(m[1].str());
    (*metrics)["light_s"] = std::stod(m[3].str());
  }
}

// The reference's own relMSE (its variance of the mean relative to its value): the floor below which
// no run's error can be measured.
double reference_noise(const Image& reference, const Image& variance) {
  double sum = 0.0;
  for (size_t i = 0; i < reference.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double r = reference.pixels[i][c];
      sum += double(variance.pixels[i][c]) / (r * r + kRelMseEpsilon);
    }
  return reference.size() ? sum / (3.0 * double(reference.size())) : 0.0;
}

}  // namespace

std::unique_ptr<StudyScene> StudyRunner::prepare_scene(const std::string& name_or_id, int width, int height,
                                                       const std::string& integrator, double time_s) const {
  auto s = std::make_unique<StudyScene>();
  const BuiltinSceneInfo* info = find_builtin_scene(name_or_id);
  s->name = info->name;
  s->id = info->id;
  s->scene = make_builtin_scene(info->name, width, height);
  s->light_count = s->scene.lights.size();
  s->accel = std::make_unique<Accel>(s->scene);

  RenderRequest request;
  request.integrator = integrator;
  request.time_limit_s = time_s;
  request.threads = config_.threads;
  request.settings.seed = config_.seed + kReferenceSeedOffset;
  Film film(width, height);
  if (!config_.quiet) fmt::print("study: {} reference, {} for {:.3g} s\n", s->id, integrator, time_s);
  std::fflush(stdout);
  const RenderStats stats = render(s->scene, *s->accel, request, film);
  s->reference = film.mean();
  s->reference_variance = film.variance_of_mean();
  s->reference_png = fmt::format("images/{}-reference.png", s->id);
  write_image(config_.out_dir + "/" + s->reference_png, s->reference);
  nlohmann::ordered_json& j = s->reference_info;
  j["integrator"] = integrator;
  j["time_budget_s"] = time_s;
  j["time_s"] = stats.wall_s;
  j["iterations"] = stats.spp;
  j["seed"] = request.settings.seed;
  j["noise_rel_mse"] = reference_noise(s->reference, s->reference_variance);
  j["image_png"] = s->reference_png;
  if (config_.write_exr) {
    const std::string exr = fmt::format("images/{}-reference.exr", s->id);
    write_image(config_.out_dir + "/" + exr, s->reference);
    j["image_exr"] = exr;
  }
  return s;
}

StudyRun StudyRunner::run(const StudyScene& scene, const RunSpec& spec) const {
  RenderRequest request;
  request.integrator = spec.integrator;
  request.spp = spec.iterations;
  request.time_limit_s = spec.time_s;
  request.threads = config_.threads;
  request.settings = spec.settings;
  request.settings.seed = config_.seed;
  Film film(scene.scene.camera.width, scene.scene.camera.height);
  const RenderStats stats = render(scene.scene, *scene.accel, request, film);

  StudyRun r;
  r.figure = spec.figure;
  r.scene_id = scene.id;
  r.label = spec.label;
  r.integrator = spec.integrator;
  r.settings = spec.settings_json;
  r.time_budget_s = spec.time_s;
  r.time_s = stats.wall_s;
  r.iterations = stats.spp;
  r.image = film.mean();
  r.error = image_error(r.image, scene.reference);
  r.rel_mse_debiased = image_error(r.image, scene.reference, &scene.reference_variance).rel_mse;
  parse_report(stats.report, &r.metrics);

  const std::string base = fmt::format("images/{}-{}-{}", scene.id, spec.figure, slug(spec.label));
  r.image_png = base + ".png";
  r.error_png = base + ".err.png";
  write_image(config_.out_dir + "/" + r.image_png, r.image);
  write_image(config_.out_dir + "/" + r.error_png, colour_error_map(rel_error_map(r.image, scene.reference)));
  if (config_.write_exr) {
    r.image_exr = base + ".exr";
    write_image(config_.out_dir + "/" + r.image_exr, r.image);
  }
  if (!config_.quiet) {
    fmt::print("study: {} {} {}: {:.2f} s, {} iterations, relMSE {:.4g}\n", scene.id, spec.figure, spec.label, r.time_s,
               r.iterations, r.error.rel_mse);
    std::fflush(stdout);
  }
  return r;
}

StudyRun StudyRunner::reuse(const StudyRun& run, const std::string& figure, const std::string& label) {
  StudyRun r = run;
  r.reused_from = run.figure;
  r.figure = figure;
  r.label = label;
  return r;
}

nlohmann::ordered_json to_json(const StudyRun& run) {
  nlohmann::ordered_json j;
  j["figure"] = run.figure;
  j["scene"] = run.scene_id;
  j["label"] = run.label;
  j["integrator"] = run.integrator;
  j["settings"] = run.settings;
  if (run.time_budget_s > 0) j["time_budget_s"] = run.time_budget_s;
  j["time_s"] = run.time_s;
  j["iterations"] = run.iterations;
  j["rel_mse"] = run.error.rel_mse;
  j["rel_mse_debiased"] = run.rel_mse_debiased;
  j["mse"] = run.error.mse;
  j["mean"] = run.error.mean_image;
  j["mean_reference"] = run.error.mean_reference;
  j["metrics"] = run.metrics;
  j["image_png"] = run.image_png;
  j["error_png"] = run.error_png;
  if (!run.image_exr.empty()) j["image_exr"] = run.image_exr;
  if (!run.reused_from.empty()) j["same_render_as"] = run.reused_from;
  return j;
}

nlohmann::ordered_json pclt_settings_json(const PcltSettings& s) {
  const char* visibility[] = {"shadow-ray", "z-buffer", "plane"};
  nlohmann::ordered_json j;
  j["light_paths_per_iteration"] = s.light_paths;
  j["visibility"] = visibility[int(s.visibility)];
  if (s.visibility != PcltVisibility::shadow_ray) j["epsilon"] = s.epsilon;
  j["hash_map"] = s.hash_map == PcltHashMap::chained ? "chained" : "stochastic";
  if (s.hash_map == PcltHashMap::stochastic) j["stochastic_slots"] = s.stochastic_slots;
  j["alpha"] = s.alpha;
  j["specular_emission"] = s.specular_emission;
  return j;
}

nlohmann::ordered_json sppm_settings_json(const SppmSettings& s) {
  nlohmann::ordered_json j;
  j["photons_per_iteration"] = s.photons;
  j["alpha"] = s.alpha;
  return j;
}

}  // namespace pathspace::cli
