// One path-traced camera path (device-safe, templated on the ray caster "Tracer" with
// intersect(Ray, SurfaceHit*) and occluded(Ray)). Unidirectional estimator with next event estimation
// and MIS (Veach 1997 §9.2); either technique can be switched off for tests:
//   nee && bsdf_sampling : MIS of light sampling and BSDF sampling (default)
//   nee only             : emission reached by BSDF rays is ignored except after delta bounces
//   bsdf_sampling only   : no light sampling; emission found by BSDF rays counts with weight 1
// The path is split at its selected vertices (common/path_sample.h) so that a path space filter can
// replace their contributions; PathSample::value() is the plain path-tracing estimate.
#pragma once

#include "pathspace/integrators/common/dimensions.h"
#include "pathspace/integrators/common/media_steps.h"
#include "pathspace/media/equiangular.h"
#include "pathspace/media/henyey_greenstein.h"
#include "pathspace/filters/path_sample.h"
#include "pathspace/integrators/pt/caustic_photons.h"
#include "pathspace/integrators/pt/selectable_vertex.h"
#include "pathspace/stats/path_counters.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/scene/light_sampling.h"
#include "pathspace/scene/light_selection.h"
#include "pathspace/materials/bsdf.h"
#include "pathspace/sampling/sampler.h"
#include "pathspace/scene/shading_material.h"
#include "pathspace/scene/texture_footprint.h"

namespace pathspace {

namespace pt_detail {
PS_INLINE float combine_mis(const PtSettings& s, float pdf_this, float pdf_other) {
  if (!(s.nee && s.bsdf_sampling)) return 1.f;
  return mis_weight(s.mis, pdf_this, pdf_other);
}

// A selected vertex while its path is still being traced.
struct OpenVertex {
  FilterVertex geometry;  // p, normals, wo, prev_p, prefix_distance, segments, selected
  BsdfLayers layers;
  Rgb throughput;                      // camera to vertex (before its BSDF)
  Rgb nee[kMaxBsdfLayers];             // next event estimation per layer
  Rgb continuation[kMaxBsdfLayers];    // f_l |cos| / pdf of the sampled direction per layer
  Rgb after;                           // radiance gathered after the vertex, relative to it
};

PS_INLINE bool wants_vertex(const VertexSelection& s, int diffuse_index, int selected) {
  switch (s.mode) {
    case VertexSelectionMode::first: return selected == 0;
    case VertexSelectionMode::nth: return diffuse_index == s.n;
    case VertexSelectionMode::all: return selected < s.max_vertices && selected < kMaxSelectedVertices;
    case VertexSelectionMode::none: return false;
  }
  return false;
}

PS_INLINE void eval_layers(const Material& m, const BsdfLayers& layers, bool split, const Vec3& wo, const Vec3& wi,
                           Rgb f[kMaxBsdfLayers]) {
  if (split) {
    bsdf_eval_layers(m, layers, wo, wi, TransportMode::radiance, f);
  } else {
    f[0] = bsdf_eval(m, wo, wi, TransportMode::radiance);
  }
}

// The visibility weight's data of a selected vertex (filters/path_sample.h, VisibilityProbes). These
// rays use no sampler dimension, so recording them changes nothing else in the path.
template <typename Tracer>
PS_HD void probe_visibility(const SceneView& scene, const Tracer& tracer, const SurfaceHit& hit, const Vec3& towards_viewer,
                            const VisibilityProbes& probes, PathCounters* counters, FilterVertex* g) {
  g->visible_lights = 0;
  for (int k = 0; k < probes.delta_count; ++k) {
    const Light& light = scene.lights[probes.delta_lights[k]];
    Vec3 d = -light.direction;
    float dist = kInfinity;
    if (light.type != LightType::directional) {
      const Vec3 to = light_position(light, hit.time) - hit.p;
      dist = length(to);
      if (!(dist > 0.f)) continue;
      d = to / dist;
    }
    ++counters->rays;
    ++counters->shadow_rays;
    if (!tracer.occluded(spawn_shadow_ray(hit.p, hit.ng, d, dist, scene.ray_epsilon, hit.time))) g->visible_lights |= 1u << k;
  }
  g->open_distance = 0.f;
  if (probes.open_ray) {
    const Vec3 up = dot(hit.ns, towards_viewer) >= 0.f ? hit.ns : -hit.ns;
    SurfaceHit h;
    ++counters->rays;
    g->open_distance = tracer.intersect(spawn_ray(hit.p, hit.ng, up, scene.ray_epsilon, hit.time), &h) ? h.t : kInfinity;
  }
}

// Whether a path may still select a vertex after `selected` of them (first and nth select one).
PS_INLINE bool selects_more(const VertexSelection& s, int selected) {
  return s.mode == VertexSelectionMode::all && wants_vertex(s, 0, selected);
}

// Demodulates the closed vertices into records: contribution = C / albedo, throughput = T albedo.
PS_INLINE void close_vertices(const OpenVertex* open, int count, PathSample* out) {
  for (int k = 0; k < count; ++k) {
    const OpenVertex& v = open[k];
    for (int l = 0; l < v.layers.count; ++l) {
      const Rgb a = v.layers.albedo[l];
      const Rgb c = v.nee[l] + v.continuation[l] * v.after;
      FilterVertex& r = out->records[out->count++];
      r = v.geometry;
      r.layer = v.layers.id[l];
      r.roughness = v.layers.roughness[l];
      r.throughput = v.throughput * a;
      for (int ch = 0; ch < 3; ++ch) r.contribution[ch] = a[ch] > 0.f ? c[ch] / a[ch] : 0.f;
    }
  }
}
}  // namespace pt_detail

// The state of one camera path between its bounces. pt_trace_path runs the steps below in a loop on
// one thread; the GPU's wavefront path tracer (gpu/cuda_wavefront_pt.cu; Laine, Karras, Aila 2013)
// keeps the state in device memory and runs each step as its own kernel over a queue of paths, so
// both are the same arithmetic in the same order: the images agree bit for bit.
// The selected vertices live outside the state (`open`, kMaxSelectedVertices of them, about 200
// bytes each): they are written once per selection and read at the end, while the rest (about 170
// bytes) changes every bounce, so the wavefront copies only that part in and out of each kernel.
struct PtPathState {
  Ray ray;                   // the next ray to trace (extension)
  pt_detail::OpenVertex* open = nullptr;
  Rgb prefix;
  int owner = -1;            // where gathered radiance goes: -1 the prefix, k open[k].after
  Rgb beta{1.f};             // throughput relative to that owner
  Rgb abs_beta{1.f};         // throughput from the camera (Russian roulette)
  bool after_delta = true;   // the camera "bounce" counts as delta: directly seen emission always counts
  float prev_bsdf_pdf = 0.f;
  Vec3 prev_p;
  Vec3 prev_ns;              // the previous vertex's shading normal (zero at the camera): light selection there
  float path_distance = 0.f, prev_distance = 0.f;
  // With caustics: 1 after a gathering (selectable) vertex's bounce, 2 once vertices that are not
  // selectable alone followed it (emission found then belongs to the photon map), 0 otherwise.
  int caustic_chain = 0;
  // Gathering vertices passed. With one-bounce photons (CausticMapView::with_one_bounce) every
  // gathering vertex gathers them, and only the first gathers caustics and estimates direct light:
  // the light that reaches a later one directly or through links (its next event estimate, the
  // emission found after it, its caustics) is what the previous vertex's one-bounce photons carry.
  int receivers_passed = 0;
  int selected = 0, diffuse_index = 0;
  int segments = 1;          // of the ray being traced (camera ray = segment 1)
  // Camera-side branches (VertexSelection::camera_splits): bit k of split_code picks the path's
  // way at its k-th split, refraction (1) or reflection (0) at smooth glass, passing (1) or
  // scattering (0) in a medium; `splits` counts the splits passed so far.
  uint32_t split_code = 0;
  int splits = 0;
  // Next event estimation waiting for its shadow ray: added if the ray is unoccluded.
  bool shadow_pending = false;
  int shadow_vertex = -1;    // -1: shadow_value[0] adds to open[shadow_owner] / the prefix; k: to open[k].nee[l]
  int shadow_owner = -1;
  Ray shadow_ray;
  Rgb shadow_value[kMaxBsdfLayers];
  // Media (docs/media.md): the medium the path's ray travels in, the one its shadow ray starts in,
  // and the path's stream of numbers for distance sampling and transmittance (dims::kMediumStream).
  int32_t medium = kVacuum;
  int32_t shadow_medium = kVacuum;
  Pcg32 medium_rng;

