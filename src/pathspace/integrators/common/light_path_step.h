// One scattering step of a light (importance) path, shared by light tracing and pixel cache light
// tracing: sample the adjoint BSDF (TransportMode::importance), apply Veach's shading-normal
// correction (thesis sec. 5.3: f |wo.ns| |wi.ng| / (|wo.ng| |wi.ns|)) and Russian roulette relative to
// the emitted throughput, and spawn the next ray. Returns false when the path ends.
#pragma once

#include "pathspace/geometry/interaction.h"
#include "pathspace/geometry/ray.h"
#include "pathspace/integrators/common/light_dimensions.h"
#include "pathspace/materials/bsdf.h"
#include "pathspace/sampling/sampler.h"

namespace pathspace {

PS_INLINE bool continue_light_path(const Sampler& sampler, uint32_t vertex, const Material& mat, const Frame& frame,
                                   const SurfaceHit& hit, const Vec3& wo_local, float wo_ng, int segments,
                                   int roulette_start, float beta0, float ray_epsilon, Rgb* beta, Ray* ray) {
  BsdfSample bs;
  const Point2 ub{sampler.at(light_dims::vertex(vertex, light_dims::kBsdfU)),
                  sampler.at(light_dims::vertex(vertex, light_dims::kBsdfU + 1))};
  if (!bsdf_sample(mat, wo_local, sampler.at(light_dims::vertex(vertex, light_dims::kLobe)), ub, TransportMode::importance, &bs))
    return false;
  const Vec3 wi_world = frame.to_world(bs.wi);
  const float wi_ns = fabsf(bs.wi.z);
  if (!(wi_ns > 0.f)) return false;
  // bs.weight = f |wi.ns| / pdf; the adjoint correction turns it into f |wo.ns| |wi.ng| / (|wo.ng| pdf).
  *beta *= bs.weight * (fabsf(wo_local.z) * fabsf(dot(wi_world, hit.ng)) / (wo_ng * wi_ns));
  if (is_black(*beta) || !all_finite(*beta)) return false;
  if (roulette_start >= 0 && segments >= roulette_start) {
    const float q = fminf(1.f, max_component(*beta) / beta0);
    if (sampler.at(light_dims::vertex(vertex, light_dims::kRoulette)) >= q) return false;
    *beta *= 1.f / q;
  }
  *ray = spawn_ray(hit.p, hit.ng, wi_world, ray_epsilon, hit.time);
  return true;
}

}  // namespace pathspace
