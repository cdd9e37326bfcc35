// Voxel keys and hashes for a batch of vertices at once: algorithm 1 of Binder, Fricke, Keller 2021
// (sec. 3.1) in structure-of-arrays form, so that the compiler runs it on 8 or 16 vertices per
// instruction. Computing keys one vertex at a time was 60-70% of the filter's accumulation cost
// (docs/benchmarks.md). The results equal make_voxel_key() and hash_voxel_key() bit for bit on
// every instruction set (tests/filter/voxel_key_batch_test.cpp), so images do not depend on the CPU.
#pragma once

#include <cstdint>

#include "pathspace/filters/hashed/voxel_key.h"

namespace pathspace {

inline constexpr int kVoxelKeyBatchSize = 64;

struct VoxelKeyBatch {
  // Inputs, one lane per vertex (fill lanes [0, n)). Vectors are kept whole and the kernel reads
  // them with stride-3 loads: filling them is a little cheaper than splitting each vector into
  // three float arrays (docs/benchmarks.md).
  alignas(64) Vec3 p[kVoxelKeyBatchSize], prev_p[kVoxelKeyBatchSize];
  alignas(64) Vec3 ng[kVoxelKeyBatchSize], ns[kVoxelKeyBatchSize], wo[kVoxelKeyBatchSize];
  alignas(64) float prefix_distance[kVoxelKeyBatchSize], roughness[kVoxelKeyBatchSize];
  alignas(64) uint64_t jitter_seed[kVoxelKeyBatchSize];  // mixed into the two jitter numbers
  alignas(64) uint8_t layer[kVoxelKeyBatchSize], selected[kVoxelKeyBatchSize];

  // Outputs.
  VoxelKey keys[kVoxelKeyBatchSize];
  VoxelHash hashes[kVoxelKeyBatchSize];

  void set_input(int lane, const VoxelKeyInput& v, uint64_t seed) {
    p[lane] = v.p, prev_p[lane] = v.prev_p;
    ng[lane] = v.ng, ns[lane] = v.ns, wo[lane] = v.wo;
    prefix_distance[lane] = v.prefix_distance;
    roughness[lane] = v.roughness;
    jitter_seed[lane] = seed;
    layer[lane] = v.layer;
    selected[lane] = v.selected;
  }
};

// Instruction sets with their own variant (x86-64-v4, x86-64-v3, the build's -march). All give the
// same keys; tests run each one the CPU supports.
enum class VoxelKeyIsa { baseline, avx2, avx512 };
bool voxel_key_isa_supported(VoxelKeyIsa isa);
VoxelKeyIsa widest_voxel_key_isa();

// Fills keys[0, n) and hashes[0, n) (n <= kVoxelKeyBatchSize). An unsupported isa falls back to
// the baseline.
void compute_voxel_keys(const VoxelKeySettings& settings, int n, VoxelKeyBatch* batch,
                        VoxelKeyIsa isa = widest_voxel_key_isa());

}  // namespace pathspace