  PS_HD Rgb& radiance() { return owner < 0 ? prefix : open[owner].after; }
  // Whether emission reached now belongs to the photon map: through links from a gathering vertex,
  // or at all from the receiver standing for a one-bounce photon's bounce.
  PS_HD bool emission_is_photons(const CausticMapView* caustics) const {
    return caustic_chain == 2 || (caustic_chain == 1 && receivers_passed >= 2 && caustics->with_one_bounce);
  }
  // Whether the path may split here (at smooth glass, in a scattering medium): a filter selects
  // vertices, none is selectable yet, and the split budget is not spent.
  PS_HD bool may_split(const VertexSelection& selection) const {
    return selection.mode != VertexSelectionMode::none && diffuse_index == 0 && splits < selection.camera_splits;
  }
  // Passes a split: true for the second way (refraction, passing), false for the first.
  PS_HD bool take_split() { return ((split_code >> splits++) & 1u) != 0u; }
};

namespace pt_detail {
// Opens the path's next selected vertex at `at` (position, normals; a medium vertex passes the
// reversed incident direction as both), reached along -wo after `segments` segments: its geometry,
// layers and throughput, empty estimates, and the visibility probes when a filter asks for them.
template <typename Tracer>
PS_HD OpenVertex* open_selected_vertex(const SceneView& scene, const Tracer& tracer, const SurfaceHit& at, const Vec3& wo,
                                       int segments, const BsdfLayers& layers, const VisibilityProbes& probes,
                                       PathCounters* counters, PtPathState* s) {
  OpenVertex* sel = &s->open[s->selected];
  FilterVertex& g = sel->geometry;
  g.p = at.p;
  g.ng = at.ng;
  g.ns = at.ns;
  g.wo = wo;
  g.prev_p = s->prev_p;
  g.prefix_distance = s->prev_distance;
  g.segments = uint8_t(segments);
  g.selected = uint8_t(s->selected);
  sel->layers = layers;
  sel->throughput = s->abs_beta;
  for (int l = 0; l < kMaxBsdfLayers; ++l) sel->nee[l] = sel->continuation[l] = Rgb();
  sel->after = Rgb();
  if (probes.any()) probe_visibility(scene, tracer, at, wo, probes, counters, &g);
  ++s->selected;
  return sel;
}

// One-bounce photons at a gathering vertex (CausticMapView::with_one_bounce): light arriving here
// as the next event estimate's does, so at a selected vertex `sel` they join its estimate, per layer,
// and the filter averages them with it (the gather discs too); elsewhere they go to what owns the
// radiance. wo: towards the camera side, in world space and in the shading frame `frame`;
// `segments`: the camera path's up to the vertex.
PS_INLINE void add_one_bounce_photons(const CausticMapView& caustics, const SurfaceHit& hit, const Material& mat, const Frame& frame,
                                      const Vec3& wo_world, const Vec3& wo, const BsdfLayers& layers, bool split_layers,
                                      int segments, OpenVertex* sel, PtPathState* s) {
  const PhotonSetView& photons = caustics.one_bounce;
  if (!sel) {
    s->radiance() += s->beta * gather_one_bounce_photons(photons, caustics.max_segments, hit, mat, wo_world, segments);
  } else if (layers.count == 1 && is_lambertian(mat)) {
    sel->nee[0] += gather_one_bounce_photons(photons, caustics.max_segments, hit, mat, wo_world, segments);
  } else {
    for_each_gathered_photon(photons, caustics.max_segments, hit, wo_world, segments, [&](const CausticPhoton& ph) {
      Rgb fl[kMaxBsdfLayers];
      eval_layers(mat, layers, split_layers, wo, frame.to_local(ph.wi), fl);
      for (int l = 0; l < layers.count; ++l)
        if (all_finite(fl[l])) sel->nee[l] += fl[l] * ph.power * photons.inv_area_count;
    });
  }
}
}  // namespace pt_detail

// What follows a step: trace s.ray next, or the path has ended (after its pending shadow ray).
enum class PtNext : uint8_t { extend, end };

// `open`: room for kMaxSelectedVertices selected vertices (written when selected, so not cleared).
// `split_code`: which branch to follow at each camera-side split (PtPathState::split_code).
PS_INLINE void pt_begin(PtPathState* s, const Ray& ray, pt_detail::OpenVertex* open, uint32_t split_code = 0) {
  s->ray = ray;
  s->open = open;
  s->prefix = Rgb();
  s->owner = -1;
  s->beta = s->abs_beta = Rgb(1.f);
  s->after_delta = true;
  s->prev_bsdf_pdf = 0.f;
  s->prev_p = ray.o;
  s->prev_ns = Vec3(0.f);
  s->path_distance = s->prev_distance = 0.f;
  s->caustic_chain = s->receivers_passed = s->selected = s->diffuse_index = 0;
  s->segments = 1;
  s->split_code = split_code;
  s->splits = 0;
  s->shadow_pending = false;
}

// The path's ray left the scene: environment emission; the path ends.
PS_INLINE void pt_on_miss(const SceneView& scene, const PtSettings& settings, PtPathState* s,
                          const CausticMapView* caustics = nullptr) {
  using namespace pt_detail;
  if (scene.environment_light < 0 || (caustics && s->emission_is_photons(caustics))) return;
  const Light& env = scene.lights[scene.environment_light];
  const Ray& ray = s->ray;
  if (s->after_delta || !settings.nee) {
    s->radiance() += s->beta * environment_radiance(scene, env, ray.d);
  } else if (settings.bsdf_sampling) {
    const float select_prob = light_selection_probability_at(scene, s->prev_p, s->prev_ns, uint32_t(scene.environment_light));
    const float light_pdf_w = select_prob * environment_pdf(scene, ray.d);
    s->radiance() += s->beta * environment_radiance(scene, env, ray.d) * combine_mis(settings, s->prev_bsdf_pdf, light_pdf_w);
  }
}

// The path's ray hit `hit`: emission, vertex selection, next event estimation (its shadow ray left
// pending in s: pt_resolve_shadow), BSDF sampling and Russian roulette. `tracer` serves only the
// visibility probes (none unless a filter asks for them).
template <typename Tracer>
PS_HD PtNext pt_on_hit(const SceneView& scene, const Tracer& tracer, const Sampler& sampler, const PtSettings& settings,
                       const SurfaceHit& hit, PathCounters* counters, PtPathState* s, const VisibilityProbes& probes = {},
                       bool query_only = false, const CausticMapView* caustics = nullptr) {
  using namespace pt_detail;
  const int max_segments = settings.max_segments > 0 ? settings.max_segments : scene.max_path_segments;
  const VertexSelection& selection = settings.selection;
  const Ray ray = s->ray;
  const int segments = s->segments;
  s->prev_distance = s->path_distance;
  s->path_distance += hit.t;

  if (hit.light != kNoLight && !(caustics && s->emission_is_photons(caustics))) {
    const Light& light = scene.lights[hit.light];
    const Rgb le = area_light_radiance(scene, light, hit.ng, -ray.d, hit.uv);
    if (!is_black(le)) {
      if (s->after_delta || !settings.nee) {
        s->radiance() += s->beta * le;
      } else if (settings.bsdf_sampling) {
        const float select_prob = light_selection_probability_at(scene, s->prev_p, s->prev_ns, uint32_t(hit.light));
        const float light_pdf_w = select_prob * light_pdf(scene, light, s->prev_p, hit.p, hit.ng, hit.time);
        s->radiance() += s->beta * le * combine_mis(settings, s->prev_bsdf_pdf, light_pdf_w);
      }
    }
  }
  if (segments >= max_segments) return PtNext::end;

  Material textured;
  const Material& mat = segments == 1 && settings.texture_footprint ? footprint_shading_material(scene, hit, ray, &textured)
                                                                     : shading_material(scene, hit, &textured);
  const Frame frame(hit.ns);
  const Vec3 wo = frame.to_local(-ray.d);
  const uint32_t v = uint32_t(segments - 1);

  // Vertex selection for filtering (none without a filter: the layers are not needed).
  // The layers are built in place: assigned from bsdf_layers' result, GCC wrote them field by field
  // into a temporary and copied that out with 16-byte loads no store could forward (the line held
  // 6.6% of pt_on_hit's samples; whole frames: no change beyond the machine's noise of +-2%).
  OpenVertex* sel = nullptr;
  BsdfLayers layers = selection.mode != VertexSelectionMode::none ? bsdf_layers(mat) : BsdfLayers();
  bool selectable = false;
  if (selection.mode != VertexSelectionMode::none) {
    if (!selection.split_layers) merge_layers(&layers);
    selectable = is_selectable(layers, selection);
  }
  // Caustic photons gather at selectable vertices rough enough (CausticMapView::receivers); the
  // others are links of caustic chains.
  const bool gathers = caustics && selectable && is_selectable(layers, caustics->receivers);
  if (gathers) ++s->receivers_passed;
  // A gathering vertex whose direct light and caustics the previous one's one-bounce photons carry.
  const bool silent = gathers && s->receivers_passed >= 2 && caustics->with_one_bounce;
  if (selectable) {
    // Caustics at every sufficiently diffuse vertex, into what owns the radiance here: the prefix
    // up to the first selected vertex (so not averaged by the filter, sec. 2.3), after it the last
    // selected vertex's contribution (light arriving there from elsewhere, filtered with it).
    if (gathers && !silent) s->radiance() += s->beta * gather_photons(caustics->caustic, caustics->max_segments, hit, mat, -ray.d, segments);
    ++s->diffuse_index;
    if (wants_vertex(selection, s->diffuse_index, s->selected)) {
      sel = open_selected_vertex(scene, tracer, hit, -ray.d, segments, layers, probes, counters, s);
      if (query_only && !selects_more(selection, s->selected)) return PtNext::end;
    }
    if (gathers && caustics->with_one_bounce)
      add_one_bounce_photons(*caustics, hit, mat, frame, -ray.d, wo, layers, selection.split_layers, segments, sel, s);
  }

  // Next event estimation: one light, one point on it; its contribution waits for the shadow ray.
  // Not at a vertex that is not selectable reached from a gathering vertex through such vertices
  // only: light -> it -> ... -> that vertex is a caustic path, which the photon map carries.
  const bool in_caustic_chain = caustics && s->caustic_chain != 0 && !gathers;
  if (settings.nee && scene.num_lights > 0 && bsdf_has_non_delta(mat) && !in_caustic_chain && !silent) {
    float select_prob;
    const uint32_t li = select_light_at(scene, hit.p, hit.ns, sampler.at(dims::vertex(v, dims::kLightSelect)), &select_prob);
    LightSample ls;
    const Point2 ul{sampler.at(dims::vertex(v, dims::kLightU)), sampler.at(dims::vertex(v, dims::kLightU + 1))};
    if (li != LightTreeView::kNone && sample_light(scene, scene.lights[li], hit.p, hit.time, ul, &ls)) {
      const Vec3 wi = frame.to_local(ls.wi);
      const Rgb f = bsdf_eval(mat, wo, wi, TransportMode::radiance);
      if (!is_black(f)) {
        s->shadow_ray = spawn_shadow_ray(hit.p, hit.ng, ls.wi, ls.dist, scene.ray_epsilon, hit.time);
        s->shadow_medium = scene.media.after(hit, ls.wi, s->medium);
        ++counters->rays;
        ++counters->shadow_rays;
        const float pdf_light = select_prob * ls.pdf_w;
        const float w = ls.delta ? 1.f : combine_mis(settings, pdf_light, bsdf_pdf(mat, wo, wi, TransportMode::radiance));
        const float scale = fabsf(wi.z) * w / pdf_light;
        s->shadow_pending = true;
        if (sel) {
          Rgb fl[kMaxBsdfLayers];
          eval_layers(mat, layers, selection.split_layers, wo, wi, fl);
          for (int l = 0; l < layers.count; ++l) s->shadow_value[l] = fl[l] * ls.li * scale;
          s->shadow_vertex = s->selected - 1;
        } else {
          s->shadow_value[0] = s->beta * f * ls.li * scale;
          s->shadow_vertex = -1;
          s->shadow_owner = s->owner;
        }
      }
    }
  }

  // Continue by BSDF sampling. At smooth glass before the path's first selectable vertex the
  // branch code picks the lobe instead (pt_continue_path traces the other branch as well); the
  // branch then keeps its lobe's probability as a weight instead of dividing by it.
  BsdfSample bs;
  const Point2 ub{sampler.at(dims::vertex(v, dims::kBsdfU)), sampler.at(dims::vertex(v, dims::kBsdfU + 1))};
  float u_lobe = sampler.at(dims::vertex(v, dims::kLobe));
  float p_reflect = 0.f;
  const bool branch = s->may_split(selection) && bsdf_delta_branches(mat, wo, &p_reflect);
  if (branch) u_lobe = s->take_split() ? p_reflect + 0.5f * (1.f - p_reflect) : 0.5f * p_reflect;
  if (!bsdf_sample(mat, wo, u_lobe, ub, TransportMode::radiance, &bs)) return PtNext::end;
  if (branch) bs.weight *= bs.pdf_w;
  s->abs_beta *= bs.weight;
  if (caustics) s->caustic_chain = gathers ? 1 : (s->caustic_chain != 0 ? 2 : 0);
  if (sel) {
    Rgb fl[kMaxBsdfLayers];
    eval_layers(mat, layers, selection.split_layers, wo, bs.wi, fl);
    for (int l = 0; l < layers.count; ++l) sel->continuation[l] = fl[l] * (fabsf(bs.wi.z) / bs.pdf_w);
    s->owner = s->selected - 1;
    s->beta = Rgb(1.f);
  } else {
    s->beta *= bs.weight;
  }
  if (is_black(s->abs_beta)) return PtNext::end;
  s->after_delta = bs.delta;
  s->prev_bsdf_pdf = bs.pdf_w;
  s->prev_p = hit.p;
  s->prev_ns = hit.ns;

  if (settings.roulette_start >= 0 && segments >= settings.roulette_start) {
    const float q = fminf(1.f, max_component(s->abs_beta));
    if (sampler.at(dims::vertex(v, dims::kRoulette)) >= q) return PtNext::end;
    s->beta *= 1.f / q;
    s->abs_beta *= 1.f / q;
  }
  const Vec3 wi_world = frame.to_world(bs.wi);
  s->medium = scene.media.after(hit, wi_world, s->medium);
  s->ray = spawn_ray(hit.p, hit.ng, wi_world, scene.ray_epsilon, hit.time);
  ++s->segments;
  return PtNext::extend;
}

// The medium segment a scattering vertex lies on, for its light sample's MIS weight against the
// segment's equiangular light sample: `equiangular` false where the segment has none.
struct PtMediumSegment {
  bool equiangular = false;
  float tmax = kInfinity;      // where the segment ends (the next surface, or infinity)
  float flight_density = 0.f;  // the density of the vertex's distance (FreeFlight::density)
};

// Whether the path's segment in its medium gets an equiangular light sample: one of its first
// PtSettings::equiangular_segments, in a homogeneous medium that scatters, with next event
// estimation, where a vertex on it could still sample a light (not past the path's length limit;
// not when the path ends at its selected vertex for a filter's query, whose answer stands for all
// the light scattered there).
PS_INLINE bool equiangular_applies(const SceneView& scene, const PtSettings& settings, const PtPathState& s, int max_segments,
                                   bool query_only) {
  if (s.segments > settings.equiangular_segments || !settings.nee || query_only || scene.num_lights == 0 || s.segments >= max_segments)
    return false;
  const Medium& m = scene.media.media[s.medium];
  return m.type == MediumType::homogeneous && !is_black(m.albedo);
}

// The density with which the equiangular technique of segment `ray` (up to tmax) picks light li and
// the distance t, given the light sample's point `sampled`: the light's probability in the scene's
// selection (by power, or uniform: the same anywhere along the segment, and no light tree to walk)
// times the equiangular density around the light's anchor (scene/light_sampling.h); 0 for distant
// and environment lights.
PS_INLINE float equiangular_light_density(const SceneView& scene, const Ray& ray, float tmax, uint32_t li, const Vec3& sampled,
                                          float t) {
  Vec3 anchor;
  if (!equiangular_anchor_of_sample(scene, scene.lights[li], sampled, &anchor)) return 0.f;
  return scene.light_selection.probability(li) * equiangular_pdf(equiangular_frame(ray.o, ray.d, ray.tmin, tmax, anchor), t);
}

// Equiangular sampling (media/equiangular.h; Kulla and Fajardo 2012): a light (by the scene's
// selection distribution) and its anchor (the point its light sample will take, or a sphere's
// centre), then a distance along the segment with density proportional to 1 / distance^2 from the
// anchor, and there a light sample with the same numbers as the anchor's and the single scattering
// towards it (a shadow ray through the media). Its MIS weight shares the light sample's part of the
// distance-sampled vertex's weight (pt_on_medium) with that vertex's light sample: the balance (or
// power) of the two distance densities, the light sample's own density being a factor of both. Its
// numbers come from the path's medium stream. The estimate goes where the path's radiance goes (the
// prefix, or the owning selected vertex's `after`).
// `collide`: the segment's scattering distance is drawn by the scatter branch (camera splits).
template <typename Tracer>
PS_HD void pt_equiangular_light(const SceneView& scene, const Tracer& tracer, const PtSettings& settings, float tmax,
                                bool collide, PathCounters* counters, PtPathState* s) {
  const Ray& ray = s->ray;
  Pcg32& rng = s->medium_rng;
  const float u_select = rng.next_float();
  const Point2 ul{rng.next_float(), rng.next_float()};
  const float u_t = rng.next_float();
  float select_power;
  const uint32_t li = scene.light_selection.sample(u_select, &select_power);
  const Light& light = scene.lights[li];
  Vec3 anchor;
  if (!equiangular_anchor(scene, light, ray.time, ul, &anchor)) return;
  const EquiangularFrame frame = equiangular_frame(ray.o, ray.d, ray.tmin, tmax, anchor);
  if (!frame.valid()) return;
  float pdf_t;
  const float t = sample_equiangular(frame, u_t, ray.tmin, tmax, &pdf_t);
  if (!(pdf_t > 0.f) || !(t < tmax)) return;
  const Vec3 x = ray.at(t);
  LightSample ls;
  if (!sample_light(scene, light, x, ray.time, ul, &ls)) return;
  const Medium& m = scene.media.media[s->medium];
  const float phase = hg_phase(dot(ray.d, ls.wi), m.g);
  const float select_x = light_selection_probability_at(scene, x, Vec3(0.f), li);
  const float p_distance = select_x * (collide ? scatter_density<true>(scene.media, s->medium, ray, tmax, s->abs_beta, t)
                                               : scatter_density<false>(scene.media, s->medium, ray, tmax, s->abs_beta, t));
  const float p_equiangular = select_power * pdf_t;
  const float w_light = ls.delta ? 1.f : pt_detail::combine_mis(settings, select_x * ls.pdf_w, phase);
  const float w = w_light * mis_weight(settings.mis, p_equiangular, p_distance);
  if (!(w > 0.f)) return;
  const Rgb scattered = m.albedo * m.sigma_t * medium_transmittance(scene.media, s->medium, ray, t, rng);
  const Ray shadow = spawn_shadow_ray(x, Vec3(0.f), ls.wi, ls.dist, scene.ray_epsilon, ray.time);
  ++counters->rays;
  ++counters->shadow_rays;
  const Rgb visible = shadow_visibility(scene, tracer, shadow, s->medium, &rng, counters);
  if (is_black(visible)) return;
  s->radiance() += s->beta * scattered * ls.li * visible * (phase * w / (p_equiangular * ls.pdf_w));
}

// The path's ray scatters in its medium at distance `t` (media/free_flight.h; the flight's weight is
// in s->beta already): next event estimation through the media (its shadow ray's transmittance is
// pt_resolve_shadow's), then a new direction from the Henyey-Greenstein phase function, whose pdf
// takes the place of the BSDF's in MIS. A medium vertex is a path vertex like a surface's: it counts
// a segment and uses its vertex's sampler dimensions.
// Path space filtering selects it like a diffuse surface vertex (2014 paper sec. 3; docs/media.md): one
// layer of its own (kLayerMedium, never averaged with surfaces) whose albedo stays in the
// throughput (the flight's weight carries it), so the filter averages the phase-weighted incident
// radiance; its "normal" is the reversed incident direction, so the hashed filter jitters it across
// the ray, as a pixel's footprint spreads, and its normal bin and the consistent filter's direction
// test separate vertices by the axis of the phase lobe. Its roughness 1 - |g| keys strongly
// anisotropic media by direction as glossy surfaces are.
// With equiangular sampling on the segment (PtMediumSegment) the light sample's MIS weight against
// the phase function is shared with the segment's equiangular light sample (pt_equiangular_light).
template <typename Tracer>
PS_HD PtNext pt_on_medium(const SceneView& scene, const Tracer& tracer, const Sampler& sampler, const PtSettings& settings,
                          float t, const PtMediumSegment& segment, PathCounters* counters, PtPathState* s,
                          const VisibilityProbes& probes, bool query_only) {
  using namespace pt_detail;
  const int max_segments = settings.max_segments > 0 ? settings.max_segments : scene.max_path_segments;
  const Ray ray = s->ray;
  const int segments = s->segments;
  const Vec3 p = ray.at(t);
  const float g = scene.media.media[s->medium].g;
  s->prev_distance = s->path_distance;
  s->path_distance += t;
  if (segments >= max_segments) return PtNext::end;
  const uint32_t v = uint32_t(segments - 1);

  OpenVertex* sel = nullptr;
  const VertexSelection& selection = settings.selection;
  if (selection.mode != VertexSelectionMode::none) {
    BsdfLayers layers;
    layers.count = 1;
    layers.id[0] = kLayerMedium;
    layers.albedo[0] = Rgb(1.f);
    layers.roughness[0] = 1.f - fabsf(g);
    if (is_selectable(layers, selection)) {
      ++s->diffuse_index;
      if (wants_vertex(selection, s->diffuse_index, s->selected)) {
        SurfaceHit at;  // the vertex as a surface would be: its normal faces the incident ray
        at.p = p;
        at.ng = at.ns = -ray.d;
        at.time = ray.time;
        sel = open_selected_vertex(scene, tracer, at, -ray.d, segments, layers, probes, counters, s);
        if (query_only && !selects_more(selection, s->selected)) return PtNext::end;
      }
    }
  }

  if (settings.nee && scene.num_lights > 0) {
    float select_prob;
    const uint32_t li = select_light_at(scene, p, Vec3(0.f), sampler.at(dims::vertex(v, dims::kLightSelect)), &select_prob);
    LightSample ls;
    const Point2 ul{sampler.at(dims::vertex(v, dims::kLightU)), sampler.at(dims::vertex(v, dims::kLightU + 1))};
    if (li != LightTreeView::kNone && sample_light(scene, scene.lights[li], p, ray.time, ul, &ls)) {
      const float phase = hg_phase(dot(ray.d, ls.wi), g);
      s->shadow_ray = spawn_shadow_ray(p, Vec3(0.f), ls.wi, ls.dist, scene.ray_epsilon, ray.time);
      s->shadow_medium = s->medium;
      ++counters->rays;
      ++counters->shadow_rays;
      const float pdf_light = select_prob * ls.pdf_w;
      float w = ls.delta ? 1.f : combine_mis(settings, pdf_light, phase);
      if (segment.equiangular) {
        const float equiangular = equiangular_light_density(scene, ray, segment.tmax, li, ls.p, t);
        if (equiangular > 0.f) w *= mis_weight(settings.mis, segment.flight_density * select_prob, equiangular);
      }
      s->shadow_pending = true;
      if (sel) {
        s->shadow_value[0] = ls.li * (phase * w / pdf_light);
        s->shadow_vertex = s->selected - 1;
      } else {
        s->shadow_value[0] = s->beta * ls.li * (phase * w / pdf_light);
        s->shadow_vertex = -1;
        s->shadow_owner = s->owner;
      }
    }
  }

  const Point2 u{sampler.at(dims::vertex(v, dims::kBsdfU)), sampler.at(dims::vertex(v, dims::kBsdfU + 1))};
  const Vec3 wi = hg_sample(ray.d, g, u);
  if (sel) {  // exact sampling: phase / pdf = 1
    sel->continuation[0] = Rgb(1.f);
    s->owner = s->selected - 1;
    s->beta = Rgb(1.f);
  }
  s->after_delta = false;
  s->prev_bsdf_pdf = hg_phase(dot(ray.d, wi), g);
  s->prev_p = p;
  s->prev_ns = Vec3(0.f);
  if (settings.roulette_start >= 0 && segments >= settings.roulette_start) {
    const float q = fminf(1.f, max_component(s->abs_beta));
    if (sampler.at(dims::vertex(v, dims::kRoulette)) >= q) return PtNext::end;
    s->beta *= 1.f / q;
    s->abs_beta *= 1.f / q;
  }
  s->ray = Ray{p, wi, 0.f, kInfinity, ray.time};
  ++s->segments;
  return PtNext::extend;
}

// The pending shadow ray's answer: the next event estimate counts unless it was blocked.
PS_INLINE void pt_resolve_shadow(PtPathState* s, bool occluded) {
  if (!s->shadow_pending) return;
  s->shadow_pending = false;
  if (occluded) return;
  if (s->shadow_vertex >= 0) {
    pt_detail::OpenVertex& o = s->open[s->shadow_vertex];
    for (int l = 0; l < o.layers.count; ++l) o.nee[l] += s->shadow_value[l];
  } else {
    (s->shadow_owner < 0 ? s->prefix : s->open[s->shadow_owner].after) += s->shadow_value[0];
  }
}

// The same with the shadow ray's visibility as a factor (integrators/common/media_steps.h: the
// transmittance through media, or 0 or 1): multiplying by 1 changes no bit of the estimate.
PS_INLINE void pt_resolve_shadow(PtPathState* s, const Rgb& transmittance) {
  if (!s->shadow_pending) return;
  for (int l = 0; l < kMaxBsdfLayers; ++l) s->shadow_value[l] *= transmittance;
  pt_resolve_shadow(s, is_black(transmittance));
}

// The ended path as a PathSample: its prefix and its selected vertices' records. With `append` they
// are added to what `out` holds already (another branch of the same camera path).
PS_INLINE void pt_finish(PtPathState* s, PathSample* out, bool append = false) {
  if (append) {
    out->prefix += s->prefix;
  } else {
    out->prefix = s->prefix;
    out->count = 0;
  }
  pt_detail::close_vertices(s->open, s->selected, out);
}

namespace pt_detail {
// Whether the path splits at its free flight through a medium (the same budget as the splits at
// smooth glass: VertexSelection::camera_splits), before its first selectable vertex.
PS_INLINE bool splits_in_medium(const SceneView& scene, const VertexSelection& selection, const PtPathState& s) {
  return selection.medium_splits && s.may_split(selection) && medium_scatters(scene.media, s.medium);
}

// One branch of a camera path (its split code) from its traced camera ray; appends its prefix and
// records to *out when `append`. Returns the number of camera-side splits it passed.
template <typename Tracer>
PS_HD int pt_trace_branch(const SceneView& scene, const Tracer& tracer, const Sampler& sampler, const Ray& ray, bool found,
                          const SurfaceHit& first, const PtSettings& settings, PathCounters* counters, PathSample* out,
                          const VisibilityProbes& probes, bool query_only, const CausticMapView* caustics, uint32_t split_code,
                          bool append) {
  OpenVertex open[kMaxSelectedVertices];
  PtPathState s;
  pt_begin(&s, ray, open, split_code);
  const int max_segments = settings.max_segments > 0 ? settings.max_segments : scene.max_path_segments;
  const bool media = scene.media.any();
  if (media) {
    s.medium = scene.media.camera_medium;
    s.medium_rng = Pcg32(sampler.bits(dims::kMediumStream), 0u);
  }
  SurfaceHit hit = first;
  for (;;) {
    if (media && s.medium != kVacuum) {
      const float tmax = found ? hit.t : kInfinity;
      // A camera-side split in the medium: bit 0 scatters (the collision drawn before tmax), bit 1
      // passes (free_flight.h). The pass branch never scatters here, so it has no equiangular sample.
      const bool split = splits_in_medium(scene, settings.selection, s);
      const bool passes = split && s.take_split();
      PtMediumSegment segment;
      segment.equiangular = !passes && equiangular_applies(scene, settings, s, max_segments, query_only);
      segment.tmax = tmax;
      if (segment.equiangular) pt_equiangular_light(scene, tracer, settings, tmax, split, counters, &s);
      FreeFlight flight;
      if (passes) {
        flight = sample_pass_branch(scene.media, s.medium, s.ray, tmax, s.medium_rng);
      } else if (split) {
        flight = sample_scatter_branch(scene.media, s.medium, s.ray, tmax, s.abs_beta, s.medium_rng);
      } else {
        flight = sample_free_flight(scene.media, s.medium, s.ray, tmax, s.abs_beta, s.medium_rng);
      }
      if (flight.event == MediumEvent::absorbed) break;
      s.beta *= flight.weight;
      s.abs_beta *= flight.weight;
      if (flight.event == MediumEvent::scattered) {
        segment.flight_density = flight.density;
        const PtNext next = pt_on_medium(scene, tracer, sampler, settings, flight.t, segment, counters, &s, probes, query_only);
        if (s.shadow_pending)
          pt_resolve_shadow(&s, shadow_visibility(scene, tracer, s.shadow_ray, s.shadow_medium, &s.medium_rng, counters));
        if (next == PtNext::end) break;
        ++counters->rays;
        found = tracer.intersect(s.ray, &hit);
        continue;
      }
    }
    if (!found) {
      pt_on_miss(scene, settings, &s, caustics);
      break;
    }
    if (media && scene.materials[hit.material].type == MaterialType::interface) {
      // A surface that only bounds media: the ray goes on unchanged, in the medium beyond it.
      s.medium = scene.media.after(hit, s.ray.d, s.medium);
      s.path_distance += hit.t;
      s.ray = spawn_ray(hit.p, hit.ng, s.ray.d, scene.ray_epsilon, s.ray.time);
      ++counters->rays;
      found = tracer.intersect(s.ray, &hit);
      continue;
    }
    const PtNext next = pt_on_hit(scene, tracer, sampler, settings, hit, counters, &s, probes, query_only, caustics);
    if (s.shadow_pending)
      pt_resolve_shadow(&s, shadow_visibility(scene, tracer, s.shadow_ray, s.shadow_medium, &s.medium_rng, counters));
    if (next == PtNext::end) break;
    ++counters->rays;
    found = tracer.intersect(s.ray, &hit);
  }
  pt_finish(&s, out, append);
  return s.splits;
}
}  // namespace pt_detail

// The path whose camera ray `ray` was traced already: `found` says whether it hit, at `first`. The
// CPU traces a chunk's camera rays together as one coherent stream (PtIntegrator), then continues
// each path here, one ray at a time, exactly as pt_trace_path would.
// With camera splits (VertexSelection::camera_splits) every branch of the path is traced, depth
// first: branch `code` passed `taken` splits and chose by bits [from, taken) the reflection, so each
// of those bits set gives a branch not traced yet. Each branch repeats the same sampler dimensions
// after the camera ray (the branches are correlated, each is unbiased) and re-traces the segments
// before its own splits; the camera ray is traced and counted once.
template <typename Tracer>
PS_HD void pt_continue_path(const SceneView& scene, const Tracer& tracer, const Sampler& sampler, Ray ray, bool found,
                            const SurfaceHit& first, const PtSettings& settings, PathCounters* counters, PathSample* out,
                            const VisibilityProbes& probes = {}, bool query_only = false,
                            const CausticMapView* caustics = nullptr) {
  ++counters->rays;
  // Branches waiting: at most d (d + 1) / 2 of them for d splits.
  constexpr int kWaiting = kMaxCameraSplits * (kMaxCameraSplits + 1) / 2;
  uint32_t codes[kWaiting];
  int from[kWaiting];
  codes[0] = 0u;
  from[0] = 0;
  int pending = 1;
  bool append = false;
  while (pending > 0) {
    --pending;
    const uint32_t code = codes[pending];
    const int first_free = from[pending];
    const int taken = pt_detail::pt_trace_branch(scene, tracer, sampler, ray, found, first, settings, counters, out, probes,
                                                 query_only, caustics, code, append);
    append = true;
    for (int k = taken - 1; k >= first_free; --k) {
      codes[pending] = code | (1u << k);
      from[pending] = k + 1;
      ++pending;
    }
  }
}

// `probes`: the visibility weight's rays at each selected vertex (none by default). `query_only`: the
// path ends at its last selectable vertex, whose records then carry no contribution (their
// contributions come from a filter's query: the anti-aliasing paths of Keller et al. 2014, sec. 3).
// `caustics`: a caustic photon map gathered at every sufficiently diffuse vertex (the selection's
// roughness test); the path then leaves out the emission it reaches, and the next event estimates it
// makes, from such a vertex through vertices that are not selectable only (those paths are the
// photons'; caustic_photons.h).
template <typename Tracer>
PS_HD void pt_trace_path(const SceneView& scene, const Tracer& tracer, const Sampler& sampler, Ray ray,
                         const PtSettings& settings, PathCounters* counters, PathSample* out,
                         const VisibilityProbes& probes = {}, bool query_only = false,
                         const CausticMapView* caustics = nullptr) {
  SurfaceHit first;
  const bool found = tracer.intersect(ray, &first);
  pt_continue_path(scene, tracer, sampler, ray, found, first, settings, counters, out, probes, query_only, caustics);
}

// Plain path tracing: the unfiltered estimate of one path.
template <typename Tracer>
PS_HD Rgb pt_trace_path(const SceneView& scene, const Tracer& tracer, const Sampler& sampler, const Ray& ray,
                        const PtSettings& settings, PathCounters* counters) {
  PathSample sample;
  pt_trace_path(scene, tracer, sampler, ray, settings, counters, &sample);
  return sample.value();
}

}  // namespace pathspace
