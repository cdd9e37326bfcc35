// One path-traced camera path (device-safe, templated on the ray caster "Tracer" with
// intersect(Ray, SurfaceHit*) and occluded(Ray)). Unidirectional estimator with next event estimation
// and MIS (Veach 1997 §9.2); either technique can be switched off for tests:
//   nee && bsdf_sampling : MIS of light sampling and BSDF sampling (default)
//   nee only             : emission reached by BSDF rays is ignored except after delta bounces
//   bsdf_sampling only   : no light sampling; emission found by BSDF rays counts with weight 1
#pragma once

#include "pathspace/integrators/common/dimensions.h"
#include "pathspace/integrators/common/path_counters.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/lights/light_sampling.h"
#include "pathspace/materials/bsdf.h"
#include "pathspace/sampling/sampler.h"

namespace pathspace {

namespace pt_detail {
PS_INLINE float combine_mis(const PtSettings& s, float pdf_this, float pdf_other) {
  if (!(s.nee && s.bsdf_sampling)) return 1.f;
  return mis_weight(s.mis, pdf_this, pdf_other);
}
}  // namespace pt_detail

template <typename Tracer>
PS_HD Rgb pt_trace_path(const SceneView& scene, const Tracer& tracer, const Sampler& sampler, Ray ray,
                        const PtSettings& settings, PathCounters* counters) {
  const int max_segments = settings.max_segments > 0 ? settings.max_segments : scene.max_path_segments;
  Rgb radiance, beta(1.f);
  bool after_delta = true;  // the camera "bounce" counts as delta: directly seen emission always counts
  float prev_bsdf_pdf = 0.f;
  Vec3 prev_p = ray.o;

  for (int segments = 1;; ++segments) {
    SurfaceHit hit;
    ++counters->rays;
    if (!tracer.intersect(ray, &hit)) {
      if (scene.environment_light >= 0) {
        const Light& env = scene.lights[scene.environment_light];
        if (after_delta || !settings.nee) {
          radiance += beta * env.value;
        } else if (settings.bsdf_sampling) {
          const float light_pdf_w = scene.light_selection.probability(uint32_t(scene.environment_light)) * uniform_sphere_pdf();
          radiance += beta * env.value * pt_detail::combine_mis(settings, prev_bsdf_pdf, light_pdf_w);
        }
      }
      break;
    }

    if (hit.light != kNoLight) {
      const Light& light = scene.lights[hit.light];
      const Rgb le = area_light_radiance(light, hit.ng, -ray.d);
      if (!is_black(le)) {
        if (after_delta || !settings.nee) {
          radiance += beta * le;
        } else if (settings.bsdf_sampling) {
          const float light_pdf_w =
              scene.light_selection.probability(uint32_t(hit.light)) * light_pdf(scene, light, prev_p, hit.p, hit.ng);
          radiance += beta * le * pt_detail::combine_mis(settings, prev_bsdf_pdf, light_pdf_w);
        }
      }
    }
    if (segments >= max_segments) break;

    const Material& mat = scene.materials[hit.material];
    const Frame frame(hit.ns);
    const Vec3 wo = frame.to_local(-ray.d);
    const uint32_t v = uint32_t(segments - 1);

    // Next event estimation: one light, one point on it.
    if (settings.nee && scene.num_lights > 0 && bsdf_has_non_delta(mat)) {
      float select_prob;
      const uint32_t li = scene.light_selection.sample(sampler.at(dims::vertex(v, dims::kLightSelect)), &select_prob);
      const Light& light = scene.lights[li];
      LightSample ls;
      const Point2 ul{sampler.at(dims::vertex(v, dims::kLightU)), sampler.at(dims::vertex(v, dims::kLightU + 1))};
      if (sample_light(scene, light, hit.p, ul, &ls)) {
        const Vec3 wi = frame.to_local(ls.wi);
        const Rgb f = bsdf_eval(mat, wo, wi, TransportMode::radiance);
        if (!is_black(f)) {
          const Ray shadow = spawn_shadow_ray(hit.p, hit.ng, ls.wi, ls.dist, scene.ray_epsilon);
          ++counters->rays;
          ++counters->shadow_rays;
          if (!tracer.occluded(shadow)) {
            const float pdf_light = select_prob * ls.pdf_w;
            const float w = ls.delta ? 1.f : pt_detail::combine_mis(settings, pdf_light, bsdf_pdf(mat, wo, wi, TransportMode::radiance));
            radiance += beta * f * ls.li * (fabsf(wi.z) * w / pdf_light);
          }
        }
      }
    }

    // Continue by BSDF sampling.
    BsdfSample bs;
    const Point2 ub{sampler.at(dims::vertex(v, dims::kBsdfU)), sampler.at(dims::vertex(v, dims::kBsdfU + 1))};
    if (!bsdf_sample(mat, wo, sampler.at(dims::vertex(v, dims::kLobe)), ub, TransportMode::radiance, &bs)) break;
    beta *= bs.weight;
    if (is_black(beta)) break;
    after_delta = bs.delta;
    prev_bsdf_pdf = bs.pdf_w;
    prev_p = hit.p;

    if (settings.roulette_start >= 0 && segments >= settings.roulette_start) {
      const float q = fminf(1.f, max_component(beta));
      if (sampler.at(dims::vertex(v, dims::kRoulette)) >= q) break;
      beta *= 1.f / q;
    }
    ray = spawn_ray(hit.p, hit.ng, frame.to_world(bs.wi), scene.ray_epsilon);
  }
  return radiance;
}

}  // namespace pathspace
