// nvcc compile check of the hashed filter's per-vertex steps (filters/, integrators layer): the
// vertex buffer view's store, the keys and jitter, accumulation, lookup, the temporal steps (level
// transfer, blend, folding and eviction of a probe window) and the resolve step are
// called from __global__ code as the GPU filter (filters/hashed/cuda_hashed_filter.cu) calls them, so a
// host-only call in them fails the build even where the CUDA backend is not built. Nothing here runs.
#include "pathspace/filters/filter_resolve.h"
#include "pathspace/filters/hashed/hashed_filter_keys.h"
#include "pathspace/filters/hashed/hashed_filter_steps.h"
#include "pathspace/filters/hashed/temporal_steps.h"
#include "pathspace/filters/vertex_buffer_view.h"

namespace pathspace {

__global__ void filter_steps_compile_check(HashedStepSettings s, VertexBufferView b, const PathSample* samples,
                                           VoxelHashTableView table, VoxelHashTableView coarse, Rgb* filtered,
                                           Rgb* out, uint64_t seed) {
  const size_t path = blockIdx.x * blockDim.x + threadIdx.x;
  if (path >= b.paths) return;
  b.store(path, uint32_t(path), samples[path]);
  const uint64_t pass_hash = pass_jitter_hash(seed, 0);
  LookupCounters c;
  for (int r = 0; r < b.count[path]; ++r) {
    const size_t i = b.slot(path, r);
    const AccumulatedVertex a = accumulate_vertex(s, b, i, pass_hash, table, coarse);
    filtered[i] = lookup_vertex(s, b, i, pass_hash, table, coarse, a.slot, a.coarse_slot, &c);
  }
  const ResolvedPath p = resolved_path_value(b, path, filtered);
  out[path] = p.value + Rgb(float(c.low_count + c.neighbour_lookups + c.multi_level_used));
}

struct CheckChange {
  const VoxelHistory* history;
  __device__ float operator()(uint64_t c) const { return history[c].change; }
};

__global__ void temporal_steps_compile_check(HashedStepSettings s, TemporalSettings t, VertexBufferView b, VoxelHashTableView table,
                                             VoxelHistory* history, Rgb* filtered, uint64_t seed) {
  const size_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= b.slots()) return;
  VoxelHistory transferred;
  const LevelTransfer kind = level_transfer(t, table, history, s.key.normal, key_for_pass(s.key, b, i, pass_jitter_hash(seed, 0)), 1, &transferred);
  float alpha = 0.f;
  filtered[i] = temporal_blend(t, transferred, table.cells[i & table.mask], 0.f, &alpha) + Rgb(alpha + float(int(kind)));
  const TemporalWindowCounts n = fold_and_evict_window(t, 12, table, history, (i & table.mask) & ~uint64_t(15), 2, CheckChange{history});
  filtered[i] = filtered[i] + Rgb(float(n.evicted + n.occupied + n.folded));
}

}  // namespace pathspace
