// Caustic photons for the path tracer (Keller, Dahm, Binder 2014, sec. 2.3; device-safe, templated
// on the ray caster like pt_trace_path). A photon path leaves a light, passes every vertex that a
// path space filter could not take (selectable_vertex.h: delta surfaces, and glossy ones smoother
// than the selection's roughness limit) by sampling its BSDF, and is stored once, at the first
// selectable vertex after at least one such bounce (a light -> specular+ -> diffuse path), then ends;
// a photon whose first hit is selectable ends at once. The path tracer gathers these photons at every
// selectable vertex of a camera path and leaves out exactly the paths they stand for (emission
// reached from such a vertex through vertices that are not selectable only, and the next event
// estimates made there), so no path is counted twice and none is lost. The 2014 paper names
// specular chains; near-specular glossy ones are the same problem for a filter (a voxel averages
// their rare bright paths into blotches) and the same cure. At the first selected vertex the
// gathered radiance goes into the path's prefix: it is not averaged again by the filter ("the
// contribution to vertices obtained by photon mapping should not be included in path space
// filtering"); at later vertices it is light arriving at the selected vertex from elsewhere,
// averaged with the rest of its contribution. With one-bounce photons (CausticSettings::one_bounce)
// a photon path goes on from its first receiver and is stored once more at the next; those are
// gathered at every receiver, and only the first receiver keeps its direct light and caustics
// (pt_kernel.h, PtPathState::receivers_passed).
#pragma once

#include "pathspace/hashgrid/hash_grid_view.h"
#include "pathspace/integrators/common/light_dimensions.h"
#include "pathspace/integrators/common/light_path_start.h"
#include "pathspace/integrators/pt/selectable_vertex.h"
#include "pathspace/materials/bsdf.h"
#include "pathspace/sampling/sampler.h"
#include "pathspace/scene/shading_material.h"
#include "pathspace/stats/path_counters.h"

