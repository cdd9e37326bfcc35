// nvcc compile check of the kernel-side headers of the lower layers (pathspace_base ..
// pathspace_scene, and the device-safe types of filters/): every header below is included and its
// PS_HD functions are called from __global__ code, so a host-only call, a missing PS_HD or anything
// else outside the device-safe subset (docs/architecture.md §4) fails the build. Nothing here runs;
// no GPU is needed. The integrator kernels: integrator_kernels_check.cu. tests/layers checks that
// every header with PS_HD code is included by a file of this folder.
#include "pathspace/base/platform.h"
#include "pathspace/math/bbox.h"
#include "pathspace/math/frame.h"
#include "pathspace/math/rgb.h"
#include "pathspace/math/scalar.h"
#include "pathspace/math/srgb.h"
#include "pathspace/math/vec3.h"
#include "pathspace/parallel/atomics.h"
#include "pathspace/stats/path_counters.h"

#include "pathspace/sampling/discrete.h"
#include "pathspace/sampling/hash.h"
#include "pathspace/sampling/mis.h"
#include "pathspace/sampling/piecewise_2d.h"
#include "pathspace/sampling/rng.h"
#include "pathspace/sampling/sampler.h"
#include "pathspace/sampling/warps.h"
#include "pathspace/geometry/interaction.h"
#include "pathspace/geometry/ray.h"
#include "pathspace/geometry/shapes.h"
#include "pathspace/geometry/surface_attributes.h"
#include "pathspace/camera/perspective_camera.h"
#include "pathspace/camera/pixel_filter.h"
#include "pathspace/filters/hashed/voxel_hash_table_view.h"
#include "pathspace/filters/hashed/voxel_key.h"
#include "pathspace/hashgrid/grid_cell.h"
#include "pathspace/hashgrid/hash_grid_view.h"
#include "pathspace/hashgrid/stochastic_hash_map_view.h"

#include "pathspace/media/equiangular.h"
#include "pathspace/media/free_flight.h"
#include "pathspace/media/grid_lookup.h"
#include "pathspace/media/henyey_greenstein.h"
#include "pathspace/media/majorant_walk.h"
#include "pathspace/media/media_view.h"
#include "pathspace/media/medium.h"
#include "pathspace/materials/bsdf.h"
#include "pathspace/materials/bsdf_layers.h"
#include "pathspace/materials/bsdf_sample.h"
#include "pathspace/materials/fresnel.h"
#include "pathspace/materials/layered_bsdf.h"
#include "pathspace/materials/material.h"
#include "pathspace/materials/microfacet.h"
#include "pathspace/materials/microfacet_beckmann.h"
#include "pathspace/materials/microfacet_distribution.h"
#include "pathspace/materials/rough_conductor.h"
#include "pathspace/materials/rough_dielectric.h"
#include "pathspace/materials/standard_material.h"
#include "pathspace/lights/emission_cells.h"
#include "pathspace/lights/environment_map.h"
#include "pathspace/lights/light.h"
#include "pathspace/lights/light_bounds.h"
#include "pathspace/lights/light_tree_view.h"
#include "pathspace/scene/environment_light.h"
#include "pathspace/scene/light_emission.h"
#include "pathspace/scene/light_sampling.h"
#include "pathspace/scene/light_selection.h"
#include "pathspace/scene/scene_view.h"
#include "pathspace/scene/point_light_intensity.h"
#include "pathspace/scene/shading_material.h"
#include "pathspace/scene/motion.h"
#include "pathspace/scene/surface_opacity.h"
#include "pathspace/scene/texture.h"
#include "pathspace/scene/texture_footprint.h"
#include "pathspace/film/splat_film.h"
#include "pathspace/film/tonemap.h"

#include "pathspace/accel/accel.h"
#include "pathspace/accel/bvh_tracer.h"
#include "pathspace/accel/bvh_view.h"
#include "pathspace/accel/wide_bvh.h"
#include "pathspace/accel/surface_hit_fill.h"
#include "pathspace/filters/path_sample.h"
#include "pathspace/filters/vertex_selection.h"

namespace pathspace {

// Media: distance sampling, transmittance, the majorant walk, the phase function (media/).
__global__ void media_compile_check(MediaView media, Rgb* out, uint32_t n) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n || media.count == 0) return;
  Pcg32 rng(i, 2);
  const Ray ray{Vec3(0.f), Vec3(0.f, 0.f, 1.f), 0.f, kInfinity, 0.f};
  const int32_t m = int32_t(i % media.count);
  const FreeFlight f = sample_free_flight(media, m, ray, 10.f, Rgb(1.f), rng);
  Rgb sum = f.weight + medium_transmittance(media, m, ray, 5.f, rng);
  const Medium& medium = media.media[m];
  sum += medium_sigma_t(medium, media.grid_values, grid_point(medium, ray.at(f.t))) +
         medium_albedo(medium, media.grid_values, grid_vector(medium, ray.d));
  if (medium.type == MediumType::grid) {
    MajorantWalk walk(medium, media.grid_values, ray, 10.f);
    MajorantSegment seg;
    while (walk.next(&seg)) sum += Rgb(seg.sigma);
  }
  const Vec3 w = hg_sample(ray.d, medium.g, {rng.next_float(), rng.next_float()});
  sum += Rgb(hg_phase(dot(ray.d, w), medium.g));
  SurfaceHit hit;
  sum += Rgb(float(media.after(hit, w, m)) + float(medium_after(make_medium_interface(0, kVacuum), hit.ng, w, m)));
  out[i] = sum;
}

