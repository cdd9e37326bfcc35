#include "render_command.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "pathspace/accel/accel.h"
#include "pathspace/filters/filter_registry.h"
#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/session/render.h"
#include "pathspace/session/render_session.h"
#include "pathspace/io/atomic_file.h"
#include "pathspace/io/image_io.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/scene/builtin_scenes.h"
#include "progress_reporter.h"
#include "render_stats_json.h"
#include "usage_error.h"

namespace pathspace::cli {

namespace {

constexpr int kMaxResolution = 16384;
constexpr const char* kDefaultOutputFolder = "pathspace-out";

struct Resolution {
  int width = 512, height = 512;
};

Resolution parse_resolution(const std::string& text) {
  Resolution r;
  if (text.empty()) return r;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &r.width, &x, &r.height, &extra) != 3 || (x != 'x' && x != 'X'))
    throw UsageError("--resolution expects WxH, e.g. 512x512, not '" + text + "'");
  if (r.width < 1 || r.height < 1 || r.width > kMaxResolution || r.height > kMaxResolution)
    throw UsageError(fmt::format("--resolution {}: width and height must be between 1 and {}", text, kMaxResolution));
  return r;
}

// The output files: --out as given, else pathspace-out/<scene>.exr and .png.
std::vector<std::string> output_paths(const RenderOptions& o, const std::string& scene_name) {
  if (!o.outputs.empty()) return o.outputs;
  std::filesystem::create_directories(kDefaultOutputFolder);
  const std::string base = std::string(kDefaultOutputFolder) + "/" + scene_name;
  return {base + ".exr", base + ".png"};
}

std::optional<Vec3> parse_vec3(const std::string& text, const char* option) {
  if (text.empty()) return std::nullopt;
  Vec3 v;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%f,%f,%f%c", &v.x, &v.y, &v.z, &extra) != 3 || !all_finite(v))
    throw UsageError(fmt::format("{} expects x,y,z, e.g. 0,1,6.8, not '{}'", option, text));
  return v;
}

// A positional scene argument names a file when it has a scene-file extension or names an existing
// file that is not also a built-in scene name.
bool names_scene_file(const std::string& scene) {
  std::error_code ec;
  return is_scene_file(scene) || (!find_builtin_scene(scene) && std::filesystem::is_regular_file(scene, ec));
}

// The integrator, filter and their options, checked against the registry (usage errors name the
// integrators or filter an option belongs to).
RenderConfig render_config(const RenderOptions& o) {
  try {
    RenderConfig config = configure_render(o.integrator, o.filter, o.registry.given());
    config.seed = o.seed;
    config.threads = o.threads;
    return config;
  } catch (const OptionError& e) {
    throw UsageError(e.what());
  }
}

// The names of the registered filters, with "none".
std::vector<std::string> filter_choices() {
  std::vector<std::string> names = {FilterChoice::kNone};
  for (const std::string& n : filter_registry().names()) names.push_back(n);
  return names;
}

}  // namespace