namespace pathspace {

struct CausticPhoton {
  Vec3 p;
  Vec3 wi;      // unit, from p towards where the photon came from
  Rgb power;    // Phi
  uint8_t segments = 0;  // light-path segments to p
  bool stored = false;
};

// One kind of stored photon in a pass: a hash grid over them, photons[i] belonging to grid record
// i (cell order), and the pass's radius and normalisation 1 / (pi r^2 N); radius 0: none stored.
struct PhotonSetView {
  HashGridView grid;
  const CausticPhoton* photons = nullptr;
  float radius = 0.f;
  float inv_area_count = 0.f;
};

// The photon map of one pass: the caustic photons (light -> links+ -> receiver) and, when asked
// for (CausticSettings::one_bounce), the photons after one diffuse bounce (light -> links* ->
// receiver -> links* -> receiver), each kind in its own grid so that a gather for one kind never
// reads the other's.
struct CausticMapView {
  PhotonSetView caustic;
  PhotonSetView one_bounce;
  int max_segments = 0;
  // Which vertices gather (and store) photons: the camera paths' selection with its roughness limit
  // raised to CausticSettings::min_roughness; the others are links of caustic chains.
  VertexSelection receivers;
  // Whether the pass traced photons after one diffuse bounce (their set may still be empty): the
  // path tracer then leaves out the paths they stand for (pt_kernel.h, PtPathState::receivers_passed).
  bool with_one_bounce = false;
};

// The sampler seed of a pass's photon paths: a stream apart from the camera paths' (both are indexed
// from 0), the same on both devices.
PS_INLINE uint64_t caustic_photon_seed(uint64_t seed) { return seed ^ 0x636175737469637aull; }

// Photons a photon path may store (trace_caustic_photon's room in `out`): its caustic photon, and
// its one-bounce photon when those are asked for.
PS_INLINE uint32_t caustic_photons_per_path(bool one_bounce) { return one_bounce ? 2u : 1u; }

// Traces one photon path; out[0] receives its caustic photon and, only with `one_bounce` (out then
// has room for caustic_photons_per_path(true)), out[1] its photon after one diffuse bounce (`stored` false where there is none). `receivers`:
// CausticMapView::receivers, whose roughness test decides where photons are stored. Without
// `one_bounce` the path ends at its first receiver; with it the path bounces there once more and
// ends at the next receiver, so the two kinds together carry all light that reaches a receiver
// after at least one bounce and at most one receiver bounce.
template <typename Tracer>
PS_HD void trace_caustic_photon(const SceneView& scene, const Tracer& tracer, const Sampler& sampler, int max_segments,
                                const VertexSelection& receivers, bool one_bounce, PathCounters* counters, CausticPhoton* out) {
  out[0].stored = false;
  if (one_bounce) out[1].stored = false;
  LightPathStart start;
  if (!start_light_path(scene, sampler, light_path_time(scene, sampler), &start)) return;
  const EmissionSample& e = start.emission;
  Rgb beta = e.weight * (1.f / start.select_prob);
  Ray ray = first_light_ray(scene, e);
  bool after_receiver = false;
  // The shortest camera side is one segment, so longer light paths cannot join.
  for (int segments = 1; segments < max_segments; ++segments) {
    SurfaceHit hit;
    ++counters->rays;
    if (!tracer.intersect(ray, &hit)) return;
    Material textured;
    const Material& mat = shading_material(scene, hit, &textured);
    const Vec3 wi_world = -ray.d;
    if (is_selectable_material(mat, receivers)) {
      if (after_receiver) {
        out[1] = {hit.p, wi_world, beta, uint8_t(segments), true};
        return;
      }
      if (segments > 1) out[0] = {hit.p, wi_world, beta, uint8_t(segments), true};
      if (!one_bounce) return;
      after_receiver = true;
    }
    const Frame frame(hit.ns);
    const uint32_t v = uint32_t(segments - 1);
    BsdfSample bs;
    const Point2 ub{sampler.at(light_dims::vertex(v, light_dims::kBsdfU)), sampler.at(light_dims::vertex(v, light_dims::kBsdfU + 1))};
    if (!bsdf_sample(mat, frame.to_local(wi_world), sampler.at(light_dims::vertex(v, light_dims::kLobe)), ub,
                     TransportMode::importance, &bs))
      return;
    beta *= bs.weight;
    if (is_black(beta) || !all_finite(beta)) return;
    ray = spawn_ray(hit.p, hit.ng, frame.to_world(bs.wi), scene.ray_epsilon, hit.time);
  }
}

// Calls visit(photon) for each photon of one kind within the pass's radius of a camera-path vertex
// that arrived from the side the camera path did (wo: world, unit, towards the camera side) and
// whose joined path fits the segment limit, in the grid's record order: deterministic.
template <typename Visit>
PS_INLINE void for_each_gathered_photon(const PhotonSetView& map, int max_segments, const SurfaceHit& hit, const Vec3& wo,
                                        int camera_segments, Visit&& visit) {
  if (map.radius <= 0.f) return;
  const Vec3 n_front = dot(hit.ng, wo) >= 0.f ? hit.ng : -hit.ng;
  const float r2 = map.radius * map.radius;
  // The photons are in the grid's record order (CausticPhotonMap::index), so a cell's range indexes
  // them directly: one array read per photon instead of a record and then the photon.
  map.grid.for_each_cell_range(hit.p, map.radius, [&](uint32_t begin, uint32_t end) {
    for (uint32_t i = begin; i < end; ++i) {
      const CausticPhoton& ph = map.photons[i];
      if (distance_squared(ph.p, hit.p) > r2) continue;
      if (camera_segments + int(ph.segments) > max_segments) continue;
      if (dot(n_front, ph.wi) <= 0.f) continue;
      visit(ph);
    }
  });
}

// Radiance reflected towards wo (world, unit) at a camera-path vertex by one kind of photons:
// sum f(wo, wi_p) Phi_p / (pi r^2 N) over the photons for_each_gathered_photon visits.
PS_INLINE Rgb gather_photons(const PhotonSetView& map, int max_segments, const SurfaceHit& hit, const Material& mat,
                             const Vec3& wo, int camera_segments) {
  // The shading frame only once a photon is found: most gathers find none.
  Frame frame;
  Vec3 wo_local;
  bool framed = false;
  Rgb sum;
  for_each_gathered_photon(map, max_segments, hit, wo, camera_segments, [&](const CausticPhoton& ph) {
    if (!framed) {
      frame = Frame(hit.ns);
      wo_local = frame.to_local(wo);
      framed = true;
    }
    const Rgb c = bsdf_eval(mat, wo_local, frame.to_local(ph.wi), TransportMode::radiance) * ph.power;
    if (all_finite(c)) sum += c;
  });
  return sum * map.inv_area_count;
}

// Whether f is Lambert's alone, rho_d / pi: a gather then sums the photons' power and multiplies once.
PS_INLINE bool is_lambertian(const Material& m) {
  return m.type == MaterialType::standard && is_black(m.glossy) && is_black(m.specular);
}

// gather_photons for the one-bounce photons, which are everywhere (a gather finds tens): at a
// Lambertian vertex the sum of the powers from above the surface times rho_d / pi, the test as
// bsdf_eval makes it but without a shading frame and an evaluation per photon.
PS_INLINE Rgb gather_one_bounce_photons(const PhotonSetView& map, int max_segments, const SurfaceHit& hit, const Material& mat,
                                        const Vec3& wo, int camera_segments) {
  if (!is_lambertian(mat)) return gather_photons(map, max_segments, hit, mat, wo, camera_segments);
  float wo_z = dot(hit.ns, wo);
  const bool flip = detail::mirrors_to_wo_side(mat) && wo_z < 0.f;
  if (flip) wo_z = -wo_z;
  if (wo_z < kMinCosine) return Rgb();
  Rgb power;
  for_each_gathered_photon(map, max_segments, hit, wo, camera_segments, [&](const CausticPhoton& ph) {
    const float wi_z = flip ? -dot(hit.ns, ph.wi) : dot(hit.ns, ph.wi);
    if (wi_z >= kMinCosine) power += ph.power;
  });
  return mat.diffuse * (kInvPi * map.inv_area_count) * power;
}

}  // namespace pathspace
