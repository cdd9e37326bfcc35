#include "scene_summary.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "pathspace/base/error.h"
#include "pathspace/base/printable.h"
#include "pathspace/camera/pixel_filter_table.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/scene/scene.h"
#include "pathspace/scene/scene_validation.h"
#include "pathspace/scene/surface_opacity.h"

namespace pathspace::cli {

namespace {

const char* light_kind(LightType t) {
  switch (t) {
    case LightType::area_triangle: return "area (triangles)";
    case LightType::area_sphere: return "area (spheres)";
    case LightType::point: return "point";
    case LightType::projector: return "projector";
    case LightType::directional: return "directional";
    case LightType::environment: return "environment";
    case LightType::spot: return "spot";
  }
  return "unknown";
}

// The material's kind as its lobes make it (a standard material may be diffuse, glossy, a mirror
// or glass, or a sum of them).
std::string base_material_kind(const Material& m) {
  switch (m.type) {
    case MaterialType::rough_conductor: return "rough conductor";
    case MaterialType::rough_dielectric: return "rough dielectric";
    case MaterialType::coated_diffuse: return "coated diffuse";
    case MaterialType::coated_conductor: return "coated conductor";
    case MaterialType::interface: return "interface (bounds media only)";
    case MaterialType::standard: break;
  }
  std::vector<std::string> lobes;
  const auto non_zero = [](const Rgb& c) { return c.r > 0.f || c.g > 0.f || c.b > 0.f; };
  if (non_zero(m.diffuse) || m.diffuse_texture >= 0) lobes.push_back("diffuse");
  if (non_zero(m.glossy) || m.glossy_texture >= 0) lobes.push_back("glossy");
  if (non_zero(m.specular) || m.specular_texture >= 0) lobes.push_back(m.ior > 0.f ? "glass" : "mirror");
  return lobes.empty() ? "black" : fmt::format("{}", fmt::join(lobes, " + "));
}

// The kind, "with cutout" where the material has opacity (scene/surface_opacity.h).
std::string material_kind(const Material& m) { return base_material_kind(m) + (has_cutout(m) ? " with cutout" : ""); }

// `path`: the file, or the built-in scene's name when `builtin`.
void print_summary(const std::string& path, bool builtin, const Scene& scene, const SceneFileSettings& settings,
                   const std::vector<std::string>& warnings, bool json) {
  std::map<std::string, size_t> lights, materials;
  for (const Light& l : scene.lights) ++lights[light_kind(l.type)];
  for (const Material& m : scene.materials) ++materials[material_kind(m)];
  size_t texels = 0;
  size_t texture_bytes = scene.environment_image.texels.size() * sizeof(Rgb);  // as rendered: 8-bit files take 3 bytes a texel
  for (const ImageTexture& t : scene.textures) texels += t.texel_count(), texture_bytes += t.memory_bytes();
  size_t moving_vertices = 0;  // motion blur (scene/motion.h): vertices that move while the shutter is open
  for (size_t i = 0; i < scene.positions_end.size(); ++i) moving_vertices += !(scene.positions_end[i] == scene.positions[i]);
  // Participating media (docs/media.md): how many of each kind, and whether the camera sits in one.
  size_t homogeneous_media = 0, grid_media = 0;
  for (const Medium& m : scene.media.media) ++(m.type == MediumType::homogeneous ? homogeneous_media : grid_media);
  const PerspectiveCamera& c = scene.camera;
  if (json) {
    nlohmann::ordered_json j;
    j["file"] = builtin ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(path);
    j["builtin"] = builtin ? nlohmann::ordered_json(path) : nlohmann::ordered_json(nullptr);
    j["vertices"] = scene.positions.size();
    j["triangles"] = scene.triangles.size();
    j["moving_vertices"] = moving_vertices;
    j["spheres"] = scene.spheres.size();
    j["textures"] = scene.textures.size();
    j["texels"] = texels;
    j["texture_bytes"] = texture_bytes;
    j["environment_image"] = scene.environment_image.empty() ? nlohmann::json(nullptr)
                                                             : nlohmann::json{scene.environment_image.width, scene.environment_image.height};
    j["lights"] = lights;
    j["materials"] = materials;
    j["media"] = {{"homogeneous", homogeneous_media}, {"grid", grid_media}, {"camera_in_medium", scene.media.camera_medium != kVacuum}};
    j["camera"] = {{"width", c.width}, {"height", c.height}, {"lens_radius", c.lens_radius}, {"moves", scene.camera_moves},
                   {"pixel_filter", describe_pixel_filter(c.filter)}};
    j["file_spp"] = settings.spp;
    j["max_path_segments"] = scene.max_path_segments;
    j["warnings"] = warnings;
    fmt::print("{}\n", j.dump(2));
    return;
  }
  fmt::print("{} {}\n", builtin ? "built-in scene" : "scene", path);
  fmt::print("  geometry     {} triangles ({} vertices), {} spheres\n", scene.triangles.size(), scene.positions.size(), scene.spheres.size());
  if (moving_vertices > 0) fmt::print("  motion blur  {} vertices move while the shutter is open\n", moving_vertices);
  const size_t moving_lights = size_t(std::count_if(scene.lights.begin(), scene.lights.end(), [](const Light& l) { return l.moves; }));
  if (moving_lights > 0) fmt::print("  motion blur  {} point-like lights move while the shutter is open\n", moving_lights);
  if (scene.camera_moves)
    fmt::print("  motion blur  the camera moves {:.4g} and turns {:.1f} degrees while the shutter is open\n",
               length(scene.camera_end.position - c.position),
               std::acos(std::clamp(dot(c.forward, scene.camera_end.forward), -1.f, 1.f)) * 180.0 / M_PI);
  fmt::print("  textures     {} ({} texels){}; {:.1f} MiB in memory\n", scene.textures.size(), texels,
             scene.environment_image.empty()
                 ? std::string()
                 : fmt::format("; environment image {}x{}", scene.environment_image.width, scene.environment_image.height),
             double(texture_bytes) / 1048576.0);
  fmt::print("  lights       {}\n", scene.lights.size());
  for (const auto& [kind, n] : lights) fmt::print("    {:<26} {}\n", kind, n);
  fmt::print("  materials    {}\n", scene.materials.size());
  for (const auto& [kind, n] : materials) fmt::print("    {:<26} {}\n", kind, n);
  if (!scene.media.empty())
    fmt::print("  media        {} homogeneous, {} grid{}\n", homogeneous_media, grid_media,
               scene.media.camera_medium != kVacuum ? "; the camera is in a medium" : "");
  fmt::print("  camera       {}x{}{}, pixel filter {}\n", c.width, c.height,
             c.is_pinhole() ? "" : fmt::format(", thin lens radius {:g}", c.lens_radius), describe_pixel_filter(c.filter));
  fmt::print("  path length  at most {} segments{}\n", scene.max_path_segments,
             settings.spp > 0 ? fmt::format("; the file suggests {} spp", settings.spp) : std::string());
  fmt::print("  approximated or ignored ({} warning{}):\n", warnings.size(), warnings.size() == 1 ? "" : "s");
  for (const std::string& w : warnings) fmt::print("    {}\n", printable(w));
}

}  // namespace

void print_scene_summary(const std::string& path, bool json) {
  std::vector<std::string> warnings;
  SceneFileSettings settings;
  Scene scene;
  try {
    scene = load_scene(path, SceneLoadOptions{}, &warnings, &settings);
    validate_scene(scene, &warnings);
  } catch (const Error&) {
    for (const std::string& w : warnings) fmt::print(stderr, "{}\n", printable(w));
    throw;
  }
  print_summary(path, false, scene, settings, warnings, json);
}

void print_builtin_scene_summary(const BuiltinSceneInfo& info, bool json) {
  std::vector<std::string> warnings;
  Scene scene = make_builtin_scene(info.name);
  validate_scene(scene, &warnings);
  print_summary(info.name, true, scene, SceneFileSettings{}, warnings, json);
}

}  // namespace pathspace::cli
