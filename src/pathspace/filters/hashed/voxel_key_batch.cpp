#include "pathspace/filters/hashed/voxel_key_batch.h"

#include <bit>
#include <cmath>

// One variant per vector width (AVX-512, AVX2, the build's baseline), chosen at run time. This
// file is compiled with -ffp-contract=off: fused multiply-adds in the wide variants would round
// differently from the baseline, and the keys must not depend on the CPU.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define PS_WIDE_VARIANTS 1
#else
#define PS_WIDE_VARIANTS 0
#endif

namespace pathspace {

namespace {

constexpr int kN = kVoxelKeyBatchSize;

// Lane-wise forms of the voxel_key.h helpers that branch or call (level_of_detail, octahedral_bin),
// written with selects so that they vectorise; each performs the same float operations in the same
// order as its scalar original. mix64 and power_of_two are used as they are.
inline int lod_lane(float psf_pixel, float distance) {
  const float target = psf_pixel * (distance > 1e-6f ? distance : 1e-6f) * 1.41421356f;
  const int e = int((std::bit_cast<uint32_t>(target) >> 23) & 0xffu) - 127;
  return e < -60 ? -60 : (e > 60 ? 60 : e);
}

inline uint32_t octahedral_lane(float x, float y, float z, int bins) {
  const float l1 = fabsf(x) + fabsf(y) + fabsf(z);
  const float u = x / l1, w = y / l1;
  const float fu = (1.f - fabsf(w)) * (u >= 0.f ? 1.f : -1.f);
  const float fw = (1.f - fabsf(u)) * (w >= 0.f ? 1.f : -1.f);
  const float uu = z < 0.f ? fu : u;
  const float ww = z < 0.f ? fw : w;
  int iu = int((uu * 0.5f + 0.5f) * float(bins));
  int iw = int((ww * 0.5f + 0.5f) * float(bins));
  iu = iu < 0 ? 0 : (iu > bins - 1 ? bins - 1 : iu);
  iw = iw < 0 ? 0 : (iw > bins - 1 ? bins - 1 : iw);
  return uint32_t(1 + iu * bins + iw);
}


// Algorithm 1 on lanes [0, n); see make_voxel_key() for the meaning of each step. Options are
// template arguments or bit masks: a select on a scalar flag inside the loop keeps it scalar.
// Always inlined, so that each variant below vectorises it for its own width.
template <bool kJitter>
[[gnu::always_inline]] inline void compute_lanes(const VoxelKeySettings& s, int n, VoxelKeyBatch& b) {
  alignas(64) int32_t cx[kN], cy[kN], cz[kN], level[kN];
  alignas(64) uint32_t nbin[kN], dbin[kN], fingerprint[kN];
  alignas(64) uint64_t index[kN];
  const float psf_pixel = s.psf_scale * s.pixel_angle;
  const uint32_t normal_mask = s.normal != NormalKeyMode::off ? ~0u : 0u;
  const uint64_t normal_index_mask = s.normal == NormalKeyMode::key ? ~uint64_t(0) : 0u;
  const int normal_bins = s.normal_bins, direction_bins = s.direction_bins;
  const float glossy = s.glossy_roughness;

#pragma omp simd
  for (int j = 0; j < n; ++j) {
    const float qx = b.p[j].x - b.prev_p[j].x, qy = b.p[j].y - b.prev_p[j].y, qz = b.p[j].z - b.prev_p[j].z;
    const int l = lod_lane(psf_pixel, b.prefix_distance[j] + sqrtf(qx * qx + qy * qy + qz * qz));
    // Jitter in the tangent plane of the geometric normal (Frame(ng): Duff et al. 2017).
    const uint64_t h = mix64(b.jitter_seed[j]);
    // 24-bit values, converted through int32 (exact) because a vector u64 -> float needs AVX-512.
    const float u0 = float(int32_t(h >> 40)) * 0x1p-24f, u1 = float(int32_t((h << 24) >> 40)) * 0x1p-24f;
    const float nx = b.ng[j].x, ny = b.ng[j].y, nz = b.ng[j].z;
    const float sign = copysignf(1.f, nz);
    const float a = -1.f / (sign + nz);
    const float bb = nx * ny * a;
    const float sx = 1.f + sign * nx * nx * a, sy = sign * bb, sz = -sign * nx;
    const float tx = bb, ty = sign + ny * ny * a, tz = -ny;
    const float edge = power_of_two(l);
    const float j0 = (u0 - 0.5f) * edge, j1 = (u1 - 0.5f) * edge;
    float xx = b.p[j].x, xy = b.p[j].y, xz = b.p[j].z;
    int lj = l;
    if constexpr (kJitter) {
      xx = xx + sx * j0 + tx * j1;
      xy = xy + sy * j0 + ty * j1;
      xz = xz + sz * j0 + tz * j1;
      const float rx = xx - b.prev_p[j].x, ry = xy - b.prev_p[j].y, rz = xz - b.prev_p[j].z;
      lj = lod_lane(psf_pixel, b.prefix_distance[j] + sqrtf(rx * rx + ry * ry + rz * rz));
    }
    const float inv_edge = power_of_two(-lj);
    cx[j] = int32_t(floorf(xx * inv_edge));
    cy[j] = int32_t(floorf(xy * inv_edge));
    cz[j] = int32_t(floorf(xz * inv_edge));
    level[j] = lj;
    // Both bins are computed for every lane and then selected: a branch would keep the loop scalar.
    const uint32_t normal_bin = octahedral_lane(b.ns[j].x, b.ns[j].y, b.ns[j].z, normal_bins);
    const uint32_t direction_bin = octahedral_lane(b.wo[j].x, b.wo[j].y, b.wo[j].z, direction_bins);
    nbin[j] = normal_bin & normal_mask;
    dbin[j] = b.roughness[j] < glossy ? direction_bin : 0u;

    // hash_voxel_key(): the table index and the 32-bit fingerprint (sec. 3.2.1).
    const uint64_t position = (uint64_t(uint32_t(cx[j])) << 32) | uint32_t(cy[j]);
    const uint64_t attributes = (uint64_t(uint32_t(cz[j])) << 32) | (uint64_t(uint8_t(lj)) << 24) |
                                (uint64_t(b.layer[j] & 3u) << 22) | (uint64_t(b.selected[j] & 3u) << 20) |
                                (uint64_t(dbin[j] & 1023u) << 10);
    const uint64_t normal_word = uint64_t(nbin[j] & 1023u);
    index[j] = mix64(position ^ mix64(attributes | (normal_word & normal_index_mask)));
    const uint64_t f = mix64(mix64((attributes | normal_word) ^ 0x5bd1e9955bd1e995ull) + position * 0x2545f4914f6cdd1dull);
    const uint32_t fp = uint32_t(f >> 32);
    fingerprint[j] = fp == kEmptyFingerprintValue ? 1u : fp;
  }

  for (int j = 0; j < n; ++j) {
    VoxelKey& k = b.keys[j];
    k.cell[0] = cx[j];
    k.cell[1] = cy[j];
    k.cell[2] = cz[j];
    k.level = int16_t(level[j]);
    k.normal_bin = uint16_t(nbin[j]);
    k.direction_bin = uint16_t(dbin[j]);
    k.layer = uint8_t(b.layer[j]);
    k.selected = uint8_t(b.selected[j]);
    b.hashes[j] = VoxelHash{index[j], fingerprint[j]};
  }
}

void keys_baseline(const VoxelKeySettings& s, int n, VoxelKeyBatch& b) {
  s.jitter ? compute_lanes<true>(s, n, b) : compute_lanes<false>(s, n, b);
}

#if PS_WIDE_VARIANTS
__attribute__((target("arch=x86-64-v3"))) void keys_avx2(const VoxelKeySettings& s, int n, VoxelKeyBatch& b) {
  s.jitter ? compute_lanes<true>(s, n, b) : compute_lanes<false>(s, n, b);
}
__attribute__((target("arch=x86-64-v4"))) void keys_avx512(const VoxelKeySettings& s, int n, VoxelKeyBatch& b) {
  s.jitter ? compute_lanes<true>(s, n, b) : compute_lanes<false>(s, n, b);
}
#endif

}  // namespace

bool voxel_key_isa_supported(VoxelKeyIsa isa) {
  switch (isa) {
    case VoxelKeyIsa::baseline: return true;
#if PS_WIDE_VARIANTS
    case VoxelKeyIsa::avx2: return __builtin_cpu_supports("x86-64-v3");
    case VoxelKeyIsa::avx512: return __builtin_cpu_supports("x86-64-v4");
#else
    case VoxelKeyIsa::avx2:
    case VoxelKeyIsa::avx512: return false;
#endif
  }
  return false;
}

VoxelKeyIsa widest_voxel_key_isa() {
  static const VoxelKeyIsa widest = voxel_key_isa_supported(VoxelKeyIsa::avx512) ? VoxelKeyIsa::avx512
                                    : voxel_key_isa_supported(VoxelKeyIsa::avx2) ? VoxelKeyIsa::avx2
                                                                                 : VoxelKeyIsa::baseline;
  return widest;
}

void compute_voxel_keys(const VoxelKeySettings& settings, int n, VoxelKeyBatch* batch, VoxelKeyIsa isa) {
  n = n < kN ? n : kN;
  if (!voxel_key_isa_supported(isa)) isa = VoxelKeyIsa::baseline;
#if PS_WIDE_VARIANTS
  if (isa == VoxelKeyIsa::avx512) return keys_avx512(settings, n, *batch);
  if (isa == VoxelKeyIsa::avx2) return keys_avx2(settings, n, *batch);
#endif
  keys_baseline(settings, n, *batch);
}

}  // namespace pathspace
