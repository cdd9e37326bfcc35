// The vectorised key batch (voxel_key_batch.h) must equal the scalar algorithm 1 (make_voxel_key,
// hash_voxel_key) bit for bit, for every option and on every instruction-set variant the CPU runs:
// otherwise the filtered image would depend on the machine.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "pathspace/filters/hashed/voxel_key_batch.h"
#include "pathspace/sampling/rng.h"

namespace pathspace {
namespace {

Vec3 random_unit(Pcg32& rng) {
  for (;;) {
    const Vec3 v(2.f * rng.next_float() - 1.f, 2.f * rng.next_float() - 1.f, 2.f * rng.next_float() - 1.f);
    const float l = length(v);
    if (l > 1e-3f && l <= 1.f) return v / l;
  }
}

// Vertices over many orders of magnitude of position and distance, both normal hemispheres,
// axis-aligned normals, glossy and diffuse layers, and a few degenerate values.
std::vector<VoxelKeyInput> random_inputs(int n, uint64_t seed) {
  Pcg32 rng(seed, 0x5eedull);
  std::vector<VoxelKeyInput> v(static_cast<size_t>(n));
  const Vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int i = 0; i < n; ++i) {
    VoxelKeyInput& in = v[size_t(i)];
    const float scale = std::ldexp(1.f, int(rng.next_float() * 24.f) - 12);
    in.p = (Vec3(rng.next_float(), rng.next_float(), rng.next_float()) - Vec3(0.5f)) * (2.f * scale);
    in.prev_p = (Vec3(rng.next_float(), rng.next_float(), rng.next_float()) - Vec3(0.5f)) * (2.f * scale);
    in.ng = i % 7 == 0 ? axes[i % 6] : random_unit(rng);
    in.ns = i % 5 == 0 ? in.ng : random_unit(rng);
    in.wo = random_unit(rng);
    in.prefix_distance = i % 3 == 0 ? 0.f : rng.next_float() * 4.f * scale;
    in.roughness = rng.next_float();
    in.layer = uint8_t(i % 3);
    in.selected = uint8_t(i % 4);
  }
  v[0].p = v[0].prev_p;  // zero segment length and prefix: the level's distance clamp
  v[0].prefix_distance = 0.f;
  v[1].ns = Vec3(0.f);  // degenerate shading normal (octahedral division by zero)
  v[2].prefix_distance = std::numeric_limits<float>::quiet_NaN();
  return v;
}

void expect_same_keys(const VoxelKeySettings& settings, VoxelKeyIsa isa, uint64_t seed) {
  const std::vector<VoxelKeyInput> inputs = random_inputs(4000, seed);
  for (size_t start = 0; start < inputs.size(); start += kVoxelKeyBatchSize) {
    // Partial batches too: n runs through every remainder of the vector width.
    const int n = int(std::min<size_t>(inputs.size() - start, size_t(1 + start / kVoxelKeyBatchSize % kVoxelKeyBatchSize)));
    VoxelKeyBatch batch;
    for (int j = 0; j < n; ++j) batch.set_input(j, inputs[start + size_t(j)], seed + start + size_t(j));
    compute_voxel_keys(settings, n, &batch, isa);
    for (int j = 0; j < n; ++j) {
      const uint64_t h = mix64(seed + start + size_t(j));
      const VoxelKey k = make_voxel_key(settings, inputs[start + size_t(j)], bits_to_unit_float(h), bits_to_unit_float(h << 24));
      const VoxelHash expected = hash_voxel_key(k, settings.normal);
      const VoxelKey& got = batch.keys[j];
      SCOPED_TRACE(testing::Message() << "vertex " << start + size_t(j) << " isa " << int(isa));
      ASSERT_EQ(got.cell[0], k.cell[0]);
      ASSERT_EQ(got.cell[1], k.cell[1]);
      ASSERT_EQ(got.cell[2], k.cell[2]);
      ASSERT_EQ(got.level, k.level);
      ASSERT_EQ(got.normal_bin, k.normal_bin);
      ASSERT_EQ(got.direction_bin, k.direction_bin);
      ASSERT_EQ(got.layer, k.layer);
      ASSERT_EQ(got.selected, k.selected);
      ASSERT_EQ(batch.hashes[j].index, expected.index);
      ASSERT_EQ(batch.hashes[j].fingerprint, expected.fingerprint);
    }
  }
}

TEST(VoxelKeyBatch, EqualsScalarKeysOnEverySupportedIsa) {
  int tested = 0;
  for (VoxelKeyIsa isa : {VoxelKeyIsa::baseline, VoxelKeyIsa::avx2, VoxelKeyIsa::avx512}) {
    if (!voxel_key_isa_supported(isa)) continue;
    ++tested;
    for (bool jitter : {true, false})
      for (NormalKeyMode normal : {NormalKeyMode::key, NormalKeyMode::fingerprint, NormalKeyMode::off}) {
        VoxelKeySettings s;
        s.jitter = jitter;
        s.normal = normal;
        s.pixel_angle = 2e-3f;
        s.normal_bins = normal == NormalKeyMode::key ? 5 : 7;
        expect_same_keys(s, isa, 17 + uint64_t(normal) * 3 + uint64_t(jitter));
      }
  }
  EXPECT_GE(tested, 1);
}

}  // namespace
}  // namespace pathspace