// Camera, lights, light sampling and emission, environment, materials and textures of a SceneView.
__global__ void scene_compile_check(SceneView scene, const SurfaceHit* hits, Rgb* out, uint32_t n) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n || scene.num_lights == 0) return;
  Sampler sampler(0, i, 0);
  Pcg32 rng(i, 1);
  const Point2 u{sampler.next_1d(), rng.next_float()};
  const Point2 v{sampler.next_1d(), sampler.next_1d()};
  const PerspectiveCamera& cam = scene.camera;
  const Ray ray = cam.generate_ray(u.x * float(cam.width), u.y * float(cam.height), v);
  float rx = 0.f, ry = 0.f;
  float acc = cam.raster_from_direction(ray.d, &rx, &ry) ? rx + ry : 0.f;
  acc += cam.pdf_direction(ray.d) + cam.importance(ray.d) + cam.pixel_area();
  CameraProjection projection;
  if (cam.project(ray.at(1.f), v, &projection)) acc += projection.factor;
  if (cam.connect(ray.at(2.f), v, &projection)) acc += projection.factor;
  const Point2 offset = sample_filter_raster(cam.filter, i % uint32_t(cam.width), 0, u.x, u.y);
  if (filter_reaches_image(cam.filter, cam.width, cam.height, offset.x, offset.y))
    for_each_filter_pixel(cam.filter, cam.width, cam.height, offset.x, offset.y, [&](uint32_t pixel, float w) { acc += w * float(pixel); });
  float tree_prob = 0.f;
  const uint32_t picked = select_light_at(scene, ray.o, ray.d, v.x, &tree_prob);
  if (picked != LightTreeView::kNone) acc += tree_prob - light_selection_probability_at(scene, ray.o, ray.d, picked);

  const SurfaceHit& hit = hits[i];
  float light_prob = 0.f;
  const Light& light = scene.lights[scene.light_selection.sample(sampler.next_1d(), &light_prob)];
  LightSample ls;
  Rgb sum;
  if (sample_light(scene, light, hit.p, hit.time, u, &ls)) {
    sum += ls.li * (1.f / ls.pdf_w);
    acc += light_pdf(scene, light, hit.p, ls.p, hit.ng, hit.time);
  }
  EmissionSample es;
  if (sample_emission(scene, light, hit.time, u, v, &es)) {
    float pdf_a = 0.f, pdf_w = 0.f;
    emission_pdf(scene, light, es.p, es.n, es.d, es.time, &pdf_a, &pdf_w);
    sum += es.weight * (pdf_a + pdf_w);
  }
  if (scene.environment_light >= 0) {
    const Light& env = scene.lights[scene.environment_light];
    Vec3 w;
    float pdf_w = 0.f;
    sum += sample_environment(scene, env, u, &w, &pdf_w) + environment_radiance(scene, env, w);
    acc += environment_pdf(scene, w) + envmap_pdf(scene.environment_map, w);
  }
  acc += mis_weight(MisHeuristic::balance, 0.5f, 0.25f) + mis_weight(MisHeuristic::power, 0.5f, 0.25f);

  const Frame frame(hit.ns);
  const Vec3 wo = frame.to_local(-ray.d);
  Material storage;
  const Material& m = shading_material(scene, hit, &storage);
  BsdfSample bs;
  if (bsdf_sample(m, wo, sampler.next_1d(), v, TransportMode::radiance, &bs)) {
    sum += bs.weight + bsdf_eval(m, wo, bs.wi, TransportMode::importance);
    acc += bsdf_pdf(m, wo, bs.wi, TransportMode::radiance);
  }
  // Both microfacet distributions directly (the materials above use whichever their record names).
  for (const MicrofacetDistribution dist : {MicrofacetDistribution::ggx, MicrofacetDistribution::beckmann}) {
    const Vec3 mn = microfacet::sample_visible_normal(wo, 0.3f, dist, v);
    acc += microfacet::d(mn, 0.3f, dist) + microfacet::g2(wo, bs.wi, 0.3f, dist) + microfacet::visible_normal_pdf(wo, mn, 0.3f, dist);
  }
  acc += microfacet::beckmann_d(wo, 0.2f) + microfacet::beckmann_lambda(wo, 0.2f) + microfacet::detail::erf_inverse(u.x - 0.5f);
  Rgb layers_f[kMaxBsdfLayers];
  bsdf_eval_layers(m, bsdf_layers(m), wo, bs.wi, TransportMode::radiance, layers_f);
  sum += layers_f[0] + shading_material(scene, hit.material, hit.uv).diffuse;
  if (scene.num_textures > 0) sum += texture_lookup(scene.textures[0], hit.uv);

  const Sphere sphere{hit.p, 1.f, 0};
  float t = 0.f;
  if (intersect_sphere(sphere, ray.o, ray.d, 0.f, kInfinity, &t)) acc += t + sphere_uv(sphere, ray.at(t)).x;
  if (scene.num_triangles > 0) {
    const Triangle& tri = scene.triangles[0];
    acc += triangle_uv(tri, scene.uvs, 0.25f, 0.25f).y;
    sum += Rgb(triangle_shading_normal(tri, scene.normals, 0.25f, 0.25f, hit.ng).x);
  }
  const Ray shadow = spawn_shadow_ray(hit.p, hit.ng, ls.wi, ls.dist, scene.ray_epsilon, hit.time);
  acc += shadow.tmax + scene.bounds.radius;
  acc += cosine_hemisphere_pdf(square_to_cosine_hemisphere(u)) + uniform_cone_pdf(0.5f) +
         square_to_uniform_sphere(disk_concentric_to_square(square_to_disk_concentric(u))).z;
  out[i] = sum + Rgb(acc + float(to_srgb8(acc)) + linear_from_srgb(u.y) + srgb_from_linear(u.x));
}

