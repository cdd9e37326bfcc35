#include "pathspace/gpu/cuda_wavefront_pt.h"

#include <cuda_runtime.h>

#include "pathspace/filters/vertex_buffer_view.h"
#include "pathspace/parallel/cuda_check.h"
#include "pathspace/gpu/cuda_event_timer.h"
#include "pathspace/gpu/wavefront_stages.h"

namespace pathspace::gpu {

namespace {

constexpr int kThreads = 128;
uint32_t blocks_for(uint32_t n) { return (n + kThreads - 1) / kThreads; }

// An ended path: its sample into the vertex buffer, or its value into the image (NaN/Inf dropped,
// as the CPU's plain path tracing does).
__device__ void finish(PtPathState* s, uint32_t path, const VertexBufferView* buffer, Rgb* image, uint32_t* dropped) {
  PathSample sample;
  pt_finish(s, &sample);
  if (buffer) {
    buffer->store(path, path, sample);
    return;
  }
  Rgb v = sample.value();
  if (!all_finite(v)) {
    *dropped = 1;
    v = Rgb();
  }
  image[path] = v;
}

struct StageParams {
  SceneView scene;
  BvhTracer tracer;
  PtSettings settings;
  uint64_t seed;
  uint32_t pass;
  VertexBufferView buffer;
  bool filtered;
  Rgb* image;
  bool has_caustics;
  CausticMapView caustics;  // device pointers
};

__global__ void camera_kernel(StageParams p, uint32_t n, PtPathState* states, pt_detail::OpenVertex* open, uint32_t* queue) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  PtPathState s;
  wavefront_camera(p.scene, p.seed, p.pass, i, &s, &open[size_t(i) * kMaxSelectedVertices]);
  states[i] = s;
  queue[i] = i;
}

__global__ void extend_kernel(StageParams p, const uint32_t* queue, const uint32_t* count, PtPathState* states, SurfaceHit* hits,
                              uint8_t* found) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= *count) return;
  const uint32_t path = queue[i];
  found[path] = wavefront_extend(p.tracer, states[path], &hits[path]) ? 1 : 0;
}

__global__ void shade_kernel(StageParams p, const uint32_t* queue, const uint32_t* count, PtPathState* states, const SurfaceHit* hits,
                             const uint8_t* found, PathQueue next, PathQueue shadow, uint8_t* ends_after_shadow,
                             PathCountersDevice* counters) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= *count) return;
  const uint32_t path = queue[i];
  PathCounters c;
  PtPathState local = states[path];  // the per-bounce part in registers; the open vertices stay in memory
  PtPathState* s = &local;
  const WavefrontAfterShade after =
      wavefront_shade(p.scene, p.tracer, p.settings, p.seed, p.pass, path, hits[path], found[path] != 0, s, &c,
                      p.has_caustics ? &p.caustics : nullptr);
  uint32_t ended = 0, dropped = 0;
  switch (after) {
    case WavefrontAfterShade::extend: next.push(path); break;
    case WavefrontAfterShade::shadow_then_extend:
    case WavefrontAfterShade::shadow_then_end:
      ends_after_shadow[path] = after == WavefrontAfterShade::shadow_then_end ? 1 : 0;
      shadow.push(path);
      break;
    case WavefrontAfterShade::ended:
      finish(s, path, p.filtered ? &p.buffer : nullptr, p.image, &dropped);
      ended = 1;
      break;
  }
  if (!ended) states[path] = local;
  add_counters(counters, uint32_t(c.rays), uint32_t(c.shadow_rays), ended, dropped);
}

__global__ void shadow_kernel(StageParams p, const uint32_t* queue, const uint32_t* count, PtPathState* states,
                              const uint8_t* ends_after_shadow, PathQueue next, PathCountersDevice* counters) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= *count) return;
  const uint32_t path = queue[i];
  PtPathState local = states[path];
  PtPathState* s = &local;
  wavefront_shadow(p.tracer, s);
  uint32_t ended = 0, dropped = 0;
  if (ends_after_shadow[path]) {
    finish(s, path, p.filtered ? &p.buffer : nullptr, p.image, &dropped);
    ended = 1;
  } else {
    states[path] = local;
    next.push(path);
  }
  add_counters(counters, 0u, 0u, ended, dropped);
}

}  // namespace

