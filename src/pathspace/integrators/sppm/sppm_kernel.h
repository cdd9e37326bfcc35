// Stochastic progressive photon mapping, per-path logic (device-safe, templated on the ray caster
// "Tracer" like pt_trace_path). Hachisuka & Jensen 2009: every iteration traces one camera path per
// pixel to its first gathering vertex (the visible point; redistributed every iteration, which
// anti-aliases and resolves glossy chains), then photons from all lights; each photon vertex on a
// non-delta surface adds f(wo_vp, wi) Phi to the visible points within the iteration's global
// radius (Knaus & Zwicker 2011, PCLT eq. 1), front side only. No next event estimation: direct
// light is the photons' first hit. Flux sums are 64-bit fixed point, so atomic accumulation is
// order-independent and a render is bit-identical for every thread count.
#pragma once

#include "pathspace/hashgrid/hash_grid_view.h"
#include "pathspace/integrators/common/dimensions.h"
#include "pathspace/stats/path_counters.h"
#include "pathspace/integrators/common/light_dimensions.h"
#include "pathspace/integrators/common/light_path_start.h"
#include "pathspace/integrators/sppm/sppm_settings.h"
#include "pathspace/scene/light_emission.h"
#include "pathspace/materials/bsdf_layers.h"
#include "pathspace/parallel/atomics.h"
#include "pathspace/sampling/sampler.h"
#include "pathspace/scene/shading_material.h"

