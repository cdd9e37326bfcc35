// Built-in scenes made to test path space filters (Keller, Dahm, Binder 2014), listed with the
// Cornell variants in builtin_scenes.h as "filter-leak" and "filter-fence".
#pragma once

#include "pathspace/scene/scene.h"

namespace pathspace {

inline constexpr float kWallHalfThickness = 0.005f;
inline constexpr float kFenceBarWidth = 0.025f;

// An open room split at x = 0 by a wall 2 * kWallHalfThickness thick, a point light in the left
// half: every path that reaches the right half's floor or walls carries exactly zero radiance, so
// whatever a filter puts there has leaked through the wall (fig. 4's weights, as numbers).
Scene make_wall_leak_scene(int width, int height);
// An open room lit by a ceiling light, with thin vertical bars half-way to the back wall (fig. 7).
Scene make_fence_scene(int width, int height);

}  // namespace pathspace
