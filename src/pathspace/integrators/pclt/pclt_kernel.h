// Pixel cache light tracing, per-path logic (device-safe, templated on the ray caster "Tracer" like
// lt_trace_path). Eye pass (PCLT sec. 3): one camera path per pixel continues through specular and
// glossy lobes until a Lambertian event is sampled; that vertex enters the pixel cache only if at
// least one non-diffuse bounce preceded it (ES+D; ED is left to projection). Light pass (sec. 3, 5):
// every light vertex gathers from cache entries within the global radius (eq. 1) and projects to
// the camera (eq. 4, filter kernels of sec. 5.2, visibility of sec. 5.3).
#pragma once

#include "pathspace/integrators/common/light_path_step.h"

#include "pathspace/hashgrid/hash_grid_view.h"
#include "pathspace/hashgrid/stochastic_hash_map_view.h"
#include "pathspace/integrators/common/dimensions.h"
#include "pathspace/integrators/common/light_dimensions.h"
#include "pathspace/integrators/common/light_path_start.h"
#include "pathspace/stats/path_counters.h"
#include "pathspace/integrators/lt/lt_kernel.h"
#include "pathspace/integrators/pclt/pclt_settings.h"
#include "pathspace/scene/light_sampling.h"
#include "pathspace/scene/shading_material.h"