namespace pathspace {

// The gathering vertex of one camera path (one per pixel per iteration).
struct VisiblePoint {
  Vec3 p;
  Vec3 n_front;       // geometric normal turned to the side the camera path arrived from
  Vec3 ns;            // shading normal (the BSDF frame)
  Vec3 wo;            // unit, towards the previous camera-path vertex
  Rgb throughput;     // camera to here, including 1 / P(non-delta lobe chosen)
  uint32_t material = 0;
  Point2 uv;              // texture coordinates at p (the material is shaded per gathered photon)
  uint32_t segments = 0;  // camera path length to p (camera ray = 1)
  bool valid = false;
  // A purely Lambertian point (a standard material without a glossy lobe, textures applied): its BSDF
  // is lambert_f wherever both directions are above the surface (mirrored for a two-sided one), so a
  // deposit needs no material lookup or frame (sppm_deposit; the same bits as bsdf_eval).
  bool lambert = false;
  bool mirrors_to_wo_side = false;  // detail::mirrors_to_wo_side of the material
  Rgb lambert_f;
};

// Photons use the light-path dimension layout of light tracing (common/light_dimensions.h).

// Fixed-point flux: quantum = reference photon power * 2^-32 keeps ~9 decimal digits per deposit
// relative to an unscattered photon, and 2^32 such photons per visible point before overflow.
inline constexpr double kFluxFixedScale = 4294967296.0;   // 2^32
inline constexpr double kFluxFixedMax = 4503599627370496.0;  // 2^52 per deposit (saturates)

namespace sppm_detail {
// Whether a camera path stops at this vertex (has a lobe a density estimate can gather).
PS_INLINE bool stores_visible_point(const Material& m, float glossy_roughness) {
  if (!bsdf_has_non_delta(m)) return false;
  if (glossy_roughness <= 0.f) return true;
  switch (m.type) {
    case MaterialType::standard:
      return !is_black(m.diffuse) || phong_roughness(m.exponent) >= glossy_roughness;
    case MaterialType::rough_conductor:
    case MaterialType::rough_dielectric: return m.alpha >= glossy_roughness;
    case MaterialType::coated_diffuse: return true;
    case MaterialType::coated_conductor: return fmaxf(m.alpha, m.base_alpha) >= glossy_roughness;
    case MaterialType::interface: return false;
  }
  return true;
}

// Probability that bsdf_sample picks a non-delta lobe for wo (the complement continues through a
// delta lobe): a mixed vertex chooses stochastically between gathering and going on.
PS_INLINE float non_delta_probability(const Material& m, Vec3 wo) {
  if (m.type == MaterialType::coated_diffuse || m.type == MaterialType::coated_conductor) {
    detail::flip_for_two_sided(m, &wo, nullptr);
    return 1.f - layered::proposal(m, wo).mirror;
  }
  if (m.type != MaterialType::standard) return 1.f;
  detail::flip_for_two_sided(m, &wo, nullptr);
  const standard::LobeProbabilities p = standard::lobe_probabilities(m, wo);
  return p.diffuse + p.glossy;
}
}  // namespace sppm_detail

// Eye pass of one pixel: emission seen along the path (through delta and smooth-glossy bounces)
// goes to *direct; the first gathering vertex becomes *vp (vp->valid = false when there is none).
template <typename Tracer>
PS_HD void sppm_trace_eye(const SceneView& scene, const Tracer& tracer, const Sampler& sampler, Ray ray,
                          const SppmSettings& settings, int max_segments, PathCounters* counters, Rgb* direct,
                          VisiblePoint* vp) {
  using namespace sppm_detail;
  vp->valid = false;
  Rgb beta(1.f);
  Rgb radiance;
  for (int segments = 1;; ++segments) {
    SurfaceHit hit;
    ++counters->rays;
    if (!tracer.intersect(ray, &hit)) {
      if (scene.environment_light >= 0) radiance += beta * environment_radiance(scene, scene.lights[scene.environment_light], ray.d);
      break;
    }
    // Without next event estimation emission always counts with weight 1.
    if (hit.light != kNoLight) radiance += beta * area_light_radiance(scene, scene.lights[hit.light], hit.ng, -ray.d, hit.uv);
    if (segments >= max_segments) break;  // a photon needs at least one more segment

    Material textured;
    const Material& mat = shading_material(scene, hit, &textured);
    const Frame frame(hit.ns);
    const Vec3 wo = frame.to_local(-ray.d);
    const uint32_t v = uint32_t(segments - 1);
    const float u_lobe = sampler.at(dims::vertex(v, dims::kLobe));
    if (stores_visible_point(mat, settings.glossy_roughness)) {
      const float p_gather = non_delta_probability(mat, wo);
      if (u_lobe < p_gather) {
        vp->p = hit.p;
        vp->n_front = dot(hit.ng, -ray.d) >= 0.f ? hit.ng : -hit.ng;
        vp->ns = hit.ns;
        vp->wo = -ray.d;
        vp->throughput = beta * (1.f / p_gather);
        vp->material = hit.material;
        vp->uv = hit.uv;
        vp->segments = uint32_t(segments);
        vp->valid = true;
        vp->lambert = mat.type == MaterialType::standard && is_black(mat.glossy);
        vp->mirrors_to_wo_side = detail::mirrors_to_wo_side(mat);
        vp->lambert_f = mat.diffuse * kInvPi;
        break;
      }
      // u_lobe >= p_gather: bsdf_sample below picks a delta lobe with the same number.
    }
    BsdfSample bs;
    const Point2 ub{sampler.at(dims::vertex(v, dims::kBsdfU)), sampler.at(dims::vertex(v, dims::kBsdfU + 1))};
    if (!bsdf_sample(mat, wo, u_lobe, ub, TransportMode::radiance, &bs)) break;
    beta *= bs.weight;
    if (is_black(beta)) break;
    if (settings.roulette_start >= 0 && segments >= settings.roulette_start) {
      const float q = fminf(1.f, max_component(beta));
      if (sampler.at(dims::vertex(v, dims::kRoulette)) >= q) break;
      beta *= 1.f / q;
    }
    ray = spawn_ray(hit.p, hit.ng, frame.to_world(bs.wi), scene.ray_epsilon, hit.time);
  }
  *direct = radiance;
}

// What a photon deposit needs: the visible points of this iteration in a hash grid (payload =
// pixel), their per-channel fixed-point flux sums, and the global radius.
// Points and flux are indexed like the grid's (cell-compacted) records, not by pixel: the records
// of a cell are consecutive, so a gather reads and adds to consecutive memory (HashGrid::compact).
struct SppmGatherView {
  HashGridView grid;
  const VisiblePoint* points = nullptr;  // points[i] belongs to grid.records[i]
  uint64_t* flux = nullptr;     // 3 per record
  float radius = 0.f;
  float inv_quantum = 0.f;      // 1 / (reference photon power * 2^-32)
  int max_segments = 0;
};

// Adds a photon arriving at p from direction wi (unit, pointing away from the surface towards where
// the photon came from) after `segments` light-path segments to every visible point in range.
PS_INLINE uint32_t sppm_deposit(const SceneView& scene, const SppmGatherView& g, const Vec3& p, const Vec3& wi,
                                const Rgb& power, int segments) {
  uint32_t gathered = 0;
  g.grid.for_each_in_radius(p, g.radius, [&](const GridRecord& rec, float) {
    const size_t index = size_t(&rec - g.grid.records);
    const VisiblePoint& vp = g.points[index];
    if (int(vp.segments) + segments > g.max_segments) return;  // the joined path would be too long
    if (dot(vp.n_front, wi) <= 0.f) return;                    // photons from the back side do not count
    Rgb f;
    if (vp.lambert) {  // bsdf_eval of a diffuse lobe alone, which needs only the shading frame's z
      float wo_z = dot(vp.wo, vp.ns), wi_z = dot(wi, vp.ns);
      if (vp.mirrors_to_wo_side && wo_z < 0.f) wo_z = -wo_z, wi_z = -wi_z;
      if (standard::both_above(Vec3(0.f, 0.f, wo_z), Vec3(0.f, 0.f, wi_z))) f = vp.lambert_f;
    } else {
      const Frame frame(vp.ns);
      Material textured;
      f = bsdf_eval(shading_material(scene, vp.material, vp.uv, &textured), frame.to_local(vp.wo), frame.to_local(wi), TransportMode::radiance);
    }
    if (is_black(f)) return;
    const Rgb c = f * power;
    if (!all_finite(c)) return;
    uint64_t* dst = g.flux + 3 * index;
    for (int ch = 0; ch < 3; ++ch) {
      const double q = fmin(double(c[ch]) * double(g.inv_quantum) + 0.5, kFluxFixedMax);
      if (q >= 1.0) atomic_fetch_add(dst + ch, uint64_t(q));
    }
    ++gathered;
  });
  return gathered;
}

// Largest power of an unscattered photon over all lights (flux / selection probability): the
// reference of the fixed-point flux quantum. Evaluated on the host once per render.
PS_INLINE float max_photon_power(const SceneView& scene) {
  float m = 0.f;
  for (uint32_t i = 0; i < scene.num_lights; ++i) {
    const Light& l = scene.lights[i];
    const float p = scene.light_selection.probability(i);
    if (!(p > 0.f)) continue;
    float scale = 0.f;
    const float disk = kPi * scene.bounds.radius * scene.bounds.radius;
    switch (l.type) {
      case LightType::area_triangle: {
        // A moving emitter's area changes while the shutter is open (scene/motion.h): the largest of
        // its two ends and its middle.
        float area = 0.f;
        for (const float time : {0.f, 0.5f, 1.f}) {
          const TriangleVertices tv = triangle_at(scene, scene.triangles[l.shape], time);
          area = fmaxf(area, triangle_area(tv.p0, tv.p1, tv.p2));
        }
        scale = kPi * area;
        break;
      }
      case LightType::area_sphere: scale = kPi * kFourPi * scene.spheres[l.shape].radius * scene.spheres[l.shape].radius; break;
      case LightType::point: scale = kFourPi; break;
      case LightType::spot: scale = kFourPi * l.image_max; break;
      // Uniform points of the image plane: the weight is at most value * image * plane area.
      case LightType::projector: scale = 4.f * projector_half_width_u(l) * projector_half_width_v(l) * l.image_max; break;
      case LightType::directional: scale = disk; break;
      // An image's radiance over its pdf stays below 4 pi times the brightest texel in practice.
      case LightType::environment: scale = kFourPi * disk * (scene.environment_map.texels ? scene.environment_map.max_texel : 1.f); break;
    }
    if (l.two_sided && is_area_light(l)) scale *= 2.f;
    m = fmaxf(m, max_component(l.value) * scale / p);
  }
  return m;
}

struct PhotonCounters {
  uint64_t deposits = 0;  // photon vertices that queried the grid
  uint64_t gathered = 0;  // (photon vertex, visible point) pairs that added flux
};

// A photon arriving at a non-delta surface: what sppm_deposit needs, kept for a later, sorted
// deposit (SppmIntegrator: photons deposited in the order of their cells hit memory in cache).
struct PhotonHit {
  Vec3 p;
  Vec3 wi;  // unit, towards where the photon came from
  Rgb power;
  uint32_t segments = 0;
};

// One photon path: emitted by sample_emission (scene/light_emission.h), scattered with importance
// transport, handing every non-delta vertex including the first (SPPM has no separate direct
// lighting) to deposit(const PhotonHit&). Light paths longer than max_segments - 1 cannot join
// the shortest camera side (one segment). `time`: the pass's (pass_time), which its visible points share.
template <typename Tracer, typename Deposit>
PS_HD void sppm_walk_photon(const SceneView& scene, const Tracer& tracer, const Sampler& sampler,
                            const SppmSettings& settings, int max_segments, float time, PathCounters* counters,
                            Deposit&& deposit) {
  LightPathStart start;
  if (!start_light_path(scene, sampler, time, &start)) return;
  const EmissionSample& e = start.emission;
  Rgb beta = e.weight * (1.f / start.select_prob);  // photon power Phi = L_e cos / (p_select pdf_a pdf_w)
  Ray ray = first_light_ray(scene, e);
  for (int segments = 1; segments < max_segments; ++segments) {
    SurfaceHit hit;
    ++counters->rays;
    if (!tracer.intersect(ray, &hit)) break;
    Material textured;
    const Material& mat = shading_material(scene, hit, &textured);
    const Vec3 wi_world = -ray.d;
    if (bsdf_has_non_delta(mat)) deposit(PhotonHit{hit.p, wi_world, beta, uint32_t(segments)});
    if (segments + 1 >= max_segments) break;
    const Frame frame(hit.ns);
    const uint32_t v = uint32_t(segments - 1);
    BsdfSample bs;
    const Point2 ub{sampler.at(light_dims::vertex(v, light_dims::kBsdfU)),
                    sampler.at(light_dims::vertex(v, light_dims::kBsdfU + 1))};
    // Importance transport: the fixed direction is where the photon came from.
    if (!bsdf_sample(mat, frame.to_local(wi_world), sampler.at(light_dims::vertex(v, light_dims::kLobe)), ub,
                     TransportMode::importance, &bs))
      break;
    const float before = max_component(beta);
    beta *= bs.weight;
    if (is_black(beta) || !all_finite(beta)) break;
    // Roulette on the change of power, so surviving photons keep roughly their emitted power.
    if (settings.roulette_start >= 0 && segments >= settings.roulette_start - 1) {
      const float q = fminf(1.f, max_component(beta) / before);
      if (sampler.at(light_dims::vertex(v, light_dims::kRoulette)) >= q) break;
      beta *= 1.f / q;
    }
    ray = spawn_ray(hit.p, hit.ng, frame.to_world(bs.wi), scene.ray_epsilon, hit.time);
  }
}

// One photon path deposited into the grid as it goes (the device's order).
template <typename Tracer>
PS_HD void sppm_trace_photon(const SceneView& scene, const Tracer& tracer, const Sampler& sampler,
                             const SppmSettings& settings, const SppmGatherView& gather, float time,
                             PathCounters* counters, PhotonCounters* photons) {
  sppm_walk_photon(scene, tracer, sampler, settings, gather.max_segments, time, counters, [&](const PhotonHit& h) {
    ++photons->deposits;
    photons->gathered += sppm_deposit(scene, gather, h.p, h.wi, h.power, int(h.segments));
  });
}

}  // namespace pathspace
