// The steps of a path through participating media shared by the integrators (docs/media.md): the
// next vertex along a ray (crossing surfaces that only bound media, sampling distances in media),
// and a shadow ray's visibility as a factor (the transmittance with media, 0 or 1 without).
#pragma once

#include "pathspace/integrators/common/transmittance_along.h"

namespace pathspace {

// Whether the shadow ray is unoccluded, as a factor: with media, the transmittance along it
// (integrators/common/transmittance_along.h); without, 0 or 1 from one occlusion test.
template <typename Tracer>
PS_HD Rgb shadow_visibility(const SceneView& scene, const Tracer& tracer, const Ray& shadow, int32_t medium, Pcg32* rng,
                            PathCounters* counters) {
  if (!scene.media.any()) return Rgb(tracer.occluded(shadow) ? 0.f : 1.f);
  return transmittance_along(scene, tracer, shadow, medium, *rng, counters);
}

// Where a subpath goes next in a scene with media.
enum class NextVertex : uint8_t { missed, surface, medium, absorbed };

// The next vertex along `ray` in medium *medium: crosses surfaces that only bound media and samples
// the distance in media (media/free_flight.h), multiplying *beta by the flight's weight. A medium
// vertex lies at distance *t_medium along the (possibly advanced) *ray, a surface vertex at *hit.
template <typename Tracer>
PS_HD NextVertex next_vertex(const SceneView& scene, const Tracer& tracer, Ray* ray, int32_t* medium, Pcg32* rng,
                             PathCounters* counters, Rgb* beta, SurfaceHit* hit, float* t_medium) {
  for (;;) {
    const bool found = tracer.intersect(*ray, hit);
    if (*medium != kVacuum) {
      const FreeFlight f = sample_free_flight(scene.media, *medium, *ray, found ? hit->t : kInfinity, *beta, *rng);
      *beta *= f.weight;
      if (f.event == MediumEvent::absorbed) return NextVertex::absorbed;
      if (f.event == MediumEvent::scattered) {
        *t_medium = f.t;
        return NextVertex::medium;
      }
    }
    if (!found) return NextVertex::missed;
    if (scene.materials[hit->material].type != MaterialType::interface) return NextVertex::surface;
    *medium = scene.media.after(*hit, ray->d, *medium);
    *ray = spawn_ray(hit->p, hit->ng, ray->d, scene.ray_epsilon, ray->time);
    ++counters->rays;
  }
}

}  // namespace pathspace
