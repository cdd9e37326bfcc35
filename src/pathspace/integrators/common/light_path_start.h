// The start of every light path (LT, BPT light subpaths, SPPM photons, PCLT): a light picked by the
// scene's light selection (light_dims::kLightSelect) and an emission sampled from it (kEmitPos,
// kEmitDir), so that all four integrators draw their light paths from the same random numbers, and
// the ray that leaves the light.
#pragma once

#include "pathspace/geometry/ray.h"
#include "pathspace/integrators/common/light_dimensions.h"
#include "pathspace/scene/light_emission.h"
#include "pathspace/scene/motion.h"
#include "pathspace/sampling/sampler.h"
#include "pathspace/scene/scene_view.h"

namespace pathspace {

struct LightPathStart {
  const Light* light = nullptr;
  float select_prob = 0.f;  // probability of having picked `light`
  EmissionSample emission;
};

// False when the scene has no light or the sampled emission carries nothing. `time`: the path's
// (scene/motion.h; light_path_time for a light path of its own).
PS_INLINE bool start_light_path(const SceneView& scene, const Sampler& sampler, float time, LightPathStart* s) {
  if (scene.num_lights == 0) return false;
  const uint32_t li = scene.light_selection.sample(sampler.at(light_dims::kLightSelect), &s->select_prob);
  if (!(s->select_prob > 0.f)) return false;
  s->light = &scene.lights[li];
  const Point2 up{sampler.at(light_dims::kEmitPos), sampler.at(light_dims::kEmitPos + 1)};
  const Point2 ud{sampler.at(light_dims::kEmitDir), sampler.at(light_dims::kEmitDir + 1)};
  return sample_emission(scene, *s->light, time, up, ud, &s->emission);
}

// The medium a light path leaves its light into along d (docs/media.md): the emitting shape's side
// where the shape bounds media, else the light's own medium (MediaView::light_media).
PS_INLINE int32_t light_path_medium(const SceneView& scene, const LightPathStart& start, const Vec3& d) {
  const uint32_t index = uint32_t(start.light - scene.lights);
  const int32_t own = scene.media.light_medium(index);
  const Light& l = *start.light;
  if (l.type != LightType::area_triangle && l.type != LightType::area_sphere) return own;
  SurfaceHit at;
  at.kind = l.type == LightType::area_triangle ? ShapeKind::triangle : ShapeKind::sphere;
  at.prim = l.shape;
  at.ng = start.emission.ng;
  return scene.media.after(at, d, own);
}

// The time of a light path that no camera path shares (LT; scene/motion.h).
PS_INLINE float light_path_time(const SceneView& scene, const Sampler& sampler) {
  return sample_time(scene, sampler, light_dims::kTime);
}

// The first ray of a light path: off the surface of an area light, from the point itself for point
// and spot lights, from the proxy disk of directional and environment lights.
PS_INLINE Ray first_light_ray(const SceneView& scene, const EmissionSample& e) {
  return e.delta_position || e.infinite ? Ray{e.p, e.d, 0.f, kInfinity, e.time}
                                        : spawn_ray(e.p, e.ng, e.d, scene.ray_epsilon, e.time);
}

}  // namespace pathspace
