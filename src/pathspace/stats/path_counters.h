// Per-path counters the kernels fill (device-safe); hosts sum them into RenderStats.
#pragma once

#include <cstdint>

namespace pathspace {

struct PathCounters {
  uint64_t rays = 0;         // intersect + occlusion queries
  uint64_t shadow_rays = 0;  // occlusion queries only
  uint64_t paths = 0;
  uint64_t dropped = 0;      // samples with NaN/Inf radiance, dropped (docs/architecture.md §6)

  void operator+=(const PathCounters& o) {
    rays += o.rays;
    shadow_rays += o.shadow_rays;
    paths += o.paths;
    dropped += o.dropped;
  }
};

}  // namespace pathspace
