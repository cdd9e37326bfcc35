// One light-traced path (device-safe, templated on the ray caster "Tracer" like pt_trace_path):
// emit from a light (scene/light_emission.h), scatter with the adjoint BSDF (TransportMode::
// importance) and connect every vertex to the camera by projection (PCLT paper eq. 4; through a
// sampled lens point for a thin lens, PerspectiveCamera::project),
// splatting into a SplatFilmView through the camera's pixel filter (camera/pixel_filter.h; the
// reconstruction kernels of PCLT sec. 5.2). Shading normals use Veach's adjoint correction (Veach 1997 §5.3, eq. 5.17):
// a light-path vertex scales by |wo.ns| |wi.ng| / (|wo.ng| |wi.ns|) on top of f |wi.ns|.
#pragma once

#include "pathspace/integrators/common/light_path_step.h"

#include "pathspace/film/splat_film.h"
#include "pathspace/integrators/common/camera_sample.h"
#include "pathspace/integrators/common/light_dimensions.h"
#include "pathspace/integrators/common/light_path_start.h"
#include "pathspace/integrators/common/media_steps.h"
#include "pathspace/media/henyey_greenstein.h"
#include "pathspace/stats/path_counters.h"
#include "pathspace/integrators/lt/lt_settings.h"
#include "pathspace/scene/light_emission.h"
#include "pathspace/materials/bsdf.h"
#include "pathspace/sampling/sampler.h"
#include "pathspace/scene/shading_material.h"

