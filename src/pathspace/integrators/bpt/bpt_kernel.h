// Bidirectional path tracing for one pixel (device-safe, templated on the ray caster "Tracer" like
// pt_trace_path): one light subpath and one camera subpath, combined by every strategy (s, t) —
// light hits (s = 0), next event estimation (s = 1), inner connections and camera connections
// (t = 1, splatted as in lt_kernel.h) — with MIS weights from the recursive quantities dVCM / dVC of
// Georgiev et al. 2012 (VCM tech. report, eqs. 31-47, merging terms dropped), as SmallVCM's BPT does.
// Throughput follows Veach 1997 (§10.2); light subpaths use the adjoint shading-normal factor (§5.3).
// Media (docs/media.md): both subpaths sample distances as PT and LT do and store medium vertices
// (phase function for the BSDF, no cosines: a medium vertex's area measure is a volume measure);
// connections carry the transmittance. The MIS weights use the directional densities alone and leave
// the distance sampling's densities out (as pbrt-v3's BDPT does): they still sum to one over the
// strategies of each path, so the estimate is unbiased, though not the balance heuristic of the full
// densities.
// Thin lens: the camera vertex is the sampled lens point; every t = 1 connection samples its own
// lens point with the same density 1 / A_lens, which cancels from the weights (perspective_camera.h).
#pragma once

#include "pathspace/film/splat_film.h"
#include "pathspace/integrators/bpt/bpt_settings.h"
#include "pathspace/integrators/common/camera_sample.h"
#include "pathspace/integrators/common/dimensions.h"
#include "pathspace/integrators/common/light_dimensions.h"
#include "pathspace/integrators/common/light_path_start.h"
#include "pathspace/integrators/common/media_steps.h"
#include "pathspace/media/henyey_greenstein.h"
#include "pathspace/stats/path_counters.h"
#include "pathspace/scene/light_emission.h"
#include "pathspace/materials/bsdf.h"
#include "pathspace/sampling/sampler.h"
#include "pathspace/scene/shading_material.h"