WavefrontPathTracer::WavefrontPathTracer(uint32_t paths)
    : paths_(paths), states_(paths), open_(size_t(paths) * kMaxSelectedVertices), hits_(paths), found_(paths), ends_after_shadow_(paths), queue_a_(paths), queue_b_(paths),
      shadow_queue_(paths), counts_(3) {}

size_t WavefrontPathTracer::bytes() const {
  return states_.bytes() + open_.bytes() + hits_.bytes() + found_.bytes() + ends_after_shadow_.bytes() + queue_a_.bytes() + queue_b_.bytes() +
         shadow_queue_.bytes() + counts_.bytes();
}

void WavefrontPathTracer::trace(const SceneView& scene, const BvhTracer& tracer, const PtSettings& settings, uint64_t seed,
                                uint32_t pass, const VertexBufferView* buffer, Rgb* image, PathCountersDevice* counters,
                                WavefrontStageTimes* times, const CausticMapView* caustics) {
  const StageParams p{scene, tracer, settings, seed, pass, buffer ? *buffer : VertexBufferView{}, buffer != nullptr, image,
                      caustics != nullptr, caustics ? *caustics : CausticMapView{}};
  uint32_t* current = queue_a_.data();
  uint32_t* next = queue_b_.data();
  uint32_t* counts = counts_.data();  // [0] current, [1] next, [2] shadow
  CudaEventTimer timer;
  timer.start();
  camera_kernel<<<blocks_for(paths_), kThreads>>>(p, paths_, states_.data(), open_.data(), current);
  PS_CUDA_CHECK_LAUNCH("camera_kernel");
  uint32_t n = paths_;
  PS_CUDA_CHECK(cudaMemcpy(&counts[0], &n, sizeof n, cudaMemcpyHostToDevice));
  timer.lap(&times->camera_ms);
  while (n > 0) {
    PS_CUDA_CHECK(cudaMemset(&counts[1], 0, 2 * sizeof(uint32_t)));
    extend_kernel<<<blocks_for(n), kThreads>>>(p, current, &counts[0], states_.data(), hits_.data(), found_.data());
    PS_CUDA_CHECK_LAUNCH("extend_kernel");
    timer.lap(&times->extend_ms);
    shade_kernel<<<blocks_for(n), kThreads>>>(p, current, &counts[0], states_.data(), hits_.data(), found_.data(),
                                              PathQueue{next, &counts[1]}, PathQueue{shadow_queue_.data(), &counts[2]},
                                              ends_after_shadow_.data(), counters);
    PS_CUDA_CHECK_LAUNCH("shade_kernel");
    timer.lap(&times->shade_ms);
    uint32_t shadow_n = 0;
    PS_CUDA_CHECK(cudaMemcpy(&shadow_n, &counts[2], sizeof shadow_n, cudaMemcpyDeviceToHost));
    if (shadow_n > 0) {
      shadow_kernel<<<blocks_for(shadow_n), kThreads>>>(p, shadow_queue_.data(), &counts[2], states_.data(), ends_after_shadow_.data(),
                                                        PathQueue{next, &counts[1]}, counters);
      PS_CUDA_CHECK_LAUNCH("shadow_kernel");
    }
    timer.lap(&times->shadow_ms);
    times->extension_rays += n;
    times->shadow_rays += shadow_n;
    ++times->bounces;
    PS_CUDA_CHECK(cudaMemcpy(&n, &counts[1], sizeof n, cudaMemcpyDeviceToHost));
    PS_CUDA_CHECK(cudaMemcpy(&counts[0], &counts[1], sizeof n, cudaMemcpyDeviceToDevice));
    uint32_t* t = current;
    current = next;
    next = t;
  }
}

}  // namespace pathspace::gpu
