// Compiles pathspace_core's device-safe headers with nvcc and instantiates the path tracing kernel
// with a trivial device tracer, so code that breaks the device-safe subset fails the build early.
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
  const Ray ray = scene.camera.generate_ray(float(i % 16) + 0.5f, float(i / 16) + 0.5f);
  out[i] = pt_trace_path(scene, NullTracer{}, sampler, ray, settings, &counters);
}

}  // namespace pathspace
