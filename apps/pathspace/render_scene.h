// The scene of `pathspace render`: a built-in scene or a scene file, with the command line's camera,
// lens and light-selection options applied and validated (shared by still renders and --frames).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "pathspace/base/input_file_log.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/scene/scene.h"
#include "distinct_files.h"
#include "number_options.h"
#include "render_command.h"

namespace pathspace::cli {

// A scene, loaded or built, with what the render needs to know about it.
struct PreparedScene {
  Scene scene;
  std::string label;         // the built-in's name or the file's path
  std::string display_name;  // the built-in's name or the file's stem
  std::string id;            // the built-in's id or the file's path (progress line)
  std::string key;           // "builtin:NAME" or the content hash of every file read (checkpoints)
  std::string file;          // the scene file, or empty
  std::vector<InputFile> input_files;  // every file the scene read, the scene file first
  SceneLoadOptions load_options;  // what the file was loaded with (the command line's camera and -r)
  int file_spp = 0;          // the file's samples per pixel, 0: none
  std::vector<std::string> validation_warnings;  // printed by prepare_scene
};

// "x,y,z" of --camera-pos and its kind; nullopt for an empty text.
std::optional<Vec3> parse_vec3(const std::string& text, const char* option);
void print_warnings(const std::vector<std::string>& warnings);
// Loads or builds the scene of `o` and applies its options (below); validation warnings are printed.
PreparedScene prepare_scene(const RenderOptions& o);
// The files the scene read, as inputs no output may replace (distinct_files.h): the scene file and
// what it named (Includes, meshes, material libraries, textures, environment maps).
std::vector<NamedFile> scene_inputs(const PreparedScene& prepared);
// The lens and light-selection options of `o`, then finalize() (every frame of an animation gets them).
void apply_scene_options(const RenderOptions& o, Scene* scene);

}  // namespace pathspace::cli
