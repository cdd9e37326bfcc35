// `pathspace study` (study_command.h): the subcommands' options, the checks and outputs every study
// shares (study_setup.h), and `study pclt`'s per-scene loop over the PCLT paper's figures
// (study_pclt_figures.h); `study psf` runs in study_psf_command.cpp.
#include "study_command.h"

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/io/atomic_file.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/session/render.h"
#include "pathspace/study/html_report.h"
#include "pathspace/study/image_files.h"
#include "number_options.h"
#include "study_pclt_figures.h"
#include "study_psf_figures.h"
#include "study_setup.h"
#include "usage_error.h"

namespace pathspace::cli {

namespace {

constexpr int kMaxStudyResolution = 4096;
constexpr double kDefaultReferenceFactor = 20.0;

// The reference is rendered with the best unbiased integrator available: BPT covers every path the
// Cornell variants have (caustics through its light-tracing strategies), PT is the fallback.
std::string reference_integrator() { return integrator_registry().find("bpt") ? "bpt" : "pt"; }

size_t max_builtin_light_count() {
  size_t n = 0;
  for (const BuiltinSceneInfo& info : builtin_scenes()) n = std::max(n, make_builtin_scene(info.name, 1, 1).lights.size());
  return n;
}

void add_common_options(CLI::App* sub, StudyOptions* o, const std::string& time_help) {
  sub->add_option("-o,--out", o->out, "Output folder (created)")->capture_default_str();
  sub->add_option("-r,--resolution", o->resolution, "Image size WxH")->capture_default_str();
  sub->add_option("-t,--time", o->time_s, time_help)->check(checked_real("time", 1e-3, 1e6))->capture_default_str();
  sub->add_option("--reference-time", o->reference_time_s, "Seconds for each scene's reference (default: 20 x --time)")
      ->check(checked_real("reference-time", 1e-3, 1e7));
  sub->add_option("--scenes", o->scenes, "Built-in scenes, comma-separated names or ids")->delimiter(',')->capture_default_str();
  sub->add_option("--seed", o->seed, "Random seed of the runs (the reference uses another)")
      ->check(checked_unsigned("seed", UINT64_MAX))
      ->capture_default_str();
  sub->add_option("-j,--threads", o->threads, "Worker threads (0: all cores)")->check(checked_integer("threads", 0, 4096))->capture_default_str();
  sub->add_flag("--no-exr", o->no_exr, "Write PNG only (commit-sized output)");
  sub->add_flag("-q,--quiet", o->quiet, "No progress lines");
}

int run_pclt_study(const StudyOptions& o) {
  const StudySetup setup = prepare_study(o);
  const study::ExperimentRunner runner = make_study_runner(o, /*keep_images=*/true);  // fig. 6 compares with fig. 1's image
  const study::ReferenceSpec reference = study_reference(o, setup);
  StudyDocument doc = study_document(o, setup, "pclt", "Pixel Cache Light Tracing",
                                     "Pixel cache light tracing: the paper's figures on pathspace scenes");
  doc.figures = make_pclt_figures();
  describe_fig9(max_builtin_light_count(), &doc.figures);
  for (const std::string& name : setup.scene_names) {
    // One scene at a time: its geometry, acceleration structure and images are freed before the next.
    const study::PreparedScene scene = runner.prepare(study::SceneSpec{name, setup.width, setup.height}, reference);
    run_pclt_figures(runner, scene, PcltStudyParams{o.time_s, o.seed}, &doc.figures);
    doc.scenes.push_back(scene.summary);
  }
  write_study(o, doc);
  return 0;
}

}  // namespace

void parse_resolution(const std::string& text, const std::string& option, int* width, int* height) {
  const Resolution r = parse_resolution_option(option.substr(2), text, kMaxStudyResolution);
  *width = r.width;
  *height = r.height;
}

StudySetup prepare_study(const StudyOptions& o) {
  StudySetup s;
  parse_resolution(o.resolution, "--resolution", &s.width, &s.height);
  if (o.scenes.empty()) throw UsageError("--scenes needs at least one scene");
  for (const std::string& name : o.scenes) {
    const BuiltinSceneInfo* info = find_builtin_scene(name);
    if (!info) throw UsageError("unknown scene '" + name + "'", "run 'pathspace info --scenes' for the list");
    if (std::find(s.scene_names.begin(), s.scene_names.end(), info->name) == s.scene_names.end()) s.scene_names.push_back(info->name);
  }
  if (o.out.empty()) throw UsageError("--out must name a folder");
  s.reference_time_s = o.reference_time_s > 0 ? o.reference_time_s : kDefaultReferenceFactor * o.time_s;
  s.reference_integrator = reference_integrator();
  study::create_image_folder(o.out);
  check_output_writable(o.out + "/study.json");
  return s;
}

study::ExperimentRunner make_study_runner(const StudyOptions& o, bool keep_images) {
  study::RunnerOptions r;
  r.out_dir = o.out;
  r.write_exr = !o.no_exr;
  r.threads = o.threads;
  r.keep_images = keep_images;
  r.quiet = o.quiet;
  return study::ExperimentRunner(r);
}

study::ReferenceSpec study_reference(const StudyOptions& o, const StudySetup& setup) {
  study::ReferenceSpec reference;
  reference.render = study::reference_render_config(setup.reference_integrator);
  reference.render.seed = o.seed + study::kReferenceSeedOffset;
  reference.budget = study::Budget::for_seconds(setup.reference_time_s);
  return reference;
}

nlohmann::ordered_json study_settings(const StudyOptions& o, const StudySetup& setup) {
  nlohmann::ordered_json settings;
  settings["width"] = setup.width;
  settings["height"] = setup.height;
  settings["time_s"] = o.time_s;
  settings["reference_time_s"] = setup.reference_time_s;
  settings["reference_integrator"] = setup.reference_integrator;
  settings["seed"] = o.seed;
  settings["threads"] = o.threads;
  settings["build_type"] = build_type();
  settings["integrators"] = integrator_registry().names();
  return settings;
}

StudyDocument study_document(const StudyOptions& o, const StudySetup& setup, std::string id, std::string paper, std::string title) {
  StudyDocument d;
  d.id = std::move(id);
  d.paper = std::move(paper);
  d.title = std::move(title);
  d.settings = study_settings(o, setup);
  return d;
}

void write_study(const StudyOptions& o, const StudyDocument& d) {
  nlohmann::ordered_json references = nlohmann::ordered_json::object();
  for (const study::SceneSummary& scene : d.scenes) {
    nlohmann::ordered_json& r = references[scene.id];
    r = study::to_json(scene.reference);
    r["name"] = scene.name;
    r["lights"] = scene.light_count;
  }
  nlohmann::ordered_json doc;
  doc["study"] = d.id;
  doc["paper"] = d.paper;
  doc["settings"] = d.settings;
  doc["scenes"] = references;
  doc["figures"] = nlohmann::ordered_json::object();
  for (const study::Figure& f : d.figures) doc["figures"][f.id] = study::to_json(f);
  write_text_file(o.out + "/study.json", doc.dump(2) + "\n");
  study::ReportPage page;
  page.title = d.title;
  page.settings = d.settings;
  page.scenes = d.scenes;
  for (const study::Figure& f : d.figures) page.sections.push_back(study::report_section(f));
  write_text_file(o.out + "/study.html", study::html_report(o.out, page));
  if (!o.quiet) fmt::print("wrote {0}/study.html, {0}/study.json and {0}/images/\n", o.out);
}

CLI::App* add_study_command(CLI::App& app, StudyCommandOptions* o) {
  CLI::App* study = app.add_subcommand("study", "Reproduce a paper's figures on the built-in scenes (images, JSON, HTML)");
  study->require_subcommand(1);
  CLI::App* pclt = study->add_subcommand("pclt", "Pixel cache light tracing paper: figs. 1, 5, 6, 7, 8 (fig. 9 explained)");
  add_common_options(pclt, &o->pclt, "Seconds per equal-time image (fig. 1); sets the iterations of figs. 5-8");
  pclt->callback([o] { o->study = "pclt"; });
  CLI::App* psf = study->add_subcommand(
      "psf", "Path space filtering papers (2014 consistent, 2021 hashed): their figures and an equal-time comparison");
  add_common_options(psf, &o->psf, "Seconds per equal-time image (the equal-time comparison)");
  psf->add_option("--max-spp", o->psf_only.max_spp, "Last sample count of the progressive series (2014 fig. 3): 1, 4, 16, ...")
      ->check(checked_integer("max-spp", 1, 1 << 20))
      ->capture_default_str();
  psf->add_option("--vertex-set-resolution", o->psf_only.vertex_set_resolution,
                  "Image size WxH of the vertex sets of the hash table figures (2019 figs. 7, 8)")
      ->capture_default_str();
  psf->add_option("--temporal-frames", o->psf_only.temporal_frames,
                  "Frames of the orbit measurements of the hashed filter across frames (2021 sec. 3.4.1; fig. 9 uses up to 32); 0: skip")
      ->check(checked_integer("temporal-frames", 0, 100000))
      ->capture_default_str();
  psf->add_option("--eviction-frames", o->psf_only.eviction_frames,
                  "Frames of the eviction flight through textured-room, per eviction policy (2021 sec. 3.4.3); 0: skip")
      ->check(checked_integer("eviction-frames", 0, 10000000))
      ->capture_default_str();
  psf->add_option("--room-scene", o->psf_only.room_scene,
                  "The textured-room scene file of the temporal figures (relative: to the working folder, else to the repository of the binary)")
      ->capture_default_str();
  psf->callback([o] { o->study = "psf"; });
  CLI::App* gallery = study->add_subcommand(
      "gallery", "Render every scene of a folder that has a reference image beside it and compare (mean ratio, relMSE, error maps)");
  add_gallery_options(gallery, &o->gallery);
  gallery->callback([o] { o->study = "gallery"; });
  return study;
}

int run_study_command(const StudyCommandOptions& o) {
  if (o.study == "psf") return run_psf_study(o.psf, o.psf_only);
  if (o.study == "gallery") return run_gallery_study(o.gallery);
  return run_pclt_study(o.pclt);
}

}  // namespace pathspace::cli