namespace pathspace {

// Where a pixel's contributions go. Camera-side strategies (t >= 2) are returned to the caller (one
// camera sample per pixel); t = 1 is splatted, already divided by the number of light paths.
struct BptFilms {
  SplatFilmView splats;
  const SplatFilmView* strategies = nullptr;  // bpt_strategy_count(strategy_max_length) images, or nullptr
  int strategy_max_length = 0;
  uint32_t light_paths = 1;                   // light subpaths per pass (= pixels: one per camera path)
};

namespace bpt_detail {

// MIS quantities are kept already raised to the heuristic's power (SmallVCM's Mis()), so that the
// recursions of the tech. report hold for the balance (x) and power (x^2) heuristics alike.
PS_INLINE float mis(MisHeuristic h, float x) { return h == MisHeuristic::power ? x * x : x; }

// A stored light-subpath vertex on a surface with a non-delta lobe (only those can be connected).
struct LightVertex {
  Vec3 p, ng, ns;
  Vec3 wo;             // world, unit, towards the previous light-subpath vertex
  Rgb beta;            // light-subpath throughput up to this vertex, its BSDF excluded
  float cos_in = 0.f;  // |wo . ng|
  float dvcm = 0.f, dvc = 0.f;
  uint32_t material = 0;
  Point2 uv;           // texture coordinates (the material is shaded again at connection time)
  int segments = 0;    // segments from the light to this vertex (1: first hit)
  // Media: a vertex in a medium (ng, ns zero; its phase asymmetry g), or the medium the path arrived
  // in at a surface and the media the surface separates.
  bool in_medium = false;
  float g = 0.f;
  int32_t medium = kVacuum;
  MediumInterface iface;
};

// The medium a connection leaving a vertex along d starts in.
PS_INLINE int32_t connection_medium(bool in_medium, int32_t medium, const MediumInterface& iface, const Vec3& ng,
                                    const Vec3& d) {
  return in_medium ? medium : medium_after(iface, ng, d, medium);
}

PS_INLINE Vec3 area_light_normal(const SceneView& scene, const Light& l, const Vec3& p, float time) {
  if (l.type == LightType::area_triangle) {
    const TriangleVertices tv = triangle_at(scene, scene.triangles[l.shape], time);
    return triangle_normal(tv.p0, tv.p1, tv.p2);
  }
  return sphere_normal(scene.spheres[l.shape], p);
}

// Adds v to the (s, t) strategy image when one is kept.
PS_INLINE void record(const BptFilms& films, int s, int t, uint32_t pixel, const Rgb& v) {
  if (!films.strategies || s + t - 1 > films.strategy_max_length) return;
  films.strategies[bpt_strategy_index(s, t)].add(pixel, v);
}

// A t = 1 contribution at raster (rx, ry), spread by the camera's pixel filter (camera/pixel_filter.h).
PS_INLINE void splat(const BptFilms& films, const PixelFilter& filter, int s, float rx, float ry, const Rgb& v) {
  for_each_filter_pixel(filter, films.splats.width, films.splats.height, rx, ry, [&](uint32_t pixel, float w) {
    const Rgb wv = w == 1.f ? v : v * w;
    films.splats.add(pixel, wv);
    record(films, s, 1, pixel, wv);
  });
}

// The camera connection (t = 1) of point p: projected through the lens sample, kept when the pixel
// filter reaches the image from there (unclipped for a wide filter, as LT's).
PS_INLINE bool connect_to_film(const PerspectiveCamera& cam, const Vec3& p, Point2 lens_u, CameraProjection* pr) {
  return cam.project(p, lens_u, pr) && filter_reaches_image(cam.filter, cam.width, cam.height, pr->rx, pr->ry);
}

// A light-subpath vertex in a medium at p, reached along `ray`: its camera connection (t = 1: phase
// function and transmittance, no cosines), its storage for inner connections, then a direction from
// the phase function (exact sampling: weight 1; reverse density = forward density) and Russian
// roulette. False when the subpath ends.
template <typename Tracer>
PS_HD bool light_medium_vertex(const SceneView& scene, const Tracer& tracer, const Sampler& sampler, const BptSettings& st,
                               const PerspectiveCamera& cam, const BptFilms& films, Ray* ray_io, const Vec3& p,
                               int32_t medium, int segments, int max_segments, float beta0, Pcg32* rng,
                               PathCounters* counters, Rgb* beta, float* dvcm, float* dvc, LightVertex* verts, int* stored) {
  const Ray ray = *ray_io;
  const MisHeuristic h = st.mis;
  const float n_light = float(films.light_paths), inv_paths = 1.f / n_light;
  const float g = scene.media.media[medium].g;
  CameraProjection pr;
  if (connect_to_film(cam, p, connection_lens_sample(cam, sampler, uint32_t(segments)), &pr)) {
    ++counters->rays;
    ++counters->shadow_rays;
    prefetch_filter_splat(films.splats, cam.filter, pr.rx, pr.ry);
    const Rgb tr = shadow_visibility(scene, tracer, spawn_shadow_ray(p, Vec3(0.f), pr.wi, pr.dist, scene.ray_epsilon, ray.time),
                              medium, rng, counters);
    if (!is_black(tr)) {
      const float phase = hg_phase(dot(ray.d, pr.wi), g);
      const float w_light = mis(h, pr.factor / n_light) * (*dvcm + *dvc * mis(h, phase));
      splat(films, cam.filter, segments + 1, pr.rx, pr.ry, *beta * tr * (phase * pr.factor * inv_paths / (1.f + w_light)));
    }
  }
  if (segments + 2 <= max_segments) {
    LightVertex& v = verts[(*stored)++];
    v.p = p;
    v.ng = v.ns = Vec3(0.f);
    v.wo = -ray.d;
    v.beta = *beta;
    v.cos_in = 1.f;
    v.dvcm = *dvcm;
    v.dvc = *dvc;
    v.segments = segments;
    v.in_medium = true;
    v.g = g;
    v.medium = medium;
    v.iface = MediumInterface{};
  }
  if (segments + 1 >= max_segments) return false;
  const uint32_t vi = uint32_t(segments - 1);
  const Point2 u{sampler.at(light_dims::vertex(vi, light_dims::kBsdfU)), sampler.at(light_dims::vertex(vi, light_dims::kBsdfU + 1))};
  const Vec3 wi = hg_sample(ray.d, g, u);
  const float pdf = hg_phase(dot(ray.d, wi), g);
  *dvc = mis(h, 1.f / pdf) * (*dvc * mis(h, pdf) + *dvcm);
  *dvcm = mis(h, 1.f / pdf);
  if (st.roulette_start >= 0 && segments >= st.roulette_start) {
    const float q = fminf(1.f, max_component(*beta) / beta0);
    if (sampler.at(light_dims::vertex(vi, light_dims::kRoulette)) >= q) return false;
    *beta *= 1.f / q;
  }
  *ray_io = Ray{p, wi, 0.f, kInfinity, ray.time};
  return true;
}

// Traces the light subpath, splats its camera connections (t = 1, including the emitter itself:
// s = 1, t = 1) and stores the connectible vertices that can still take part in an inner connection
// (at most max_segments - 2 segments from the light). Returns the number stored.
template <typename Tracer>
PS_HD int trace_light_subpath(const SceneView& scene, const Tracer& tracer, const Sampler& sampler, const BptSettings& st,
                              int max_segments, float time, const BptFilms& films, PathCounters* counters,
                              LightVertex* verts) {
  if (scene.num_lights == 0) return 0;
  const PerspectiveCamera cam = camera_at(scene, time);
  const MisHeuristic h = st.mis;
  const float n_light = float(films.light_paths), inv_paths = 1.f / n_light;

  LightPathStart start;
  if (!start_light_path(scene, sampler, time, &start)) return 0;
  const Light& light = *start.light;
  const EmissionSample& e = start.emission;
  const float select_prob = start.select_prob;
  const float emit_pdf_a = e.pdf_a * select_prob;  // of the origin (on the disk for infinite lights)
  const float emit_pdf = emit_pdf_a * e.pdf_w;     // of origin and direction
  const bool delta_light = e.delta_position || e.delta_direction;
  const bool media = scene.media.any();
  Pcg32 rng;
  if (media) rng = Pcg32(sampler.bits(light_dims::kMediumStream), 0u);

  // s = 1, t = 1: the emitter point seen by the camera. Its rival is s = 0 (the camera ray hits the
  // point, density camera_pdf_a per camera sample) against n_light light paths.
  if (is_area_light(light)) {
    CameraProjection pr;
    if (connect_to_film(cam, e.p, connection_lens_sample(cam, sampler, 0), &pr)) {
      const Rgb le = area_light_radiance(scene, light, e.ng, pr.wi, e.uv);
      if (!is_black(le)) {
        ++counters->rays;
        ++counters->shadow_rays;
        prefetch_filter_splat(films.splats, cam.filter, pr.rx, pr.ry);
        const Rgb tr = shadow_visibility(scene, tracer, spawn_shadow_ray(e.p, e.ng, pr.wi, pr.dist, scene.ray_epsilon, time),
                                  media ? light_path_medium(scene, start, pr.wi) : kVacuum, &rng, counters);
        if (!is_black(tr)) {
          const float cos_light = fabsf(dot(e.ng, pr.wi));
          const float w_light = mis(h, pr.factor * cos_light / (n_light * emit_pdf_a));
          const Rgb c = le * (cos_light / emit_pdf_a * pr.factor * inv_paths / (1.f + w_light));
          splat(films, cam.filter, 1, pr.rx, pr.ry, media ? c * tr : c);
        }
      }
    }
  }
  if (max_segments < 2) return 0;

  Rgb beta = e.weight * (1.f / select_prob);
  const float beta0 = max_component(beta);
  Ray ray = first_light_ray(scene, e);
  // Tech. report eq. 31-33 at the emitted vertex: dVC = cos / p_emit (0 for delta lights, which no
  // camera path can hit). dVCM = p_direct / p_emit needs NEE's density of the origin, which for
  // cone-sampled spheres depends on the point that would sample it, so it is completed at the first hit.
  float dvc = delta_light ? 0.f : mis(h, (e.infinite ? 1.f : fabsf(dot(e.n, e.d))) / emit_pdf);
  float dvcm = 0.f;
  Vec3 prev_p = e.p;
  int stored = 0;
  int32_t medium = media ? light_path_medium(scene, start, e.d) : kVacuum;

  for (int segments = 1; segments < max_segments; ++segments) {
    SurfaceHit hit;
    ++counters->rays;
    float t_medium = 0.f;
    bool in_medium = false;
    if (media) {
      const NextVertex next = next_vertex(scene, tracer, &ray, &medium, &rng, counters, &beta, &hit, &t_medium);
      if (next == NextVertex::missed || next == NextVertex::absorbed) break;
      in_medium = next == NextVertex::medium;
      if (in_medium) hit.p = ray.at(t_medium);
    } else if (!tracer.intersect(ray, &hit)) {
      break;
    }
    const Vec3 wo_world = -ray.d;
    const float cos_in = in_medium ? 1.f : fabsf(dot(wo_world, hit.ng));  // a medium vertex has no cosine
    if (!(cos_in > 0.f)) break;
    // Distances between vertices, not hit.t: the camera side measures the same segments that way.
    const float d2 = distance_squared(hit.p, prev_p);
    if (segments == 1) {
      float direct_pdf = select_prob;  // point and directional lights: NEE picks the light's only point/direction
      if (is_area_light(light)) {
        direct_pdf *= light_pdf(scene, light, hit.p, e.p, e.ng, time) * fabsf(dot(e.ng, e.d)) / d2;
      } else if (light.type == LightType::environment) {
        direct_pdf *= environment_pdf(scene, -e.d);
      }
      dvcm = mis(h, direct_pdf / emit_pdf);
      if (!e.infinite) dvcm *= mis(h, d2);  // infinite lights: no distance to the (proxy) origin
    } else {
      dvcm *= mis(h, d2);
    }
    dvcm /= mis(h, cos_in);
    dvc /= mis(h, cos_in);
    if (in_medium) {
      if (!light_medium_vertex(scene, tracer, sampler, st, cam, films, &ray, hit.p, medium, segments, max_segments, beta0,
                               &rng, counters, &beta, &dvcm, &dvc, verts, &stored))
        break;
      prev_p = hit.p;
      continue;
    }

    Material textured;
    const Material& mat = shading_material(scene, hit, &textured);
    const Frame frame(hit.ns);
    const Vec3 wo = frame.to_local(wo_world);
    if (bsdf_has_non_delta(mat)) {
      // t = 1 (PCLT eq. 4 with the LT kernel's adjoint factor), weighted against all camera-side strategies.
      CameraProjection pr;
      if (connect_to_film(cam, hit.p, connection_lens_sample(cam, sampler, uint32_t(segments)), &pr)) {
        const Vec3 wi = frame.to_local(pr.wi);
        const Rgb f = bsdf_eval(mat, wo, wi, TransportMode::importance);
        if (!is_black(f)) {
          ++counters->rays;
          ++counters->shadow_rays;
          prefetch_filter_splat(films.splats, cam.filter, pr.rx, pr.ry);
          const Rgb tr = shadow_visibility(scene, tracer, spawn_shadow_ray(hit.p, hit.ng, pr.wi, pr.dist, scene.ray_epsilon, time),
                                    scene.media.after(hit, pr.wi, medium), &rng, counters);
          if (!is_black(tr)) {
            // factor * cos_cam: the camera subpath's area density of this vertex from the lens point.
            const float cos_cam = fabsf(dot(pr.wi, hit.ng));
            const float pdf_rev = bsdf_pdf(mat, wi, wo, TransportMode::radiance);
            const float w_light = mis(h, pr.factor * cos_cam / n_light) * (dvcm + dvc * mis(h, pdf_rev));
            const float scale = fabsf(wo.z) * cos_cam / cos_in * pr.factor * inv_paths / (1.f + w_light);
            const Rgb c = beta * f * scale;
            splat(films, cam.filter, segments + 1, pr.rx, pr.ry, media ? c * tr : c);
          }
        }
      }
      if (segments + 2 <= max_segments) {
        LightVertex& v = verts[stored++];
        v.p = hit.p;
        v.ng = hit.ng;
        v.ns = hit.ns;
        v.wo = wo_world;
        v.beta = beta;
        v.cos_in = cos_in;
        v.dvcm = dvcm;
        v.dvc = dvc;
        v.material = hit.material;
        v.uv = hit.uv;
        v.segments = segments;
        v.in_medium = false;
        v.medium = medium;
        v.iface = scene.media.interface_at(hit);
      }
    }
    if (segments + 1 >= max_segments) break;  // a further vertex could not connect within the limit

    BsdfSample bs;
    const uint32_t vi = uint32_t(segments - 1);
    const Point2 ub{sampler.at(light_dims::vertex(vi, light_dims::kBsdfU)), sampler.at(light_dims::vertex(vi, light_dims::kBsdfU + 1))};
    if (!bsdf_sample(mat, wo, sampler.at(light_dims::vertex(vi, light_dims::kLobe)), ub, TransportMode::importance, &bs)) break;
    const Vec3 wi_world = frame.to_world(bs.wi);
    const float wi_ns = fabsf(bs.wi.z);
    const float cos_out = fabsf(dot(wi_world, hit.ng));
    if (!(wi_ns > 0.f) || !(cos_out > 0.f)) break;
    beta *= bs.weight * (fabsf(wo.z) * cos_out / (cos_in * wi_ns));
    if (is_black(beta) || !all_finite(beta)) break;
    if (bs.delta) {
      // Tech. report eqs. 53-55: a Dirac vertex cannot be connected, and its forward and reverse
      // (discrete) pdfs cancel.
      dvcm = 0.f;
      dvc *= mis(h, cos_out);
    } else {
      const float pdf_rev = bsdf_pdf(mat, bs.wi, wo, TransportMode::radiance);
      dvc = mis(h, cos_out / bs.pdf_w) * (dvc * mis(h, pdf_rev) + dvcm);
      dvcm = mis(h, 1.f / bs.pdf_w);
    }
    // Russian roulette is left out of the MIS densities (the weights still sum to one per path).
    if (st.roulette_start >= 0 && segments >= st.roulette_start) {
      const float q = fminf(1.f, max_component(beta) / beta0);
      if (sampler.at(light_dims::vertex(vi, light_dims::kRoulette)) >= q) break;
      beta *= 1.f / q;
    }
    prev_p = hit.p;
    medium = scene.media.after(hit, wi_world, medium);
    ray = spawn_ray(hit.p, hit.ng, wi_world, scene.ray_epsilon, time);
  }
  return stored;
}

// The camera-side state at a connectible vertex.
struct CameraVertex {
  const Material* mat;  // null at a medium vertex
  Frame frame;
  Vec3 p, ng, wo;  // wo local (surfaces)
  Rgb beta;
  float dvcm, dvc;
  float time;  // the sample's (camera and light subpath share it; scene/motion.h)
  // Media: a vertex in a medium (its phase asymmetry g, wo_world towards the previous vertex), or the
  // medium the path arrived in at a surface and the media the surface separates.
  bool in_medium = false;
  float g = 0.f;
  Vec3 wo_world;
  int32_t medium = kVacuum;
  MediumInterface iface;
  Pcg32* rng = nullptr;  // the camera subpath's stream (transmittance of connections)
};

// s = 1: next event estimation from camera vertex z, weighted against BSDF sampling (s = 0) and the
// light subpath strategies (s >= 2, tech. report eqs. 44-45).
template <typename Tracer>
PS_HD Rgb connect_to_light(const SceneView& scene, const Tracer& tracer, const Sampler& sampler, uint32_t vi, MisHeuristic h,
                           const CameraVertex& z, PathCounters* counters) {
  float select_prob;
  const uint32_t li = scene.light_selection.sample(sampler.at(dims::vertex(vi, dims::kLightSelect)), &select_prob);
  if (!(select_prob > 0.f)) return {};
  const Light& light = scene.lights[li];
  LightSample ls;
  const Point2 ul{sampler.at(dims::vertex(vi, dims::kLightU)), sampler.at(dims::vertex(vi, dims::kLightU + 1))};
  if (!sample_light(scene, light, z.p, z.time, ul, &ls)) return {};
  const Vec3 wi = z.in_medium ? ls.wi : z.frame.to_local(ls.wi);
  const float phase = z.in_medium ? hg_phase(dot(-z.wo_world, ls.wi), z.g) : 0.f;  // symmetric in its directions
  const Rgb f = z.in_medium ? Rgb(phase) : bsdf_eval(*z.mat, z.wo, wi, TransportMode::radiance);
  if (is_black(f)) return {};
  const float cos_z = z.in_medium ? 1.f : fabsf(dot(ls.wi, z.ng));
  // Emission density of the light vertex towards z, in z's area measure, over NEE's density of the
  // light vertex (area measure; solid angle for infinite lights). Light selection cancels.
  float pa, pw, emit_to_z, direct;
  if (is_area_light(light)) {
    const Vec3 n = area_light_normal(scene, light, ls.p, z.time);
    emission_pdf(scene, light, ls.p, n, -ls.wi, z.time, &pa, &pw);
    emit_to_z = pa * pw * cos_z;
    direct = ls.pdf_w * fabsf(dot(n, ls.wi));  // both over dist^2, which cancels
  } else {
    emission_pdf(scene, light, ls.p, ls.wi, -ls.wi, z.time, &pa, &pw);
    emit_to_z = pa * pw * cos_z;
    if (is_point_light(light)) emit_to_z /= ls.dist * ls.dist;
    direct = ls.pdf_w;  // 1 for delta lights, the sphere pdf for the environment
  }
  if (!(direct > 0.f)) return {};
  const float pdf_light_w = select_prob * ls.pdf_w;
  const float cam_dir = ls.delta ? 0.f : (z.in_medium ? phase : bsdf_pdf(*z.mat, z.wo, wi, TransportMode::radiance));
  const float cam_rev = z.in_medium ? phase : bsdf_pdf(*z.mat, wi, z.wo, TransportMode::importance);
  const float w_light = mis(h, cam_dir / pdf_light_w);
  const float w_camera = mis(h, emit_to_z / direct) * (z.dvcm + z.dvc * mis(h, cam_rev));
  ++counters->rays;
  ++counters->shadow_rays;
  const Rgb tr = shadow_visibility(scene, tracer, spawn_shadow_ray(z.p, z.ng, ls.wi, ls.dist, scene.ray_epsilon, z.time),
                            connection_medium(z.in_medium, z.medium, z.iface, z.ng, ls.wi), z.rng, counters);
  if (is_black(tr)) return {};
  const Rgb c = f * ls.li * ((z.in_medium ? 1.f : fabsf(wi.z)) / (pdf_light_w * (w_light + 1.f + w_camera)));
  return scene.media.any() ? c * tr : c;
}

// s >= 2, t >= 2: connects camera vertex z to light vertex y (tech. report eqs. 37-41). The light
// side gets the adjoint shading-normal factor, the camera side f |cos_ns| as in PT.
template <typename Tracer>
PS_HD Rgb connect_vertices(const SceneView& scene, const Tracer& tracer, MisHeuristic h, const CameraVertex& z,
                           const LightVertex& y, PathCounters* counters) {
  const Vec3 d = y.p - z.p;
  const float d2 = length_squared(d);
  if (!(d2 > 0.f)) return {};
  const float dist = sqrtf(d2);
  const Vec3 dir = d / dist;  // from z towards y
  // Medium vertices: the phase function (symmetric in its directions) in place of the BSDF and its
  // densities, and no cosines.
  const Vec3 wz = z.in_medium ? dir : z.frame.to_local(dir);
  const float phase_z = z.in_medium ? hg_phase(dot(-z.wo_world, dir), z.g) : 0.f;
  const Rgb fz = z.in_medium ? Rgb(phase_z) : bsdf_eval(*z.mat, z.wo, wz, TransportMode::radiance);
  if (is_black(fz)) return {};
  Material textured;
  const Material& ymat = y.in_medium ? textured : shading_material(scene, y.material, y.uv, &textured);
  const Frame yframe(y.in_medium ? -dir : y.ns);
  const Vec3 ywo = yframe.to_local(y.wo), ywi = yframe.to_local(-dir);
  const float phase_y = y.in_medium ? hg_phase(dot(y.wo, dir), y.g) : 0.f;
  const Rgb fy = y.in_medium ? Rgb(phase_y) : bsdf_eval(ymat, ywo, ywi, TransportMode::importance);
  if (is_black(fy)) return {};
  const float cos_z = z.in_medium ? 1.f : fabsf(dot(dir, z.ng)), cos_y = y.in_medium ? 1.f : fabsf(dot(dir, y.ng));
  const float cam_dir_a = (z.in_medium ? phase_z : bsdf_pdf(*z.mat, z.wo, wz, TransportMode::radiance)) * cos_y / d2;
  const float cam_rev = z.in_medium ? phase_z : bsdf_pdf(*z.mat, wz, z.wo, TransportMode::importance);
  const float light_dir_a = (y.in_medium ? phase_y : bsdf_pdf(ymat, ywo, ywi, TransportMode::importance)) * cos_z / d2;
  const float light_rev = y.in_medium ? phase_y : bsdf_pdf(ymat, ywi, ywo, TransportMode::radiance);
  const float w_light = mis(h, cam_dir_a) * (y.dvcm + y.dvc * mis(h, light_rev));
  const float w_camera = mis(h, light_dir_a) * (z.dvcm + z.dvc * mis(h, cam_rev));
  ++counters->rays;
  ++counters->shadow_rays;
  const Rgb tr = shadow_visibility(scene, tracer, spawn_shadow_ray(z.p, z.ng, dir, dist, scene.ray_epsilon, z.time),
                            connection_medium(z.in_medium, z.medium, z.iface, z.ng, dir), z.rng, counters);
  if (is_black(tr)) return {};
  const float g = (z.in_medium ? 1.f : fabsf(wz.z)) * (y.in_medium ? 1.f : fabsf(ywo.z)) * cos_y / (y.cos_in * d2);
  const Rgb c = fz * fy * y.beta * (g / (w_light + 1.f + w_camera));
  return scene.media.any() ? c * tr : c;
}

// Every connection of camera vertex z (reached after `segments` segments): next event estimation
// (s = 1) and the inner connections to the stored light vertices within the path limit, each
// recorded under its strategy and added to *radiance, times z's throughput, one by one.
template <typename Tracer>
PS_HD void connect_camera_vertex(const SceneView& scene, const Tracer& tracer, const Sampler& sampler, uint32_t vi,
                                 MisHeuristic h, const CameraVertex& z, const LightVertex* verts, int nv, int segments,
                                 int max_segments, const BptFilms& films, uint32_t pixel, PathCounters* counters, Rgb* radiance) {
  if (scene.num_lights > 0) {
    const Rgb c = z.beta * connect_to_light(scene, tracer, sampler, vi, h, z, counters);
    *radiance += c;
    record(films, 1, segments + 1, pixel, c);
  }
  for (int k = 0; k < nv && verts[k].segments + 1 + segments <= max_segments; ++k) {
    const Rgb c = z.beta * connect_vertices(scene, tracer, h, z, verts[k], counters);
    *radiance += c;
    record(films, verts[k].segments + 1, segments + 1, pixel, c);
  }
}

}  // namespace bpt_detail

// One BPT sample of `pixel`: returns the camera-side estimate (strategies with t >= 2) and splats
// t = 1 into films.splats. light_sampler must be independent of camera_sampler.
template <typename Tracer>
PS_HD Rgb bpt_trace_pixel(const SceneView& scene, const Tracer& tracer, const Sampler& camera_sampler,
                          const Sampler& light_sampler, const BptSettings& st, uint32_t pixel, const BptFilms& films,
                          PathCounters* counters) {
  using namespace bpt_detail;
  const int max_segments = min_int(st.max_segments > 0 ? st.max_segments : scene.max_path_segments, kBptMaxSegments);
  const MisHeuristic h = st.mis;
  // One time for the whole sample: every connection joins vertices of the same instant, and the
  // camera subpath and the light subpath's camera connections see the camera at it.
  const float time = camera_path_time(scene, camera_sampler);
  const PerspectiveCamera cam = camera_at(scene, time);
  LightVertex verts[kBptMaxSegments];
  const int nv = trace_light_subpath(scene, tracer, light_sampler, st, max_segments, time, films, counters, verts);

  const Sampler& sampler = camera_sampler;
  Ray ray = sample_camera_ray(cam, sampler, pixel, time);
  // Eq. 31 for the camera: the per-pixel density of the direction is the image's times the pixel
  // count. The lens point's density 1 / A_lens is the same for t = 1 and cancels (header comment).
  const float pdf_pixel_w = cam.pdf_direction(ray.d) * float(cam.width) * float(cam.height);
  if (!(pdf_pixel_w > 0.f)) return {};
  float dvcm = mis(h, float(films.light_paths) / pdf_pixel_w), dvc = 0.f;
  Rgb radiance, beta(1.f);
  Vec3 prev_p = ray.o;  // the pinhole or the sampled lens point
  const bool media = scene.media.any();
  Pcg32 rng;
  int32_t medium = kVacuum;
  if (media) {
    rng = Pcg32(sampler.bits(dims::kMediumStream), 0u);
    medium = scene.media.camera_medium;
  }

  for (int segments = 1;; ++segments) {
    SurfaceHit hit;
    ++counters->rays;
    bool found;
    float t_medium = 0.f;
    NextVertex next = NextVertex::surface;
    if (media) {
      next = next_vertex(scene, tracer, &ray, &medium, &rng, counters, &beta, &hit, &t_medium);
      if (next == NextVertex::absorbed) break;
      found = next != NextVertex::missed;
    } else {
      found = tracer.intersect(ray, &hit);
    }
    if (next == NextVertex::medium) {
      const Vec3 p = ray.at(t_medium);
      dvcm *= mis(h, distance_squared(p, prev_p));  // no cosine at a medium vertex
      if (segments >= max_segments) break;
      const uint32_t vi = uint32_t(segments - 1);
      const CameraVertex z{nullptr, Frame(), p,    Vec3(0.f), Vec3(0.f),         beta, dvcm, dvc, time,
                           true,    scene.media.media[medium].g, -ray.d, medium, MediumInterface{}, &rng};
      connect_camera_vertex(scene, tracer, sampler, vi, h, z, verts, nv, segments, max_segments, films, pixel, counters,
                            &radiance);
      // A new direction from the phase function (exact sampling: weight 1, reverse density = forward).
      const Point2 u{sampler.at(dims::vertex(vi, dims::kBsdfU)), sampler.at(dims::vertex(vi, dims::kBsdfU + 1))};
      const Vec3 wi = hg_sample(ray.d, z.g, u);
      const float pdf = hg_phase(dot(ray.d, wi), z.g);
      dvc = mis(h, 1.f / pdf) * (dvc * mis(h, pdf) + dvcm);
      dvcm = mis(h, 1.f / pdf);
      if (st.roulette_start >= 0 && segments >= st.roulette_start) {
        const float q = fminf(1.f, max_component(beta));
        if (sampler.at(dims::vertex(vi, dims::kRoulette)) >= q) break;
        beta *= 1.f / q;
      }
      prev_p = p;
      ray = Ray{p, wi, 0.f, kInfinity, time};
      continue;
    }
    if (!found) {
      // s = 0 on the environment (tech. report eq. 43 without the distance term). Seen directly it
      // has no rival: the light subpath's proxy origin is not a surface the camera can connect to.
      if (scene.environment_light >= 0) {
        const Light& env = scene.lights[scene.environment_light];
        float w_light = 0.f;
        if (segments > 1) {
          const float pick = scene.light_selection.probability(uint32_t(scene.environment_light));
          float pa, pw;
          emission_pdf(scene, env, ray.o, ray.d, -ray.d, time, &pa, &pw);
          w_light = mis(h, pick * environment_pdf(scene, ray.d)) * dvcm + mis(h, pick * pa * pw) * dvc;
        }
        const Rgb c = beta * environment_radiance(scene, env, ray.d) * (1.f / (1.f + w_light));
        radiance += c;
        record(films, 0, segments + 1, pixel, c);
      }
      break;
    }
    const float cos_in = fabsf(dot(ray.d, hit.ng));
    if (!(cos_in > 0.f)) break;
    const float d2 = distance_squared(hit.p, prev_p);
    dvcm *= mis(h, d2);
    dvcm /= mis(h, cos_in);
    dvc /= mis(h, cos_in);

    if (hit.light != kNoLight) {
      // s = 0 (eq. 43). Directly seen, its only rival is the emitter splat s = 1, t = 1.
      const Light& light = scene.lights[hit.light];
      const Rgb le = area_light_radiance(scene, light, hit.ng, -ray.d, hit.uv);
      if (!is_black(le)) {
        const float pick = scene.light_selection.probability(uint32_t(hit.light));
        float pa, pw;
        emission_pdf(scene, light, hit.p, hit.ng, -ray.d, time, &pa, &pw);
        float w_light;
        if (segments == 1) {
          w_light = mis(h, pick * pa) * dvcm;
        } else {
          const float direct_a = pick * light_pdf(scene, light, prev_p, hit.p, hit.ng, time) * cos_in / d2;
          w_light = mis(h, direct_a) * dvcm + mis(h, pick * pa * pw) * dvc;
        }
        const Rgb c = beta * le * (1.f / (1.f + w_light));
        radiance += c;
        record(films, 0, segments + 1, pixel, c);
      }
    }
    if (segments >= max_segments) break;

    Material textured;
    const Material& mat = shading_material(scene, hit, &textured);
    const Frame frame(hit.ns);
    const Vec3 wo = frame.to_local(-ray.d);
    const uint32_t vi = uint32_t(segments - 1);
    if (bsdf_has_non_delta(mat)) {
      const CameraVertex z{&mat, frame, hit.p,  hit.ng, wo,    beta, dvcm, dvc, time,
                           false, 0.f,  -ray.d, medium, scene.media.interface_at(hit), &rng};
      connect_camera_vertex(scene, tracer, sampler, vi, h, z, verts, nv, segments, max_segments, films, pixel, counters,
                            &radiance);
    }

    BsdfSample bs;
    const Point2 ub{sampler.at(dims::vertex(vi, dims::kBsdfU)), sampler.at(dims::vertex(vi, dims::kBsdfU + 1))};
    if (!bsdf_sample(mat, wo, sampler.at(dims::vertex(vi, dims::kLobe)), ub, TransportMode::radiance, &bs)) break;
    const Vec3 wi_world = frame.to_world(bs.wi);
    const float cos_out = fabsf(dot(wi_world, hit.ng));
    if (!(cos_out > 0.f)) break;
    beta *= bs.weight;
    if (is_black(beta)) break;
    if (bs.delta) {
      dvcm = 0.f;
      dvc *= mis(h, cos_out);
    } else {
      const float pdf_rev = bsdf_pdf(mat, bs.wi, wo, TransportMode::importance);
      dvc = mis(h, cos_out / bs.pdf_w) * (dvc * mis(h, pdf_rev) + dvcm);
      dvcm = mis(h, 1.f / bs.pdf_w);
    }
    if (st.roulette_start >= 0 && segments >= st.roulette_start) {
      const float q = fminf(1.f, max_component(beta));
      if (sampler.at(dims::vertex(vi, dims::kRoulette)) >= q) break;
      beta *= 1.f / q;
    }
    prev_p = hit.p;
    medium = scene.media.after(hit, wi_world, medium);
    ray = spawn_ray(hit.p, hit.ng, wi_world, scene.ray_epsilon, time);
  }
  return radiance;
}

}  // namespace pathspace
