// Wavefront path tracing on the GPU (Laine, Karras, Aila 2013): the path states of a whole pass in
// device memory, and per bounce one kernel per stage over queues of path indices (wavefront_stages.h):
// extension rays (closest hit), shading, shadow rays (any hit). Each stage's device time is summed
// for the statistics. Ended paths are written as the megakernel writes them: into the device
// vertex buffer (filtered) or as pixel values (plain). CUDA builds only.
#pragma once

#include <cstdint>
#include <vector>

#include "pathspace/accel/bvh_tracer.h"
#include "pathspace/filters/vertex_buffer_view.h"
#include "pathspace/gpu/device_counters.h"
#include "pathspace/parallel/device_buffer.h"
#include "pathspace/integrators/pt/pt_kernel.h"

namespace pathspace::gpu {

struct WavefrontStageTimes {
  double camera_ms = 0, extend_ms = 0, shade_ms = 0, shadow_ms = 0;
  uint64_t extension_rays = 0, shadow_rays = 0, bounces = 0;
};

class WavefrontPathTracer {
 public:
  explicit WavefrontPathTracer(uint32_t paths);
  // One pass: every pixel's path, traced stage by stage. `buffer` non-null: ended paths are stored
  // there (filtering); else their values go to image[pixel]. `caustics` non-null: the pass's caustic
  // photon map, in device memory (pt_trace_path). Adds the stage times to *times.
  void trace(const SceneView& scene, const BvhTracer& tracer, const PtSettings& settings, uint64_t seed, uint32_t pass,
             const VertexBufferView* buffer, Rgb* image, PathCountersDevice* counters, WavefrontStageTimes* times,
             const CausticMapView* caustics = nullptr);
  size_t bytes() const;

 private:
  uint32_t paths_;
  DeviceBuffer<PtPathState> states_;                // the per-bounce part, copied in and out by each kernel
  DeviceBuffer<pt_detail::OpenVertex> open_;         // kMaxSelectedVertices per path
  DeviceBuffer<SurfaceHit> hits_;
  DeviceBuffer<uint8_t> found_, ends_after_shadow_;
  DeviceBuffer<uint32_t> queue_a_, queue_b_, shadow_queue_;
  DeviceBuffer<uint32_t> counts_;  // [0] current, [1] next, [2] shadow
};

}  // namespace pathspace::gpu
