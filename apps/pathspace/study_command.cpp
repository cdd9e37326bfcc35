// `pathspace study pclt` (study_command.h): options, validation before any render, the per-scene loop
// over the PCLT paper's figures on the experiment harness (src/pathspace/study/), and the JSON and
// HTML outputs (written atomically, io/atomic_file.h).
#include "study_command.h"

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/io/atomic_file.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/session/render.h"
#include "pathspace/study/experiment_runner.h"
#include "pathspace/study/html_report.h"
#include "pathspace/study/image_files.h"
#include "study_pclt_figures.h"
#include "usage_error.h"

namespace pathspace::cli {

namespace {

constexpr int kMaxStudyResolution = 4096;
constexpr double kDefaultReferenceFactor = 20.0;

void parse_resolution(const std::string& text, int* width, int* height) {
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", width, &x, height, &extra) != 3 || (x != 'x' && x != 'X'))
    throw UsageError("--resolution expects WxH, e.g. 128x128, not '" + text + "'");
  if (*width < 1 || *height < 1 || *width > kMaxStudyResolution || *height > kMaxStudyResolution)
    throw UsageError(fmt::format("--resolution {}: width and height must be between 1 and {}", text, kMaxStudyResolution));
}

// The reference is rendered with the best unbiased integrator available: BPT covers every path the
// Cornell variants have (caustics through its light-tracing strategies), PT is the fallback.
std::string reference_integrator() { return integrator_registry().find("bpt") ? "bpt" : "pt"; }

size_t max_builtin_light_count() {
  size_t n = 0;
  for (const BuiltinSceneInfo& info : builtin_scenes()) n = std::max(n, make_builtin_scene(info.name, 1, 1).lights.size());
  return n;
}

}  // namespace

CLI::App* add_study_command(CLI::App& app, StudyOptions* o) {
  CLI::App* study = app.add_subcommand("study", "Reproduce a paper's figures on the built-in scenes (images, JSON, HTML)");
  study->require_subcommand(1);
  CLI::App* pclt = study->add_subcommand("pclt", "Pixel cache light tracing paper: figs. 1, 5, 6, 7, 8 (fig. 9 explained)");
  pclt->add_option("-o,--out", o->out, "Output folder (created)")->capture_default_str();
  pclt->add_option("-r,--resolution", o->resolution, "Image size WxH")->capture_default_str();
  pclt->add_option("-t,--time", o->time_s, "Seconds per equal-time image (fig. 1); sets the iterations of figs. 5-8")
      ->check(CLI::Range(1e-3, 1e6))
      ->capture_default_str();
  pclt->add_option("--reference-time", o->reference_time_s, "Seconds for each scene's reference (default: 20 x --time)")
      ->check(CLI::Range(1e-3, 1e7));
  pclt->add_option("--scenes", o->scenes, "Built-in scenes, comma-separated names or ids")
      ->delimiter(',')
      ->capture_default_str();
  pclt->add_option("--seed", o->seed, "Random seed of the runs (the reference uses another)")->capture_default_str();
  pclt->add_option("-j,--threads", o->threads, "Worker threads (0: all cores)")->check(CLI::Range(0, 4096))->capture_default_str();
  pclt->add_flag("--no-exr", o->no_exr, "Write PNG only (commit-sized output)");
  pclt->add_flag("-q,--quiet", o->quiet, "No progress lines");
  return study;
}

int run_study_command(const StudyOptions& o) {
  // Validate everything before the first render.
  int width = 0, height = 0;
  parse_resolution(o.resolution, &width, &height);
  if (o.scenes.empty()) throw UsageError("--scenes needs at least one scene");
  std::vector<std::string> scene_names;
  for (const std::string& s : o.scenes) {
    const BuiltinSceneInfo* info = find_builtin_scene(s);
    if (!info) throw UsageError("unknown scene '" + s + "'", "run 'pathspace info --scenes' for the list");
    if (std::find(scene_names.begin(), scene_names.end(), info->name) == scene_names.end()) scene_names.push_back(info->name);
  }
  if (o.out.empty()) throw UsageError("--out must name a folder");
  const double reference_time = o.reference_time_s > 0 ? o.reference_time_s : kDefaultReferenceFactor * o.time_s;
  study::create_image_folder(o.out);
  check_output_writable(o.out + "/study.json");

  study::RunnerOptions runner_options;
  runner_options.out_dir = o.out;
  runner_options.write_exr = !o.no_exr;
  runner_options.threads = o.threads;
  runner_options.keep_images = true;  // fig. 6 compares with fig. 1's image
  runner_options.quiet = o.quiet;
  const study::ExperimentRunner runner(runner_options);
  const std::string ref_integrator = reference_integrator();
  study::ReferenceSpec reference;
  reference.render = study::reference_render_config(ref_integrator);
  reference.render.seed = o.seed + study::kReferenceSeedOffset;
  reference.budget = study::Budget::for_seconds(reference_time);

  std::vector<StudyFigure> figures = make_pclt_figures();
  describe_fig9(max_builtin_light_count(), &figures);
  std::vector<study::SceneSummary> summaries;
  nlohmann::ordered_json references = nlohmann::ordered_json::object();
  for (const std::string& name : scene_names) {
    // One scene at a time: its geometry, acceleration structure and images are freed before the next.
    const study::PreparedScene scene = runner.prepare(study::SceneSpec{name, width, height}, reference);
    run_pclt_figures(runner, scene, PcltStudyParams{o.time_s, o.seed}, &figures);
    summaries.push_back(scene.summary);
    nlohmann::ordered_json& r = references[scene.id()];
    r = study::to_json(scene.summary.reference);
    r["name"] = scene.summary.name;
    r["lights"] = scene.summary.light_count;
  }

  nlohmann::ordered_json settings;
  settings["width"] = width;
  settings["height"] = height;
  settings["time_s"] = o.time_s;
  settings["reference_time_s"] = reference_time;
  settings["reference_integrator"] = ref_integrator;
  settings["seed"] = o.seed;
  settings["threads"] = o.threads;
  settings["build_type"] = build_type();
  settings["integrators"] = integrator_registry().names();

  nlohmann::ordered_json doc;
  doc["study"] = "pclt";
  doc["paper"] = "Pixel Cache Light Tracing";
  doc["settings"] = settings;
  doc["scenes"] = references;
  doc["figures"] = nlohmann::ordered_json::object();
  for (const StudyFigure& f : figures) doc["figures"][f.id] = to_json(f);
  write_text_file(o.out + "/study.json", doc.dump(2) + "\n");
  study::ReportPage page;
  page.title = "Pixel cache light tracing: the paper's figures on pathspace scenes";
  page.settings = settings;
  page.scenes = summaries;
  for (const StudyFigure& f : figures) page.sections.push_back(report_section(f));
  write_text_file(o.out + "/study.html", study::html_report(o.out, page));
  if (!o.quiet) fmt::print("wrote {0}/study.html, {0}/study.json and {0}/images/\n", o.out);
  return 0;
}

}  // namespace pathspace::cli