namespace pathspace {

// One pixel cache record (sec. 4.1): position, eye-path throughput weight (the Lambertian albedo/pi
// and 1/P(diffuse lobe) folded in, so no BSDF or direction is stored) and pixel. Two additions to
// the paper's record: the octahedral-packed front normal (4 bytes), so light arriving from behind
// the surface is not gathered (the one-sided Lambertian f is zero there; SPPM tests the same), and
// the eye path's segment count, so joined paths respect the path length limit like LT and SPPM.
struct PixelCacheEntry {
  Vec3 p;
  Rgb weight;
  uint32_t pixel = 0;
  uint32_t normal = 0;    // oct_encode(front normal)
  uint32_t segments = 0;  // camera path length to p (camera ray = 1)
};

// What the eye pass leaves for one pixel.
struct PcltEyeResult {
  Rgb direct;                  // ES+L emission (settings.specular_emission)
  PixelCacheEntry entry;
  bool stored = false;         // entry is an ES+D record
  uint32_t nondiffuse_bounces = 0;  // specular/glossy bounces before the stored vertex
  bool first_event_diffuse = false; // the first vertex sampled its Lambertian lobe (ED: projection)
  // First hit of the jittered camera ray, for the z-buffer and plane visibility tests (sec. 5.3).
  bool has_first_hit = false;
  Vec3 first_p, first_n;       // first_n faces the camera
  float first_depth = kInfinity;  // view depth dot(p - camera, forward)
};

namespace pclt_detail {

// Octahedral normal encoding, 16 bits per coordinate (Cigolle et al. 2014): ~1e-4 rad error.
PS_INLINE uint32_t oct_encode(Vec3 n) {
  const float l1 = fabsf(n.x) + fabsf(n.y) + fabsf(n.z);
  float u = n.x / l1, v = n.y / l1;
  if (n.z < 0.f) {
    const float ou = (1.f - fabsf(v)) * (u >= 0.f ? 1.f : -1.f), ov = (1.f - fabsf(u)) * (v >= 0.f ? 1.f : -1.f);
    u = ou;
    v = ov;
  }
  auto q = [](float x) { return uint32_t(fminf(fmaxf((x * 0.5f + 0.5f) * 65535.f + 0.5f, 0.f), 65535.f)); };
  return q(u) | (q(v) << 16);
}
PS_INLINE Vec3 oct_decode(uint32_t e) {
  const float u = float(e & 0xffffu) / 65535.f * 2.f - 1.f, v = float(e >> 16) / 65535.f * 2.f - 1.f;
  Vec3 n(u, v, 1.f - fabsf(u) - fabsf(v));
  if (n.z < 0.f) {
    const float x = (1.f - fabsf(v)) * (u >= 0.f ? 1.f : -1.f), y = (1.f - fabsf(u)) * (v >= 0.f ? 1.f : -1.f);
    n.x = x;
    n.y = y;
  }
  return normalize(n);
}

// The eye path's scattering decision at one vertex. f = f_D + f_S with f_D the Lambertian lobe and
// f_S everything else (Phong, delta, microfacet): the Lambertian part is estimated by projection
// (first vertex) or by the pixel cache (later vertices), so a continuing path must carry f_S only.
// standard::sample's glossy weight is the one-sample mixture f_D + f_G over the mixture pdf, which
// would count f_D twice; the glossy weight is therefore recomputed for the glossy lobe alone.
enum class EyeEvent : uint8_t { absorbed, diffuse, scatter };
struct EyeScatter {
  EyeEvent event = EyeEvent::absorbed;
  Rgb weight;  // diffuse: albedo / (pi P(diffuse)); scatter: f_S |cos| / pdf
  Vec3 wi;     // scatter: local direction
};

PS_INLINE EyeScatter scatter_eye(const Material& m, const Vec3& wo, float u_lobe, Point2 u) {
  EyeScatter out;
  if (m.type == MaterialType::standard) {
    Vec3 wo_f = wo;
    detail::flip_for_two_sided(m, &wo_f, nullptr);
    const standard::LobeProbabilities p = standard::lobe_probabilities(m, wo_f);
    if (u_lobe < p.diffuse) {  // bsdf_sample would pick the same lobe with this u_lobe
      out.event = EyeEvent::diffuse;
      out.weight = m.diffuse * (kInvPi / p.diffuse);
      return out;
    }
    BsdfSample bs;
    if (!bsdf_sample(m, wo, u_lobe, u, TransportMode::radiance, &bs)) return out;
    out.wi = bs.wi;
    if (bs.lobe & kLobeGlossy) {
      // Phong alone: f_G |cos| / (P(glossy) pdf_G) = rho_p (n + 2) / (n + 1) cos_i / P(glossy).
      const float cos_i = fabsf(bs.wi.z);
      const float c = standard::phong_lobe_cosine(wo_f, wo_f.z == wo.z ? bs.wi : Vec3(bs.wi.x, bs.wi.y, -bs.wi.z));
      if (c <= standard::kMinPhongCosine || cos_i < kMinCosine) return out;
      out.weight = m.glossy * ((m.exponent + 2.f) / (m.exponent + 1.f) * cos_i / p.glossy);
    } else {
      out.weight = bs.weight;
    }
    out.event = EyeEvent::scatter;
    return out;
  }
  // Microfacet conductors and dielectrics have no Lambertian lobe: the whole BSDF is "specular".
  BsdfSample bs;
  if (!bsdf_sample(m, wo, u_lobe, u, TransportMode::radiance, &bs)) return out;
  out.event = EyeEvent::scatter;
  out.weight = bs.weight;
  out.wi = bs.wi;
  return out;
}

// The Lambertian part f_D that projection carries (importance transport; Lambert is symmetric).
PS_INLINE Rgb diffuse_eval(const Material& m, Vec3 wo, Vec3 wi) {
  if (m.type != MaterialType::standard || is_black(m.diffuse)) return {};
  detail::flip_for_two_sided(m, &wo, &wi);
  return standard::both_above(wo, wi) ? m.diffuse * kInvPi : Rgb();
}
PS_INLINE bool has_diffuse(const Material& m) { return m.type == MaterialType::standard && !is_black(m.diffuse); }

// E S+ L paths whose L is a delta light (point, directional): the continuing eye path can never hit
// such a light, and projection carries f_D only, so the glossy highlight of a point light or the sun
// would be missing (measured: -3.5% image mean on gbs_s's floor). With specular_emission, the
// non-Lambertian part f - f_D is connected to one light picked by the scene's light selection; a
// picked area or environment light contributes nothing here because hitting it finds those paths.
template <typename Tracer>
PS_HD Rgb delta_light_connection(const SceneView& scene, const Tracer& tracer, const Sampler& sampler, uint32_t v,
                                 const SurfaceHit& hit, const Frame& frame, const Material& m, const Vec3& wo,
                                 PathCounters* counters) {
  if (scene.num_lights == 0 || !bsdf_has_non_delta(m)) return {};
  float select_prob;
  const uint32_t li = scene.light_selection.sample(sampler.at(dims::vertex(v, dims::kLightSelect)), &select_prob);
  const Light& light = scene.lights[li];
  LightSample ls;
  const Point2 ul{sampler.at(dims::vertex(v, dims::kLightU)), sampler.at(dims::vertex(v, dims::kLightU + 1))};
  if (!is_delta_light(light) || !sample_light(scene, light, hit.p, hit.time, ul, &ls)) return {};
  const Vec3 wi = frame.to_local(ls.wi);
  const Rgb full = bsdf_eval(m, wo, wi, TransportMode::radiance), fd = diffuse_eval(m, wo, wi);
  const Rgb f(fmaxf(full.r - fd.r, 0.f), fmaxf(full.g - fd.g, 0.f), fmaxf(full.b - fd.b, 0.f));
  if (is_black(f)) return {};
  ++counters->rays;
  ++counters->shadow_rays;
  if (tracer.occluded(spawn_shadow_ray(hit.p, hit.ng, ls.wi, ls.dist, scene.ray_epsilon, hit.time))) return {};
  return f * ls.li * (fabsf(wi.z) / (select_prob * ls.pdf_w));
}

}  // namespace pclt_detail

// Eye pass of one pixel (sec. 3): at most one record, direct ES+L emission, and the first hit.
template <typename Tracer>
PS_HD void pclt_trace_eye(const SceneView& scene, const Tracer& tracer, const Sampler& sampler, Ray ray, uint32_t pixel,
                          const PcltSettings& settings, int max_segments, PathCounters* counters, PcltEyeResult* out) {
  using namespace pclt_detail;
  *out = PcltEyeResult{};
  Rgb beta(1.f);
  uint32_t bounces = 0;  // non-diffuse scattering events so far
  for (int segments = 1;; ++segments) {
    SurfaceHit hit;
    ++counters->rays;
    if (!tracer.intersect(ray, &hit)) {
      if (bounces > 0 && settings.specular_emission && scene.environment_light >= 0)
        out->direct += beta * environment_radiance(scene, scene.lights[scene.environment_light], ray.d);
      return;
    }
    const Vec3 n_front = dot(hit.ng, -ray.d) >= 0.f ? hit.ng : -hit.ng;
    if (segments == 1) {
      out->has_first_hit = true;
      out->first_p = hit.p;
      out->first_n = n_front;
      const PerspectiveCamera cam = camera_at(scene, ray.time);
      out->first_depth = dot(hit.p - cam.position, cam.forward);
    }
    // EL is the light tracer's emitter splat; emission behind >= 1 non-diffuse bounce is ES+L.
    if (hit.light != kNoLight && bounces > 0 && settings.specular_emission)
      out->direct += beta * area_light_radiance(scene, scene.lights[hit.light], hit.ng, -ray.d, hit.uv);
    if (segments >= max_segments) return;  // a light path needs at least one more segment

    Material textured;
    const Material& mat = shading_material(scene, hit, &textured);
    const Frame frame(hit.ns);
    const Vec3 wo = frame.to_local(-ray.d);
    const uint32_t v = uint32_t(segments - 1);
    const Point2 ub{sampler.at(dims::vertex(v, dims::kBsdfU)), sampler.at(dims::vertex(v, dims::kBsdfU + 1))};
    if (settings.specular_emission)
      out->direct += beta * delta_light_connection(scene, tracer, sampler, v, hit, frame, mat, wo, counters);
    const EyeScatter sc = scatter_eye(mat, wo, sampler.at(dims::vertex(v, dims::kLobe)), ub);
    if (sc.event == EyeEvent::absorbed) return;
    if (sc.event == EyeEvent::diffuse) {
      if (bounces == 0) {  // ED: the Lambertian lobe of a directly seen vertex is projection's
        out->first_event_diffuse = true;
        return;
      }
      out->entry.p = hit.p;
      out->entry.weight = beta * sc.weight;
      out->entry.pixel = pixel;
      out->entry.normal = oct_encode(n_front);
      out->entry.segments = uint32_t(segments);
      out->stored = all_finite(out->entry.weight) && !is_black(out->entry.weight);
      out->nondiffuse_bounces = bounces;
      return;
    }
    beta *= sc.weight;
    ++bounces;
    if (is_black(beta) || !all_finite(beta)) return;
    if (settings.roulette_start >= 0 && segments >= settings.roulette_start) {
      const float q = fminf(1.f, max_component(beta));
      if (sampler.at(dims::vertex(v, dims::kRoulette)) >= q) return;
      beta *= 1.f / q;
    }
    ray = spawn_ray(hit.p, hit.ng, frame.to_world(sc.wi), scene.ray_epsilon, hit.time);
  }
}

// Everything a light path needs besides the scene: the splat film (gathers and projections both
// land there, fixed point), this iteration's cache and its search structure, the visibility buffers.
struct PcltLightView {
  SplatFilmView film;
  PcltVisibility visibility = PcltVisibility::shadow_ray;
  float epsilon = 5e-4f;
  const float* zbuffer = nullptr;  // per pixel, kInfinity where the camera ray escaped
  const Vec3* plane_p = nullptr;   // per pixel first hit; plane_n = 0 where the ray escaped
  const Vec3* plane_n = nullptr;
  PcltHashMap hash_map = PcltHashMap::chained;
  HashGridView grid;
  StochasticHashMapView stochastic;
  const PixelCacheEntry* entries = nullptr;
  uint32_t entry_count = 0;
  float radius = 0.f;
  float gather_scale = 0.f;  // 1 / (pi r^2 N_light): density estimate and the pass average in one
  float inv_paths = 0.f;     // 1 / N_light
  int max_segments = 0;
  float time = 0.f;          // the pass's (pass_time): its eye paths' and light paths' instant
};

struct PcltLightCounters {
  uint64_t gather_queries = 0, gathered = 0, projections = 0, visibility_tests = 0;
};

namespace pclt_detail {

// Visibility of point p from the camera for the projection at raster (rx, ry) (sec. 5.3). The
// shortcuts look at the pixel the point falls in and hold for a pinhole only (PcltIntegrator selects
// the shadow ray for a thin lens); points outside the image (reached only by wide filters) and the
// shadow-ray mode cast a ray towards the projection's lens point.
template <typename Tracer>
PS_HD bool projection_visible(const SceneView& scene, const Tracer& tracer, const PcltLightView& lv, const Vec3& p,
                              const Vec3& ng, const lt_detail::Projection& pr, PathCounters* counters) {
  const PerspectiveCamera cam = camera_at(scene, lv.time);
  uint32_t pixel;
  if (lv.visibility != PcltVisibility::shadow_ray && raster_pixel(cam.width, cam.height, pr.rx, pr.ry, &pixel)) {
    const float depth = dot(p - cam.position, cam.forward);
    if (lv.visibility == PcltVisibility::z_buffer) return depth <= lv.zbuffer[pixel] * (1.f + lv.epsilon);
    const Vec3 n = lv.plane_n[pixel];
    if (n.x == 0.f && n.y == 0.f && n.z == 0.f) return true;  // nothing in front
    return dot(p - lv.plane_p[pixel], n) > -lv.epsilon * depth;
  }
  ++counters->rays;
  ++counters->shadow_rays;
  return !tracer.occluded(spawn_shadow_ray(p, ng, pr.wi, pr.dist, scene.ray_epsilon, lv.time));
}

// Adds the light vertex (power beta, arriving from wi, after `segments` light segments) to every
// cache entry within the radius whose front side faces wi: weight * beta / (pi r^2 N).
PS_INLINE void gather(const PcltLightView& lv, const Vec3& p, const Vec3& wi, const Rgb& beta, int segments,
                      PcltLightCounters* c) {
  ++c->gather_queries;
  auto add = [&](uint32_t index, float count) {
    const PixelCacheEntry& e = lv.entries[index];
    if (int(e.segments) + segments > lv.max_segments) return;  // the joined path would be too long
    if (dot(oct_decode(e.normal), wi) <= 0.f) return;
    lv.film.add(e.pixel, e.weight * beta * (lv.gather_scale * count));
    ++c->gathered;
  };
  if (lv.hash_map == PcltHashMap::chained)
    lv.grid.for_each_in_radius(p, lv.radius, [&](const GridRecord& rec, float) { add(rec.payload, 1.f); });
  else  // one record per slot stands for all count_s that hashed there (stochastic_hash_map_view.h)
    lv.stochastic.for_each_in_radius(p, lv.radius, [&](const StochasticSlot& s, float) { add(s.payload, float(s.count)); });
}

}  // namespace pclt_detail

// One light path of the light pass: emitter splat (EL), then at every vertex a gather from the
// pixel cache and a projection of the Lambertian part to the camera.
template <typename Tracer>
PS_HD void pclt_trace_light(const SceneView& scene, const Tracer& tracer, const Sampler& sampler, const PcltSettings& settings,
                            const PcltLightView& lv, PathCounters* counters, PcltLightCounters* lc) {
  using namespace lt_detail;
  using pclt_detail::projection_visible;
  if (scene.num_lights == 0) return;
  const PerspectiveCamera cam = camera_at(scene, lv.time);  // the pass's instant: its pixel cache saw this camera
  LightPathStart start;
  if (!start_light_path(scene, sampler, lv.time, &start)) return;
  const Light& light = *start.light;
  const EmissionSample& e = start.emission;
  const float inv_select = 1.f / start.select_prob;

  if (is_area_light(light)) {  // EL, as LT
    Projection pr;
    if (cam.project(e.p, connection_lens_sample(cam, sampler, 0), &pr) && reaches_image(lv.film, cam.filter, pr.rx, pr.ry)) {
      const Rgb le = area_light_radiance(scene, light, e.ng, pr.wi, e.uv);
      if (!is_black(le) && (++lc->visibility_tests, projection_visible(scene, tracer, lv, e.p, e.ng, pr, counters))) {
        ++lc->projections;
        const float scale = fabsf(dot(e.ng, pr.wi)) / e.pdf_a * inv_select * pr.factor * lv.inv_paths;
        splat(lv.film, cam.filter, pr.rx, pr.ry, le * scale);
      }
    }
  }
  if (lv.max_segments < 2) return;

  Rgb beta = e.weight * inv_select;  // photon power
  const float beta0 = max_component(beta);
  Ray ray = first_light_ray(scene, e);
  for (int segments = 1; segments < lv.max_segments; ++segments) {
    SurfaceHit hit;
    ++counters->rays;
    if (!tracer.intersect(ray, &hit)) break;
    Material textured;
    const Material& mat = shading_material(scene, hit, &textured);
    const Frame frame(hit.ns);
    const Vec3 wo_world = -ray.d;  // towards the light side
    const Vec3 wo = frame.to_local(wo_world);
    const float wo_ng = fabsf(dot(wo_world, hit.ng));
    if (!(wo_ng > 0.f)) break;
    const uint32_t v = uint32_t(segments - 1);

    // (1) Gather: cache entries lie on Lambertian surfaces; a delta-only vertex has nothing to give.
    if (lv.entry_count > 0 && bsdf_has_non_delta(mat)) pclt_detail::gather(lv, hit.p, wo_world, beta, segments, lc);

    // (2) Projection of the Lambertian part (eq. 4 with the adjoint shading-normal factor, as LT);
    // the other lobes of a directly seen vertex are the eye pass's.
    if (pclt_detail::has_diffuse(mat)) {
      Projection pr;
      if (cam.project(hit.p, connection_lens_sample(cam, sampler, v + 1), &pr) &&
          reaches_image(lv.film, cam.filter, pr.rx, pr.ry)) {
        const Rgb f = pclt_detail::diffuse_eval(mat, wo, frame.to_local(pr.wi));
        if (!is_black(f)) {
          ++lc->visibility_tests;
          if (projection_visible(scene, tracer, lv, hit.p, hit.ng, pr, counters)) {
            ++lc->projections;
            const float cosines = fabsf(wo.z) * fabsf(dot(pr.wi, hit.ng)) / wo_ng;
            splat(lv.film, cam.filter, pr.rx, pr.ry, beta * f * (cosines * pr.factor * lv.inv_paths));
          }
        }
      }
    }
    if (segments + 1 >= lv.max_segments) break;

    if (!continue_light_path(sampler, v, mat, frame, hit, wo, wo_ng, segments, settings.roulette_start, beta0,
                             scene.ray_epsilon, &beta, &ray))
      break;
  }
}

}  // namespace pathspace
