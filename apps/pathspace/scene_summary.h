// `pathspace info SCENE_FILE`: what a scene file holds, as pathspace reads it: counts of geometry,
// lights and materials by kind, the camera, and every warning of the loader (what it approximated
// or ignored, each with its file:line:column) and of scene validation, as text or --json.
#pragma once

#include <string>

namespace pathspace::cli {

// Loads the file as `render` would (without command-line changes) and prints its summary. A scene
// that fails to load or validate throws, after printing the warnings gathered before the error.
void print_scene_summary(const std::string& path, bool json);

}  // namespace pathspace::cli
