// What every study does around its figures (studies/common/study_setup.h).
#include "studies/common/study_setup.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <fmt/format.h>

#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/io/atomic_file.h"
#include "pathspace/options/resolution_option.h"
#include "pathspace/options/usage_error.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/session/render.h"
#include "pathspace/study/html_report.h"
#include "pathspace/study/image_files.h"

namespace pathspace::studies {

namespace {

constexpr int kMaxStudyResolution = 4096;
constexpr double kDefaultReferenceFactor = 20.0;

// The reference is rendered with the best unbiased integrator available: BPT covers every path the
// Cornell variants have (caustics through its light-tracing strategies), PT is the fallback.
std::string reference_integrator() { return integrator_registry().find("bpt") ? "bpt" : "pt"; }

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
  if (!o.reference_dir.empty() && !std::filesystem::is_directory(o.reference_dir))
    throw UsageError("--reference-dir '" + o.reference_dir + "' is not a folder");
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

study::ReferenceSpec study_reference(const StudyOptions& o, const StudySetup& setup, const std::string& scene) {
  study::ReferenceSpec reference;
  reference.render = study::reference_render_config(setup.reference_integrator);
  reference.render.seed = o.seed + study::kReferenceSeedOffset;
  reference.budget = study::Budget::for_seconds(setup.reference_time_s);
  if (!o.reference_dir.empty()) {
    const std::filesystem::path image = std::filesystem::path(o.reference_dir) / (scene + ".exr");
    const std::filesystem::path variance = std::filesystem::path(o.reference_dir) / (scene + ".variance.exr");
    if (std::filesystem::is_regular_file(image)) {
      reference.image_file = image.string();
      if (std::filesystem::is_regular_file(variance)) reference.variance_file = variance.string();
    }
  }
  return reference;
}

nlohmann::ordered_json study_settings(const StudyOptions& o, const StudySetup& setup) {
  nlohmann::ordered_json settings;
  settings["width"] = setup.width;
  settings["height"] = setup.height;
  settings["time_s"] = o.time_s;
  settings["reference_time_s"] = setup.reference_time_s;
  settings["reference_integrator"] = setup.reference_integrator;
  settings["reference_dir"] = o.reference_dir;
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

}  // namespace pathspace::studies
