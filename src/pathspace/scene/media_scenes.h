// Built-in scenes with participating media (docs/media.md), listed with the Cornell variants in
// builtin_scenes.h: the Cornell box filled with chromatic, forward-scattering fog (about one mean
// free path across), the scene of the media tests and the filtering figures.
#pragma once

#include "pathspace/math/bbox.h"
#include "pathspace/scene/scene.h"

namespace pathspace {

// Six quads of MaterialType::interface around `box` (normals outwards): inside them `medium`,
// outside vacuum.
void add_medium_box(Scene* scene, const Bounds3& box, uint32_t medium);

// SmallVCM's Cornell box with its ceiling light, filled with homogeneous fog bounded just outside
// its walls (so the light box lies wholly in it); the camera, in front of the open box, is outside.
Scene make_fog_box_scene(int width, int height);

}  // namespace pathspace
