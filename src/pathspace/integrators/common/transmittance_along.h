// The transmittance between two points of a scene with media (pbrt-v4's Integrator::Tr): the
// shadow ray passes surfaces whose material is an interface (MaterialType::interface: they only
// bound media) and multiplies the transmittance of each medium it crosses; any other surface
// blocks it. Templated on the ray caster like the kernels.
#pragma once

#include "pathspace/media/free_flight.h"
#include "pathspace/scene/scene_view.h"
#include "pathspace/stats/path_counters.h"

namespace pathspace {

// `shadow`: a shadow ray (geometry/ray.h, spawn_shadow_ray) starting in medium `medium`.
template <typename Tracer>
PS_HD Rgb transmittance_along(const SceneView& scene, const Tracer& tracer, Ray shadow, int32_t medium, Pcg32& rng,
                              PathCounters* counters) {
  constexpr int kMaxCrossings = 256;  // nested interfaces beyond this count as blocking
  Rgb tr(1.f);
  const bool finite = !isinf(shadow.tmax);
  const Vec3 target = finite ? shadow.at(shadow.tmax + scene.ray_epsilon) : Vec3();
  for (int crossing = 0; crossing < kMaxCrossings; ++crossing) {
    SurfaceHit hit;
    const bool found = tracer.intersect(shadow, &hit);
    if (medium != kVacuum) {
      tr *= medium_transmittance(scene.media, medium, shadow, found ? hit.t : shadow.tmax, rng);
      if (is_black(tr)) return tr;
    }
    if (!found) return tr;
    if (scene.materials[hit.material].type != MaterialType::interface) return Rgb();
    medium = scene.media.after(hit, shadow.d, medium);
    ++counters->rays;
    shadow = finite ? spawn_shadow_ray(hit.p, hit.ng, shadow.d, length(target - hit.p), scene.ray_epsilon, shadow.time)
                    : spawn_ray(hit.p, hit.ng, shadow.d, scene.ray_epsilon, shadow.time);
  }
  return Rgb();
}

}  // namespace pathspace
