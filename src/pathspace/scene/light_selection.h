// Which light next event estimation samples at a shading point, and with what probability: the
// light tree (lights/light_tree_view.h) when the scene's selection is bvh, else the scene's
// discrete distribution (uniform or by power), which ignores the point. Light paths always start
// from the discrete distribution (SceneView::light_selection).
#pragma once

#include "pathspace/scene/scene_view.h"

namespace pathspace {

// A light for the point p with shading normal n (zero vector: none), or LightTreeView::kNone when
// no light can reach p; writes its probability.
PS_INLINE uint32_t select_light_at(const SceneView& scene, const Vec3& p, const Vec3& n, float u, float* prob) {
  if (scene.light_tree.active) return scene.light_tree.sample(p, n, u, prob);
  return scene.light_selection.sample(u, prob);
}

// The probability that select_light_at(p, n) picks `light` (for MIS of emission found by BSDF rays).
PS_INLINE float light_selection_probability_at(const SceneView& scene, const Vec3& p, const Vec3& n, uint32_t light) {
  if (scene.light_tree.active) return scene.light_tree.probability(p, n, light);
  return scene.light_selection.probability(light);
}

}  // namespace pathspace
