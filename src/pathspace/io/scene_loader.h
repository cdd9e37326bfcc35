// Scene files: `load_scene` picks the parser by extension (.pbrt, .xml for Mitsuba, .gltf/.glb, .ply,
// .obj, each optionally .gz) and returns a finalised Scene. Unsupported or approximated features become warnings
// with file:line (collected in *warnings for the CLI to print); malformed input is a pathspace::Error.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pathspace/scene/scene.h"

namespace pathspace {

struct SceneLoadOptions {
  int width = 0, height = 0;  // > 0: replaces the file's resolution (pbrt Film); else the file's or 512x512
  // Camera override (all formats); without it pbrt files use their Camera, OBJ/PLY frame the bounds.
  std::optional<Vec3> camera_position, camera_target, camera_up;
  std::optional<float> fov_degrees;  // field of view of the shorter image axis (pbrt's convention)
  // pbrt: a missing image texture becomes a constant mid grey (0.5) and a missing environment map a
  // constant white environment (radiance 1 times the light's scale), each with a warning. Off: every
  // missing file is listed in one Error.
  bool substitute_missing_textures = false;
  // Mitsuba: scene parameters given from outside (`render -D NAME=VALUE`), used for `$NAME` before
  // the file's <default>; other formats ignore them with a warning.
  std::vector<std::pair<std::string, std::string>> defines;
  // glTF: the animation to play, by index ("2") or name; empty: the first (`render --animation`).
  // Other formats ignore it with a warning.
  std::string animation;
};

// What a scene file suggests for the render besides the scene itself.
struct SceneFileSettings {
  int spp = 0;             // pbrt Sampler "pixelsamples"; 0: none given
  std::string image_name;  // pbrt Film "filename"; empty: none given
};

// A scene parameter's name (Mitsuba's $name and <default name>, `render -D NAME=VALUE`): letters,
// digits and '_'.
bool is_scene_parameter_name(const std::string& name);

// True when the path has an extension load_scene understands.
bool is_scene_file(const std::string& path);

// Whether a scene given by name (the CLI's positional scene, Python's Scene.load) names a file rather
// than a built-in scene: it has a scene-file extension, or names an existing file that is not also a
// built-in scene's name.
bool names_scene_file(const std::string& name);

Scene load_scene(const std::string& path, const SceneLoadOptions& options, std::vector<std::string>* warnings,
                 SceneFileSettings* settings = nullptr);

// The finalised scene of an animated file at any time in seconds (glTF node animations,
// docs/animation.md); at 0 s it is load_scene's. An empty function for a file that stands still
// (other formats, glTF files without node animation).
std::function<Scene(double seconds)> load_scene_animation(const std::string& path, const SceneLoadOptions& options,
                                                          std::vector<std::string>* warnings);

// A camera looking from `position` along `forward`, raster right = `right`, up = `up` (unit vectors
// not required to form a right-handed frame: pbrt cameras are left-handed), with `fov_degrees`
// spanning the shorter image axis.
PerspectiveCamera make_file_camera(const Vec3& position, const Vec3& forward, const Vec3& right, const Vec3& up,
                               float fov_degrees, int width, int height);

// Applies the camera options of `o` (position/target/up/fov), or frames the scene's bounds when
// `frame_bounds` and no position is given: looking along -z at the centre of the bounding sphere.
// The camera's thin lens (radius, focus distance) is kept.
void apply_camera_options(const SceneLoadOptions& o, bool frame_bounds, int width, int height, Scene* scene);

}  // namespace pathspace
