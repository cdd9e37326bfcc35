// Compiles pathspace_core's device-safe headers with nvcc and instantiates the kernels a CUDA backend
// will launch (path tracing with vertex recording, the hashed filter's key + table insertion, light
// tracing with splats) with a trivial device tracer, so code that breaks the device-safe subset
// fails the build early. Nothing here runs; no GPU is needed.
#include "pathspace/hashing/voxel_hash_table_view.h"
#include "pathspace/integrators/bpt/bpt_kernel.h"
#include "pathspace/integrators/common/camera_sample.h"
#include "pathspace/integrators/lt/lt_kernel.h"
#include "pathspace/integrators/pt/pt_kernel.h"

namespace pathspace {

struct NullTracer {
  __device__ bool intersect(const Ray&, SurfaceHit*) const { return false; }
  __device__ bool occluded(const Ray&) const { return false; }
};

__global__ void pt_compile_check(SceneView scene, PtSettings settings, Rgb* out, uint32_t n) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  PathCounters counters;
  const Sampler sampler(0, i, 0);
  const Ray ray = sample_camera_ray(scene.camera, sampler, i);  // pinhole or thin lens
  PathSample sample;
  pt_trace_path(scene, NullTracer{}, sampler, ray, settings, &counters, &sample);
  out[i] = sample.value();
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
  slots[i] = r.slot;
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

}  // namespace pathspace
