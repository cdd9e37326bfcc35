// What moves in the scene of `render --frames` and `view` (docs/animation.md): an animated built-in
// moves its lights and objects, a glTF file its animated nodes; other scenes stand still.
#pragma once

#include <functional>

#include "pathspace/scene/scene.h"
#include "render_scene.h"

namespace pathspace::cli {

// The finalised scene `seconds` into its animation, with the command line's scene options applied
// (apply_scene_options), or an empty function for a scene that does not move. `o` and `prepared`
// must outlive it.
std::function<Scene(double seconds)> scene_animation(const RenderOptions& o, const PreparedScene& prepared);

}  // namespace pathspace::cli