namespace pathspace {

namespace lt_detail {

// A point projected onto the image plane (PerspectiveCamera::project): unlike connect, the raster
// position is not clipped to the image, so a wide filter lets points just outside reach border pixels.
using Projection = CameraProjection;

// Distributes value (already divided by the path count; box-filter units) over the pixels whose
// pixel filter support contains (rx, ry) (camera/pixel_filter.h: the same filter camera paths sample).
PS_INLINE void splat(const SplatFilmView& film, const PixelFilter& filter, float rx, float ry, const Rgb& value) {
  for_each_filter_pixel(filter, film.width, film.height, rx, ry, [&](uint32_t pixel, float w) {
    film.add(pixel, w == 1.f ? value : value * w);
  });
}

// Whether any pixel can receive a splat at (rx, ry): saves the shadow ray for points far outside.
PS_INLINE bool reaches_image(const SplatFilmView& film, const PixelFilter& filter, float rx, float ry) {
  return filter_reaches_image(filter, film.width, film.height, rx, ry);
}

}  // namespace lt_detail

namespace lt_detail {
// A light path's vertex in a medium at distance t along `ray`: its camera connection (phase function
// times the transmittance to the camera; no cosine), then a direction from the phase function and
// Russian roulette as at surfaces. False when the path ends.
template <typename Tracer>
PS_HD bool lt_medium_vertex(const SceneView& scene, const Tracer& tracer, const Sampler& sampler, const LtSettings& settings,
                            const PerspectiveCamera& cam, const SplatFilmView& film, const Ray& ray, float t, int32_t medium,
                            int segments, int max_segments, float beta0, float inv_paths, Pcg32& rng, PathCounters* counters,
                            Rgb* beta, Ray* next) {
  const Vec3 p = ray.at(t);
  const float g = scene.media.media[medium].g;
  const uint32_t v = uint32_t(segments - 1);
  Projection pr;
  if (cam.project(p, connection_lens_sample(cam, sampler, v + 1), &pr) && reaches_image(film, cam.filter, pr.rx, pr.ry)) {
    ++counters->rays;
    ++counters->shadow_rays;
    const Rgb tr = transmittance_along(scene, tracer, spawn_shadow_ray(p, Vec3(0.f), pr.wi, pr.dist, scene.ray_epsilon, ray.time),
                                       medium, rng, counters);
    if (!is_black(tr)) splat(film, cam.filter, pr.rx, pr.ry, *beta * tr * (hg_phase(dot(ray.d, pr.wi), g) * pr.factor * inv_paths));
  }
  if (segments + 1 >= max_segments) return false;
  const Point2 u{sampler.at(light_dims::vertex(v, light_dims::kBsdfU)), sampler.at(light_dims::vertex(v, light_dims::kBsdfU + 1))};
  const Vec3 wi = hg_sample(ray.d, g, u);
  if (settings.roulette_start >= 0 && segments >= settings.roulette_start) {
    const float q = fminf(1.f, max_component(*beta) / beta0);
    if (sampler.at(light_dims::vertex(v, light_dims::kRoulette)) >= q) return false;
    *beta *= 1.f / q;
  }
  *next = Ray{p, wi, 0.f, kInfinity, ray.time};
  return true;
}
}  // namespace lt_detail

// Traces one light path and splats all its camera connections; inv_paths = 1 / (light paths per
// pass), which turns the sum of splats into the pass's pixel estimate.
template <typename Tracer>
PS_HD void lt_trace_path(const SceneView& scene, const Tracer& tracer, const Sampler& sampler, const LtSettings& settings,
                         float inv_paths, const SplatFilmView& film, PathCounters* counters) {
  using namespace lt_detail;
  if (scene.num_lights == 0) return;
  const int max_segments = settings.max_segments > 0 ? settings.max_segments : scene.max_path_segments;
  const float time = light_path_time(scene, sampler);
  const PerspectiveCamera cam = camera_at(scene, time);  // the path's connections see the camera of its instant

  LightPathStart start;
  if (!start_light_path(scene, sampler, time, &start)) return;
  const Light& light = *start.light;
  const EmissionSample& e = start.emission;
  const float inv_select = 1.f / start.select_prob;
  // Media (docs/media.md): the medium the path travels in and its stream of numbers.
  const bool media = scene.media.any();
  Pcg32 rng;
  if (media) rng = Pcg32(sampler.bits(light_dims::kMediumStream), 0u);

  // Path length 1: the emitter seen by the camera. Only area lights have a visible surface; point,
  // directional and environment lights are never hit by camera rays either (PT agrees).
  if (!settings.skip_emitter && is_area_light(light)) {
    Projection pr;
    if (cam.project(e.p, connection_lens_sample(cam, sampler, 0), &pr) && reaches_image(film, cam.filter, pr.rx, pr.ry)) {
      const Rgb le = area_light_radiance(scene, light, e.ng, pr.wi, e.uv);
      if (!is_black(le)) {
        ++counters->rays;
        ++counters->shadow_rays;
        prefetch_filter_splat(film, cam.filter, pr.rx, pr.ry);
        const Rgb tr = shadow_visibility(scene, tracer, spawn_shadow_ray(e.p, e.ng, pr.wi, pr.dist, scene.ray_epsilon, e.time),
                                         media ? light_path_medium(scene, start, pr.wi) : kVacuum, &rng, counters);
        if (!is_black(tr)) {
          const float scale = fabsf(dot(e.ng, pr.wi)) / e.pdf_a * inv_select * pr.factor * inv_paths;
          splat(film, cam.filter, pr.rx, pr.ry, le * tr * scale);
        }
      }
    }
  }
  if (max_segments < 2) return;

  Rgb beta = e.weight * inv_select;
  const float beta0 = max_component(beta);  // Russian roulette looks at the throughput relative to this
  Ray ray = first_light_ray(scene, e);
  int32_t medium = media ? light_path_medium(scene, start, e.d) : kVacuum;

  // The vertex reached after `segments` segments; its camera connection makes segments + 1.
  for (int segments = 1; segments < max_segments; ++segments) {
    SurfaceHit hit;
    ++counters->rays;
    float t_medium = 0.f;
    NextVertex next = NextVertex::surface;
    if (media) {
      next = next_vertex(scene, tracer, &ray, &medium, &rng, counters, &beta, &hit, &t_medium);
    } else if (!tracer.intersect(ray, &hit)) {
      next = NextVertex::missed;
    }
    if (next == NextVertex::missed || next == NextVertex::absorbed) break;
    if (next == NextVertex::medium) {
      if (!lt_medium_vertex(scene, tracer, sampler, settings, cam, film, ray, t_medium, medium, segments, max_segments, beta0,
                            inv_paths, rng, counters, &beta, &ray))
        break;
      continue;
    }
    Material textured;
    const Material& mat = shading_material(scene, hit, &textured);
    const Frame frame(hit.ns);
    const Vec3 wo_world = -ray.d;  // towards the light side (the previous vertex)
    const Vec3 wo = frame.to_local(wo_world);
    const float wo_ng = fabsf(dot(wo_world, hit.ng));
    if (!(wo_ng > 0.f)) break;
    const uint32_t v = uint32_t(segments - 1);

    // Camera connection: beta f(wo, wi) |wo.ns| |wi.ng| / |wo.ng| We cos_cam / d^2, the adjoint
    // shading-normal factor times |wi.ns| (Veach eq. 5.17).
    if (bsdf_has_non_delta(mat)) {
      Projection pr;
      if (cam.project(hit.p, connection_lens_sample(cam, sampler, v + 1), &pr) && reaches_image(film, cam.filter, pr.rx, pr.ry)) {
        const Vec3 wi = frame.to_local(pr.wi);
        const Rgb f = bsdf_eval(mat, wo, wi, TransportMode::importance);
        if (!is_black(f)) {
          ++counters->rays;
          ++counters->shadow_rays;
          prefetch_filter_splat(film, cam.filter, pr.rx, pr.ry);
          const Rgb tr = shadow_visibility(scene, tracer, spawn_shadow_ray(hit.p, hit.ng, pr.wi, pr.dist, scene.ray_epsilon, hit.time),
                                           scene.media.after(hit, pr.wi, medium), &rng, counters);
          if (!is_black(tr)) {
            const float cosines = fabsf(wo.z) * fabsf(dot(pr.wi, hit.ng)) / wo_ng;
            splat(film, cam.filter, pr.rx, pr.ry, beta * f * tr * (cosines * pr.factor * inv_paths));
          }
        }
      }
    }
    if (segments + 1 >= max_segments) break;  // a further vertex could not connect within the limit

    if (!continue_light_path(sampler, v, mat, frame, hit, wo, wo_ng, segments, settings.roulette_start, beta0,
                             scene.ray_epsilon, &beta, &ray))
      break;
    medium = scene.media.after(hit, ray.d, medium);
  }
}

}  // namespace pathspace
