// `pathspace info SCENE_FILE` (or a built-in scene's name): what a scene holds, as pathspace reads it: counts of geometry,
// lights and materials by kind, the camera, and every warning of the loader (what it approximated
// or ignored, each with its file:line:column) and of scene validation, as text or --json.
#pragma once

#include <string>

#include "pathspace/scene/builtin_scenes.h"

namespace pathspace::cli {

// Loads the file as `render` would (without command-line changes) and prints its summary. A scene
// that fails to load or validate throws, after printing the warnings gathered before the error.
void print_scene_summary(const std::string& path, bool json);
// The same for a built-in scene at its default resolution (`pathspace info cornell-box`).
void print_builtin_scene_summary(const BuiltinSceneInfo& info, bool json);

}  // namespace pathspace::cli
