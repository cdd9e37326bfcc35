// The voxel key of a record slot in one pass of the hashed filter (Binder et al. 2021, sec. 3.1,
// algorithm 1): its inputs from the vertex buffer and its jitter, a pure function of (seed, pass,
// path, record), so keys are the same for any thread count and on the GPU (sec. 3.1.4). HashedFilter
// (its scalar reference; the batched keys of voxel_key_batch.h equal it bit for bit) and
// filters/hashed/cuda_hashed_filter.cu both use these.
#pragma once

#include <cstddef>
#include <cstdint>

#include "pathspace/filters/vertex_buffer_view.h"
#include "pathspace/filters/hashed/voxel_key.h"

namespace pathspace {

PS_INLINE uint64_t pass_jitter_hash(uint64_t seed, uint32_t pass) { return hash_combine(mix64(seed ^ 0x4a17e5ull), pass); }

// `stream`: VertexBufferView::record_stream of the record.
PS_INLINE uint64_t jitter_seed(uint64_t pass_hash, size_t stream) { return pass_hash + uint64_t(stream) * kGoldenGamma; }

PS_INLINE VoxelKeyInput key_input(const VertexBufferView& b, size_t i) {
  return {b.position[i],        b.geometric_normal[i], b.shading_normal[i], b.incident[i], b.previous_position[i],
          b.prefix_distance[i], b.roughness[i],        b.layer[i],          b.selected[i]};
}

// Algorithm 1 for record slot i with the pass's jitter.
PS_INLINE VoxelKey key_for_pass(const VoxelKeySettings& s, const VertexBufferView& b, size_t i, uint64_t pass_hash) {
  const uint64_t h = mix64(jitter_seed(pass_hash, b.record_stream(i)));
  return make_voxel_key(s, key_input(b, i), bits_to_unit_float(h), bits_to_unit_float(h << 24));
}

}  // namespace pathspace