CLI::App* add_render_command(CLI::App& app, RenderOptions* o) {
  CLI::App* cmd = app.add_subcommand("render", "Render a scene to EXR/PFM/PNG");
  cmd->add_option("scene", o->scene, "Built-in scene name or id (see 'pathspace info --scenes'), or a .pbrt/.xml/.gltf/.glb/.ply/.obj file")
      ->default_str(kDefaultSceneName);
  cmd->add_option("-i,--integrator", o->integrator,
                  fmt::format("Integrator: {} (see 'pathspace info --integrators')", integrator_registry().joined_names()))
      ->capture_default_str();
  cmd->add_option("--filter", o->filter, "Path space filter of the selected vertices (with an integrator that composes with it)")
      ->check(CLI::IsMember(filter_choices()))
      ->capture_default_str();
  CLI::Option* spp = cmd->add_option("-s,--spp", o->spp, "Samples per pixel (default 16)")->check(CLI::Range(1u, 1u << 24));
  cmd->add_option("-t,--time", o->time_s, "Render for this many seconds (whole passes) instead of --spp")
      ->check(CLI::Range(1e-3, 1e7))
      ->excludes(spp);
  cmd->add_option("-r,--resolution", o->resolution, "Image size WxH (default 512x512, or the scene file's)");
  cmd->add_option("--camera-pos", o->camera_pos, "Scene files: camera position x,y,z");
  cmd->add_option("--camera-target", o->camera_target, "Scene files: point the camera looks at x,y,z (default: the scene centre)");
  cmd->add_option("--camera-up", o->camera_up, "Scene files: camera up vector x,y,z (default 0,1,0)");
  cmd->add_option("--fov", o->fov, "Scene files: field of view of the shorter image axis in degrees")->check(CLI::Range(0.01, 179.0));
  cmd->add_option("--lens-radius", o->lens_radius, "Thin lens radius in scene units for depth of field (0: pinhole; default: the scene's)")
      ->check(CLI::Range(0.0, 1e30));
  cmd->add_option("--focus-distance", o->focus_distance, "Distance of the plane in focus along the view axis (default: the scene's)")
      ->check(CLI::Range(1e-30, 1e30));
  cmd->add_flag("--substitute-missing-textures", o->substitute_missing_textures,
                "Scene files: replace missing image textures by mid grey 0.5 and a missing environment map by white 1 (warnings)");
  cmd->add_option("--seed", o->seed, "Random seed (renders are a pure function of the seed)")->capture_default_str();
  cmd->add_option("-j,--threads", o->threads, "Worker threads (0: all cores)")->check(CLI::Range(0, 4096))->capture_default_str();
  cmd->add_option("-o,--out", o->outputs, "Output file(s): .exr, .pfm or .png (default pathspace-out/SCENE.exr and .png)");
  cmd->add_option("--stats", o->stats_path, "Write run statistics as JSON to this file");
  cmd->add_option("--variance-out", o->variance_path, "Write the per-pixel variance of the mean (.exr/.pfm; .png would clamp it)");
  cmd->add_flag("-q,--quiet", o->quiet, "No progress output");
  cmd->add_option("--light-selection", o->light_selection, "How lights are picked for sampling")
      ->check(CLI::IsMember({"uniform", "power"}))
      ->capture_default_str();
  o->registry.add_to(cmd);
  return cmd;
}