// Binder et al. 2021 algorithm 1 and sec. 3.2 on the device: key, hashes, insertion, atomic adds.
__global__ void hashed_filter_compile_check(VoxelKeySettings key_settings, VoxelHashTableView table,
                                            const VoxelKeyInput* vertices, const Rgb* contributions, int64_t* slots,
                                            uint32_t n) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  const uint64_t h = mix64(i);
  const VoxelKey key = make_voxel_key(key_settings, vertices[i], bits_to_unit_float(h), bits_to_unit_float(h << 24));
  const ProbeResult r = table.find_or_insert(hash_voxel_key(key, key_settings.normal));
  uint64_t fixed[3];
  if (r.slot >= 0 && to_fixed_point(contributions[i], fixed)) table.add(uint64_t(r.slot), fixed);
  slots[i] = r.slot >= 0 ? r.slot : table.find(hash_voxel_key(coarser_key(key), key_settings.normal)).slot;
}

// The chained hash grid and the stochastic hash map (PCLT listing 1, Hachisuka & Jensen 2010): build
// and query on the device.
__global__ void hash_grid_compile_check(HashGridView grid, StochasticHashMapView stochastic, const Vec3* points,
                                        float radius, float* out, uint32_t n) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  grid.insert(points[i], i);
  stochastic.insert(points[i], i);
  stochastic.resolve(i & stochastic.slot_mask, [&](uint32_t payload) { return points[payload]; });
  float sum = 0.f;
  grid.for_each_in_radius(points[i], radius, [&](const GridRecord& rec, float d2) { sum += d2 + float(rec.payload); });
  stochastic.for_each_in_radius(points[i], radius, [&](const StochasticSlot& s, float d2) { sum += d2 * float(s.count); });
  out[i] = sum;
}

// The device tracer over a flat BVH (Aila-Laine traversal, watertight triangles) and the hit filling
// it shares with the Embree backend.
__global__ void bvh_tracer_compile_check(SceneView scene, BvhView bvh, const Ray* rays, SurfaceHit* hits, bool* blocked,
                                         uint32_t n) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  const BvhTracer tracer{scene, bvh};
  if (!tracer.intersect(rays[i], &hits[i])) fill_sphere_hit(scene, 0, 1.f, rays[i], &hits[i]);
  blocked[i] = tracer.occluded(rays[i]);
}

// The tracer over the 8-wide BVH with quantised child boxes.
__global__ void wide_bvh_tracer_compile_check(SceneView scene, WideBvhView bvh, const Ray* rays, SurfaceHit* hits, bool* blocked,
                                              uint32_t n) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  const WideBvhTracer tracer{scene, bvh};
  tracer.intersect(rays[i], &hits[i]);
  blocked[i] = tracer.occluded(rays[i]);
}

// Fixed-point splats of light paths and the path records a filter receives.
__global__ void film_compile_check(SplatFilmView film, const PathSample* samples, PathCounters* counters, uint32_t n) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  film.add(i % uint32_t(film.width * film.height), samples[i].value());
  atomic_fetch_add(&counters[0].paths, uint64_t(1));
}

}  // namespace pathspace
