// nvcc compile check of the integrator kernels (pathspace_integrators' *_kernel.h): instantiates the
// per-path functions a CUDA backend will launch (path tracing with vertex recording, visibility
// probes, query-only paths and caustic photons, light tracing
// with splats, bidirectional path tracing, SPPM's eye pass, photon pass and deposit, PCLT's eye and
// light passes) with a trivial device tracer, so code that breaks the device-safe subset fails the
// build early. Nothing here runs; no GPU is needed. The lower layers: layers_compile_check.cu.
#include "pathspace/accel/bvh_tracer.h"
#include "pathspace/integrators/bpt/bpt_kernel.h"
#include "pathspace/integrators/bpt/bpt_settings.h"
#include "pathspace/integrators/common/camera_sample.h"
#include "pathspace/integrators/common/dimensions.h"
#include "pathspace/integrators/common/light_dimensions.h"
#include "pathspace/integrators/common/light_path_start.h"
#include "pathspace/integrators/common/light_path_step.h"
#include "pathspace/integrators/common/media_steps.h"
#include "pathspace/integrators/common/transmittance_along.h"
#include "pathspace/integrators/lt/lt_kernel.h"
#include "pathspace/integrators/lt/lt_settings.h"
#include "pathspace/integrators/pclt/pclt_kernel.h"
#include "pathspace/integrators/pclt/pclt_settings.h"
#include "pathspace/integrators/pt/caustic_photons.h"
#include "pathspace/integrators/pt/selectable_vertex.h"
#include "pathspace/integrators/pt/pt_kernel.h"
#include "pathspace/gpu/wavefront_stages.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/integrators/sppm/sppm_kernel.h"
#include "pathspace/integrators/sppm/sppm_settings.h"

namespace pathspace {

// A device tracer that answers from memory (the kernels are templated on the Tracer concept of
// accel/accel.h), so the optimiser cannot drop the code after a hit and every path is compiled.
__device__ const SurfaceHit* g_hits;
__device__ uint32_t g_hit_count;

struct NullTracer {
  __device__ bool intersect(const Ray& ray, SurfaceHit* hit) const {
    *hit = g_hits[uint32_t(ray.d.x * 1024.f) % g_hit_count];
    return hit->t < ray.tmax;
  }
  __device__ bool occluded(const Ray& ray) const { return g_hits[0].t < ray.tmax; }
};

// Path tracing, plain and with what filters ask for: visibility probes, query-only paths and a
// caustic photon map (traced by trace_caustic_photon).
__global__ void pt_compile_check(SceneView scene, PtSettings settings, VisibilityProbes probes, CausticMapView caustics,
                                 CausticPhoton* photons, Rgb* out, uint32_t n) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  PathCounters counters;
  const Sampler sampler(0, i, 0);
  const Ray ray = sample_camera_ray(scene, sampler, i, camera_path_time(scene, sampler));  // pinhole or thin lens
  PathSample sample;
  pt_trace_path(scene, NullTracer{}, sampler, ray, settings, &counters, &sample);
  out[i] = sample.value() + pt_trace_path(scene, NullTracer{}, sampler, ray, settings, &counters);
  pt_trace_path(scene, NullTracer{}, sampler, ray, settings, &counters, &sample, probes, i % 2 == 0, &caustics);
  out[i] += sample.value();
  trace_caustic_photon(scene, NullTracer{}, Sampler(1, i, 0), scene.max_path_segments, caustics.receivers, true, &counters, &photons[2 * i]);
  BsdfLayers layers;  // the receivers' test of the camera paths and the photons (selectable_vertex.h)
  merge_layers(&layers);
  if (is_selectable(layers, caustics.receivers)) out[i] = Rgb();
}

// Path tracing through the BVH tracer, as a CUDA backend calls it.
__global__ void pt_bvh_compile_check(SceneView scene, BvhView bvh, PtSettings settings, Rgb* out, uint32_t n) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  PathCounters counters;
  const Sampler sampler(0, i, 0);
  out[i] = pt_trace_path(scene, BvhTracer{scene, bvh}, sampler, sample_camera_ray(scene, sampler, i, camera_path_time(scene, sampler)), settings, &counters);
}

__global__ void lt_compile_check(SceneView scene, LtSettings settings, SplatFilmView film, uint32_t n) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  PathCounters counters;
  lt_trace_path(scene, NullTracer{}, Sampler(0, i, 0), settings, 1.f / float(n), film, &counters);
}

// Bidirectional path tracing: both subpaths, all connections, t = 1 splats.
__global__ void bpt_compile_check(SceneView scene, BptSettings settings, BptFilms films, Rgb* out, uint32_t n) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  PathCounters counters;
  out[i] = bpt_trace_pixel(scene, NullTracer{}, Sampler(0, i, 0), Sampler(0, i, uint64_t(1) << 63), settings, i, films, &counters);
}

// SPPM: one iteration's eye pass (visible points), the photon pass and its deposits into the grid.
__global__ void sppm_compile_check(SceneView scene, SppmSettings settings, SppmGatherView gather, VisiblePoint* points,
                                   Rgb* direct, PhotonCounters* photons, uint32_t n) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  PathCounters counters;
  const Sampler sampler(0, i, 0);
  sppm_trace_eye(scene, NullTracer{}, sampler, sample_camera_ray(scene, sampler, i, camera_path_time(scene, sampler)), settings,
                 scene.max_path_segments, &counters, &direct[i], &points[i]);
  sppm_trace_photon(scene, NullTracer{}, Sampler(1, i, 0), settings, gather, pass_time(scene, 1, 0), &counters, &photons[i]);
  if (i == 0) direct[0] += Rgb(max_photon_power(scene));
}

// PCLT: the eye pass (pixel cache records) and the light pass (gathers and projections).
__global__ void pclt_compile_check(SceneView scene, PcltSettings settings, PcltLightView light_view, PcltEyeResult* eye,
                                   PcltLightCounters* light_counters, uint32_t n) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  PathCounters counters;
  const Sampler sampler(0, i, 0);
  pclt_trace_eye(scene, NullTracer{}, sampler, sample_camera_ray(scene, sampler, i, camera_path_time(scene, sampler)), i, settings,
                 scene.max_path_segments, &counters, &eye[i]);
  pclt_trace_light(scene, NullTracer{}, Sampler(1, i, 0), settings, light_view, &counters, &light_counters[i]);
}

}  // namespace pathspace
