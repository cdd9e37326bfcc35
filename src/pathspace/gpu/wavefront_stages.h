// The stages of wavefront path tracing (Laine, Karras, Aila 2013, "Megakernels Considered Harmful"),
// one path each, device-safe: the CUDA kernels of cuda_wavefront_pt.cu call them one thread per
// queued path, and tests/unit/wavefront_stages_test.cpp calls them from the CPU's parallel loop
// to check that stage by stage the paths equal pt_trace_path's bit for bit. The path's state lives
// in PtPathState (integrators/pt/pt_kernel.h), whose step functions both run.
//
//   camera  : every pixel's path starts (pt_begin); all go to the extension queue
//   extend  : nearest hit of each queued path's ray (closest-hit traversal only)
//   shade   : emission, selection, NEE, BSDF sampling (pt_on_miss / pt_on_hit); paths with a
//             pending shadow ray go to the shadow queue, others to the next extension queue or end
//   shadow  : any-hit traversal of the pending shadow rays; the NEE estimate counts if unblocked
//   finish  : an ended path becomes its PathSample (pt_finish)
#pragma once

#include <cstdint>

#include "pathspace/integrators/common/camera_sample.h"
#include "pathspace/integrators/pt/pt_kernel.h"
#include "pathspace/parallel/atomics.h"

namespace pathspace {

// The wavefront keeps one path state per pixel, so it traces no camera-side branches
// (VertexSelection::camera_splits; CudaPtIntegrator refuses them): what is compared with it, or
// timed beside it, is traced without them.
inline PtSettings without_camera_branches(PtSettings s) {
  s.selection.camera_splits = 0;
  return s;
}

// A queue of path indices in memory the stages share; `count` is advanced atomically.
struct PathQueue {
  uint32_t* paths = nullptr;
  uint32_t* count = nullptr;
  PS_HD void push(uint32_t path) const { paths[atomic_fetch_add(count, 1u)] = path; }
};

// What shade decided for a path.
enum class WavefrontAfterShade : uint8_t { ended, extend, shadow_then_extend, shadow_then_end };

// `open`: the path's room for its selected vertices (kMaxSelectedVertices of them).
PS_INLINE void wavefront_camera(const SceneView& scene, uint64_t seed, uint32_t pass, uint32_t pixel, PtPathState* s,
                                pt_detail::OpenVertex* open) {
  const Sampler sampler(seed, pixel, pass);
  pt_begin(s, sample_camera_ray(scene, sampler, pixel, camera_path_time(scene, sampler)), open);
}

template <typename Tracer>
PS_HD bool wavefront_extend(const Tracer& tracer, const PtPathState& s, SurfaceHit* hit) {
  return tracer.intersect(s.ray, hit);
}

// The path's extension ray found `hit` (or nothing): one bounce of pt_trace_path's loop up to its
// shadow ray. Counts the extension ray in *counters.
template <typename Tracer>
PS_HD WavefrontAfterShade wavefront_shade(const SceneView& scene, const Tracer& tracer, const PtSettings& settings, uint64_t seed,
                                          uint32_t pass, uint32_t pixel, const SurfaceHit& hit, bool found, PtPathState* s,
                                          PathCounters* counters, const CausticMapView* caustics = nullptr) {
  ++counters->rays;
  if (!found) {
    pt_on_miss(scene, settings, s, caustics);
    return WavefrontAfterShade::ended;
  }
  const Sampler sampler(seed, pixel, pass);
  const PtNext next = pt_on_hit(scene, tracer, sampler, settings, hit, counters, s, {}, false, caustics);
  if (s->shadow_pending) return next == PtNext::extend ? WavefrontAfterShade::shadow_then_extend : WavefrontAfterShade::shadow_then_end;
  return next == PtNext::extend ? WavefrontAfterShade::extend : WavefrontAfterShade::ended;
}

template <typename Tracer>
PS_HD void wavefront_shadow(const Tracer& tracer, PtPathState* s) {
  pt_resolve_shadow(s, tracer.occluded(s->shadow_ray));
}

}  // namespace pathspace