int run_render_command(const RenderOptions& o) {
  // Validate everything before the (possibly long) render.
  const std::string scene_name = o.scene.empty() ? kDefaultSceneName : o.scene;
  const bool from_file = names_scene_file(scene_name);
  const BuiltinSceneInfo* info = from_file ? nullptr : find_builtin_scene(scene_name);
  if (!from_file && !info) throw UsageError("unknown scene '" + scene_name + "'", "run 'pathspace info --scenes' for the list, or pass a .pbrt/.xml/.gltf/.glb/.ply/.obj file");
  SceneLoadOptions load_options;
  load_options.camera_position = parse_vec3(o.camera_pos, "--camera-pos");
  load_options.camera_target = parse_vec3(o.camera_target, "--camera-target");
  load_options.camera_up = parse_vec3(o.camera_up, "--camera-up");
  if (o.fov > 0.f) load_options.fov_degrees = o.fov;
  load_options.substitute_missing_textures = o.substitute_missing_textures;
  if (!from_file && (load_options.camera_position || load_options.camera_target || load_options.camera_up || load_options.fov_degrees ||
                     o.substitute_missing_textures))
    throw UsageError("--camera-pos, --camera-target, --camera-up, --fov and --substitute-missing-textures apply to scene files only");
  Resolution res = parse_resolution(o.resolution);
  if (from_file && !o.resolution.empty()) load_options.width = res.width, load_options.height = res.height;
  const RenderConfig config = render_config(o);
  const std::string display_name = from_file ? std::filesystem::path(scene_name).stem().string() : info->name;
  const std::vector<std::string> outputs = output_paths(o, display_name);
  for (const std::string& path : outputs) {
    try {
      image_format_from_path(path);
    } catch (const Error& e) {
      throw UsageError(e.what());
    }
    check_output_writable(path);
  }
  if (!o.stats_path.empty()) check_output_writable(o.stats_path);
  if (!o.variance_path.empty()) {
    try {
      image_format_from_path(o.variance_path);
    } catch (const Error& e) {
      throw UsageError(e.what());
    }
    check_output_writable(o.variance_path);
  }

  SceneFileSettings file_settings;
  Scene scene;
  if (from_file) {
    std::vector<std::string> warnings;
    scene = load_scene(scene_name, load_options, &warnings, &file_settings);
    for (const std::string& w : warnings) fmt::print(stderr, "{}\n", w);
    res.width = scene.camera.width;
    res.height = scene.camera.height;
  } else {
    scene = make_builtin_scene(info->name, res.width, res.height);
  }
  if (o.lens_radius >= 0.f || o.focus_distance > 0.f) {
    const PerspectiveCamera& c = scene.camera;
    const float radius = o.lens_radius >= 0.f ? o.lens_radius : c.lens_radius;
    const float focus = o.focus_distance > 0.f ? o.focus_distance : (c.is_pinhole() ? 0.f : c.focus_distance);
    if (radius > 0.f && !(focus > 0.f))
      throw UsageError("--lens-radius needs --focus-distance: the scene's camera is a pinhole and has no focus distance");
    if (!(radius > 0.f) && o.focus_distance > 0.f) throw UsageError("--focus-distance needs a thin lens: give --lens-radius too");
    if (!set_thin_lens(&scene.camera, radius, focus)) throw UsageError("invalid --lens-radius or --focus-distance");
  }
  scene.light_selection = o.light_selection == "power" ? LightSelection::power : LightSelection::uniform;
  scene.finalize();
  RenderSession session(std::move(scene), config);
  const uint32_t spp = o.spp > 0 ? o.spp : (file_settings.spp > 0 ? uint32_t(file_settings.spp) : 16);
  const RunLimit limit = o.time_s > 0.0 ? RunLimit::for_seconds(o.time_s) : RunLimit::for_passes(spp);
  ProgressReporter progress(stdout, uint64_t(res.width) * uint64_t(res.height), o.quiet);
  if (!o.quiet) fmt::print("pathspace: {} ({}), {}x{}, {}\n", display_name, from_file ? scene_name : info->id, res.width, res.height, o.integrator);
  session.run(limit, [&](const RenderProgress& p) { progress.update(p); });
  progress.finish();
  const RenderSnapshot result = session.snapshot();
  const RenderStats& stats = result.stats;

  for (const std::string& path : outputs) write_image(path, result.mean);
  std::vector<std::string> written = outputs;
  if (!o.variance_path.empty()) {
    write_image(o.variance_path, result.variance);
    written.push_back(o.variance_path);
  }
  for (const NamedImage& aov : result.aovs) {
    const std::filesystem::path first(outputs.front());
    const std::string path = (first.parent_path() / (first.stem().string() + ".aov-" + aov.name + ".exr")).string();
    write_image(path, aov.image);
    written.push_back(path);
  }
  const OptionValues given = o.registry.given();
  const std::string* depth = given.find("max-depth");
  RenderRunInfo run{display_name, res.width, res.height, depth ? std::stoi(*depth) : session.scene().max_path_segments,
                    fmt::format("{}", fmt::join(written, ","))};
  if (!o.stats_path.empty()) write_text_file(o.stats_path, render_stats_json(stats, run));
  if (!o.quiet) {
    fmt::print("{} spp in {:.2f} s: {:.2f} Mrays/s, {:.3g} paths/s, {} threads", stats.spp, stats.wall_s, stats.mrays_per_s(),
               stats.paths_per_s(), stats.threads);
    if (stats.dropped_samples) fmt::print(", {} NaN/Inf samples dropped", stats.dropped_samples);
    fmt::print("\n{}wrote {}\n", format_statistics(stats.details), fmt::join(written, ", "));
  }
  return 0;
}

}  // namespace pathspace::cli
