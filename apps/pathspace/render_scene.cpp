#include "render_scene.h"

#include <filesystem>

#include <fmt/format.h>

#include "pathspace/base/printable.h"
#include "pathspace/camera/pixel_filter_table.h"
#include "pathspace/checkpoint/checkpoint_file.h"
#include "pathspace/io/file_bytes.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/options/option_parse.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/scene/scene_validation.h"
#include "pathspace/session/run_options.h"
#include "job_group.h"
#include "number_options.h"
#include "pathspace/options/usage_error.h"

namespace pathspace::cli {

// "x,y,z", each a finite number within the scene coordinate range (scene/scene_validation.h).
std::optional<Vec3> parse_vec3(const std::string& text, const char* option) {
  if (text.empty()) return std::nullopt;
  float c[3];
  size_t begin = 0;
  for (int i = 0; i < 3; ++i) {
    const size_t end = i < 2 ? text.find(',', begin) : text.size();
    if (end == std::string::npos) throw UsageError(fmt::format("{} expects x,y,z, e.g. 0,1,6.8, not '{}'", option, text));
    try {
      c[i] = parse_float_option(option + 2, text.substr(begin, end - begin), -kMaxSceneCoordinate, kMaxSceneCoordinate);
    } catch (const OptionError& e) {
      throw UsageError(fmt::format("{} expects x,y,z, e.g. 0,1,6.8, not '{}': {}", option, text, e.what()));
    }
    begin = end + 1;
  }
  return Vec3(c[0], c[1], c[2]);
}

// Under mpirun every rank reads the same scene and notices the same: rank 0 alone prints it.
void print_warnings(const std::vector<std::string>& warnings) {
  if (const std::shared_ptr<ProcessGroup> group = job_group(); group && group->rank() != 0) return;
  for (const std::string& w : warnings) fmt::print(stderr, "{}\n", printable(w));
}

PreparedScene prepare_scene(const RenderOptions& o) {
  set_decompression_limit(o.max_decompression_ratio);
  PreparedScene p;
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
  for (const std::string& d : o.defines) {
    const size_t eq = d.find('=');
    const std::string name = d.substr(0, eq);
    if (!is_scene_parameter_name(name)) throw UsageError("-D " + d + ": a parameter name is made of letters, digits and '_'");
    load_options.defines.emplace_back(name, d.substr(eq + 1));
  }
  load_options.animation = o.animation;
  if (!from_file && (o.substitute_missing_textures || !o.defines.empty() || !o.animation.empty()))
    throw UsageError("--substitute-missing-textures, -D and --animation apply to scene files only");
  const Resolution res = image_size(o.resolution);
  if (from_file && !o.resolution.empty()) load_options.width = res.width, load_options.height = res.height;
  if (from_file) {
    p.label = p.id = p.file = scene_name;
    p.load_options = load_options;
    p.display_name = std::filesystem::path(scene_name).stem().string();
    std::vector<std::string> warnings;
    SceneFileSettings file_settings;
    try {
      const InputFileLog read;
      p.scene = load_scene(scene_name, load_options, &warnings, &file_settings);
      p.input_files = read.files();
      p.key = scene_files_hash(p.input_files);
    } catch (const Error&) {
      // What was noticed before the error can explain it (on every rank: the error may be this rank's).
      for (const std::string& w : warnings) fmt::print(stderr, "{}\n", printable(w));
      throw;
    }
    print_warnings(warnings);
    p.file_spp = file_settings.spp;
  } else {
    p.label = p.display_name = info->name;
    p.id = info->id;
    p.key = std::string("builtin:") + info->name;
    p.scene = make_builtin_scene(info->name, res.width, res.height);
    // A placed camera (`pathspace view`'s CLI options reproduce any view) has square pixels.
    apply_camera_options(load_options, false, res.width, res.height, &p.scene);
  }
  apply_scene_options(o, &p.scene);
  // Every scene, built-in or from any file format, with the command line's camera changes applied.
  validate_scene(p.scene, &p.validation_warnings);
  print_warnings(p.validation_warnings);
  return p;
}

std::vector<NamedFile> scene_inputs(const PreparedScene& prepared) {
  std::vector<NamedFile> inputs;
  for (const InputFile& f : prepared.input_files)
    inputs.push_back({f.path == prepared.file ? "the scene file" : "read by the scene", f.path});
  return inputs;
}

namespace {

// --pixel-filter and its radius over the scene's filter: a new kind starts from its usual radius (the
// gaussian's sigma a third of the radius, Mitchell's B = C = 1/3); the same kind keeps the scene's
// parameters except the radius given.
void apply_pixel_filter_options(const RenderOptions& o, PerspectiveCamera* camera) {
  const PixelFilter& scene_filter = camera->filter;
  const PixelFilterKind kind = o.pixel_filter.empty() ? scene_filter.kind : *parse_pixel_filter_kind(o.pixel_filter);
  const bool same_kind = kind == scene_filter.kind;
  const float radius = o.pixel_filter_radius > 0.f ? o.pixel_filter_radius : same_kind ? scene_filter.radius : default_pixel_filter_radius(kind);
  const float sigma = same_kind && !(o.pixel_filter_radius > 0.f) ? scene_filter.sigma : radius / 3.f;
  try {
    camera->filter = same_kind ? make_pixel_filter(kind, radius, sigma, scene_filter.b, scene_filter.c) : make_pixel_filter(kind, radius, sigma);
  } catch (const Error& e) {
    throw UsageError(std::string("--pixel-filter: ") + e.what());
  }
}

}  // namespace

void apply_scene_options(const RenderOptions& o, Scene* scene) {
  if (!o.pixel_filter.empty() || o.pixel_filter_radius > 0.f) apply_pixel_filter_options(o, &scene->camera);
  if (o.lens_radius >= 0.f || o.focus_distance > 0.f) {
    const PerspectiveCamera& c = scene->camera;
    const float radius = o.lens_radius >= 0.f ? o.lens_radius : c.lens_radius;
    const float focus = o.focus_distance > 0.f ? o.focus_distance : (c.is_pinhole() ? 0.f : c.focus_distance);
    if (radius > 0.f && !(focus > 0.f))
      throw UsageError("--lens-radius needs --focus-distance: the scene's camera is a pinhole and has no focus distance");
    if (!(radius > 0.f) && o.focus_distance > 0.f) throw UsageError("--focus-distance needs a thin lens: give --lens-radius too");
    if (!set_thin_lens(&scene->camera, radius, focus)) throw UsageError("invalid --lens-radius or --focus-distance");
  }
  if (!parse_light_selection(o.light_selection, &scene->light_selection))
    throw UsageError("unknown --light-selection '" + o.light_selection + "'");
  scene->finalize();
}

}  // namespace pathspace::cli
