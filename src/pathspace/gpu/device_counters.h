// The common path counters of a GPU pass (stats/path_counters.h) in device memory, and their
// device-side sum: per warp first (__reduce_add_sync), then one 64-bit atomic per warp and field,
// so that two million paths do not queue on four addresses.
#pragma once

#include "pathspace/stats/path_counters.h"

namespace pathspace::gpu {

struct PathCountersDevice {
  unsigned long long rays, shadow_rays, paths, dropped;
};

#ifdef __CUDACC__
__device__ inline void add_counters(PathCountersDevice* out, uint32_t rays, uint32_t shadow_rays, uint32_t paths, uint32_t dropped) {
  const unsigned mask = __activemask();
  rays = __reduce_add_sync(mask, rays);
  shadow_rays = __reduce_add_sync(mask, shadow_rays);
  paths = __reduce_add_sync(mask, paths);
  dropped = __reduce_add_sync(mask, dropped);
  if ((threadIdx.x & 31u) == uint32_t(__ffs(mask) - 1)) {
    atomicAdd(&out->rays, (unsigned long long)rays);
    atomicAdd(&out->shadow_rays, (unsigned long long)shadow_rays);
    atomicAdd(&out->paths, (unsigned long long)paths);
    atomicAdd(&out->dropped, (unsigned long long)dropped);
  }
}
#endif

}  // namespace pathspace::gpu
