// Every vertex gets exactly the average of the vertices that share its voxel key (Binder et al.
// 2021, sec. 3.2), computed here independently from the scalar key (HashedFilter::key_of): with
// empty record slots between the vertices, several records per path, unrepresentable
// contributions, and the two low-count fallbacks (26 neighbours, sec. 3.3.1; one level coarser,
// sec. 3.3.2). Fixed-point sums make the expected values exact, so the comparison is exact. And a
// pass's table holds nothing of the pass before (the clear of only the cells it used).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "pathspace/filters/hashed/hashed_filter.h"
#include "pathspace/filters/vertex_buffer.h"
#include "pathspace/sampling/rng.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace {
namespace {

using KeyTuple = std::array<int64_t, 8>;

KeyTuple tuple_of(const VoxelKey& k) {
  return {k.cell[0], k.cell[1], k.cell[2], k.level, k.normal_bin, k.direction_bin, k.layer, k.selected};
}

struct Sum {
  uint64_t s[3] = {0, 0, 0};
  uint64_t count = 0;
};

// Vertices on two planes, denser towards one corner so that voxels range from one to hundreds of
// vertices; about a third of the slots are empty; `huge_fraction` of them carry values near the
// largest one the table accumulates.
VertexBuffer make_buffer(size_t paths, int records_per_path, uint64_t seed, float huge_fraction) {
  VertexBuffer b;
  b.resize(paths, records_per_path);
  Pcg32 rng(seed, 7);
  for (size_t path = 0; path < paths; ++path) {
    const int count = int(rng.next_bounded(uint32_t(records_per_path + 1)));
    b.count[path] = uint8_t(count);
    for (int r = 0; r < count; ++r) {
      const size_t i = b.slot(path, r);
      const float u = rng.next_float(), v = rng.next_float();
      const bool floor = rng.next_float() < 0.5f;
      const Vec3 n = floor ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
      b.position[i] = floor ? Vec3(u * u * u, 0.f, v * v) : Vec3(u * u, v * v * v, -1.f);
      b.previous_position[i] = b.position[i] + Vec3(0.3f, 0.8f, 1.5f);
      b.prefix_distance[i] = 0.5f * float(r);
      b.geometric_normal[i] = b.shading_normal[i] = n;
      b.incident[i] = normalize(Vec3(0.3f, 0.8f, 1.5f));
      b.roughness[i] = r == 0 ? 1.f : 0.2f;  // the second record is glossy: direction in the key
      b.selected[i] = uint8_t(r);
      b.contribution[i] = Rgb(rng.next_float(), 2.f * rng.next_float(), 0.5f * rng.next_float());
      // Near the largest accumulated value (2^18): sums of a few hundred need all 48+ bits.
      if (rng.next_float() < huge_fraction) b.contribution[i] = Rgb(2.5e5f, 1.9e5f, 2.2e5f) * (0.9f + 0.1f * rng.next_float());
      if (rng.next_bounded(97) == 0) b.contribution[i] = Rgb(-1.f, 0.f, 0.f);  // not accumulated
      if (rng.next_bounded(101) == 0) b.contribution[i].g = std::numeric_limits<float>::quiet_NaN();
    }
  }
  return b;
}

enum class Fallback { none, neighbours, coarser };

// What a vertex adds to its voxel under --psf-clamp (max_luminance > 0): the colour scaled to that luminance.
Rgb clamped(const Rgb& c, float max_luminance) {
  const float y = 0.212671f * c.r + 0.715160f * c.g + 0.072169f * c.b;  // Rgb luminance()
  return max_luminance > 0.f && y > max_luminance ? c * (max_luminance / y) : c;
}

void expect_exact_averages(Fallback fallback, int records_per_path, int threads_seed, float psf_scale = 3.f,
                           float max_luminance = 0.f) {
  const Scene scene = make_builtin_scene("cornell-box", 64, 64);
  HashedFilterSettings settings;
  settings.key.psf_scale = psf_scale;
  settings.min_count = 6;
  settings.neighbour_search = fallback == Fallback::neighbours;
  settings.multi_level = fallback == Fallback::coarser;
  settings.max_luminance = max_luminance;
  HashedFilter filter(settings, scene.camera, size_t(1) << 16);  // large enough: no probe-limit fallbacks
  const VertexBuffer b = make_buffer(20000, records_per_path, uint64_t(threads_seed), psf_scale > 10.f ? 0.5f : 0.f);
  const uint64_t seed = 42;
  const uint32_t pass = 3;
  SlotValues filtered;
  filter.filter(b, seed, pass, &filtered);
  ASSERT_EQ(filter.stats().probe_failures, 0u);

  std::map<KeyTuple, Sum> voxels, coarse_voxels;
  std::vector<VoxelKey> keys(filtered.size());
  std::vector<bool> accumulated(filtered.size(), false);
  for (size_t path = 0; path < b.paths(); ++path)
    for (int r = 0; r < b.count[path]; ++r) {
      const size_t i = b.slot(path, r);
      uint64_t fixed[3];
      if (!to_fixed_point(clamped(b.contribution[i], max_luminance), fixed)) continue;
      accumulated[i] = true;
      keys[i] = filter.key_of(b, i, seed, pass);
      for (Sum* s : {&voxels[tuple_of(keys[i])], &coarse_voxels[tuple_of(coarser_key(keys[i]))]}) {
        for (int c = 0; c < 3; ++c) s->s[c] += fixed[c];
        ++s->count;
      }
    }
  uint64_t largest = 0;
  for (const auto& [key, sum] : voxels) largest = std::max(largest, sum.count);
  if (psf_scale > 10.f) {
    ASSERT_GT(largest, 1000u) << "large voxels: the local cache hands a voxel to the table every 255 vertices";
  } else {
    ASSERT_GT(voxels.size(), 500u);
  }

  size_t low = 0, checked = 0;
  for (size_t path = 0; path < b.paths(); ++path)
    for (int r = 0; r < b.count[path]; ++r) {
      const size_t i = b.slot(path, r);
      const Rgb got = filtered[i];
      SCOPED_TRACE(testing::Message() << "slot " << i);
      if (!accumulated[i]) {  // keeps its own contribution (NaN included)
        for (int c = 0; c < 3; ++c)
          if (std::isnan(b.contribution[i][c])) ASSERT_TRUE(std::isnan(got[c]));
          else ASSERT_EQ(got[c], b.contribution[i][c]);
        continue;
      }
      const Sum own = voxels.at(tuple_of(keys[i]));
      Sum expected = own;
      if (own.count < uint64_t(settings.min_count)) {
        ++low;
        if (fallback == Fallback::neighbours) {
          expected = Sum{};
          for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
              for (int dx = -1; dx <= 1; ++dx) {
                VoxelKey n = keys[i];
                n.cell[0] += dx, n.cell[1] += dy, n.cell[2] += dz;
                const auto it = voxels.find(tuple_of(n));
                if (it == voxels.end()) continue;
                for (int c = 0; c < 3; ++c) expected.s[c] += it->second.s[c];
                expected.count += it->second.count;
              }
        } else if (fallback == Fallback::coarser) {
          const Sum coarse = coarse_voxels.at(tuple_of(coarser_key(keys[i])));
          if (coarse.count > own.count) expected = coarse;
        }
      }
      const Rgb want = from_fixed_point(expected.s, expected.count);
      ASSERT_EQ(got.r, want.r);
      ASSERT_EQ(got.g, want.g);
      ASSERT_EQ(got.b, want.b);
      ++checked;
    }
  if (psf_scale > 10.f) return;
  EXPECT_GT(low, checked / 20) << "the low-count fallback must be exercised";
  EXPECT_LT(low, checked / 2) << "most voxels must hold several vertices";
}

TEST(HashedFilterAverages, EveryVertexGetsItsVoxelAverage) { expect_exact_averages(Fallback::none, 1, 1); }
TEST(HashedFilterAverages, SeveralRecordsPerPath) { expect_exact_averages(Fallback::none, 2, 2); }
// Voxels with thousands of vertices, half of them near the largest accumulated value: the local
// cache's 48-bit partial sums must reach the table before they overflow (local_voxel_cache.h).
TEST(HashedFilterAverages, LargeVoxels) { expect_exact_averages(Fallback::none, 1, 5, 60.f); }
TEST(HashedFilterAverages, NeighbourSearchAddsTheTwentySixNeighbours) {
  expect_exact_averages(Fallback::neighbours, 2, 3);
}
TEST(HashedFilterAverages, MultiLevelUsesTheCoarserVoxel) { expect_exact_averages(Fallback::coarser, 2, 4); }
// --psf-clamp: every vertex adds its contribution with the luminance clamped (about half of them
// here are above the limit), and the average is that of the clamped values.
TEST(HashedFilterAverages, ClampedContributionsAreAveraged) { expect_exact_averages(Fallback::none, 1, 5, 3.f, 0.8f); }

// A pass clears only the cells the pass before used when they are few (HashedFilter::gather_step_cells),
// found through the vertices that reached the table, including those the overflow settling gave a
// cell. After every pass the table must hold exactly that pass's accumulated vertices, and without
// --temporal no key without vertices. One probe per key makes home cells collide, so windows are
// settled (without --temporal); 3000 records in 65,536 cells are few enough to be cleared one by one.
TEST(HashedFilterAverages, EachPassFindsATableHoldingNothingOfTheLast) {
  const Scene scene = make_builtin_scene("cornell-box", 64, 64);
  for (const TemporalMode mode : {TemporalMode::off, TemporalMode::integrate}) {
    HashedFilterSettings settings;
    settings.key.psf_scale = 2.f;
    settings.max_probes = 1;
    settings.temporal.mode = mode;
    HashedFilter filter(settings, scene.camera, size_t(1) << 16);
    SlotValues filtered;
    for (uint32_t pass = 0; pass < 6; ++pass) {
      const VertexBuffer b = make_buffer(3000, 1, 100 + pass, 0.f);
      filter.filter(b, 42, pass, &filtered);
      uint64_t accumulated = 0;
      for (size_t path = 0; path < b.paths(); ++path)
        for (int r = 0; r < b.count[path]; ++r) {
          uint64_t fixed[3];
          accumulated += to_fixed_point(b.contribution[b.slot(path, r)], fixed) ? 1 : 0;
        }
      const VoxelHashTableView view = filter.table().view();
      uint64_t counted = 0, keys_without_vertices = 0;
      for (uint64_t c = 0; c <= view.mask; ++c) {
        counted += view.cells[c].count;
        keys_without_vertices += view.fingerprints[c] != kEmptyFingerprint && view.cells[c].count == 0 ? 1 : 0;
      }
      EXPECT_EQ(counted, accumulated - filter.stats().probe_failures_last) << "pass " << pass << ", mode " << int(mode);
      if (mode == TemporalMode::off) {
        EXPECT_EQ(keys_without_vertices, 0u) << "pass " << pass;
      }
    }
    if (mode == TemporalMode::off) {
      EXPECT_GT(filter.stats().settled_passes, 0u);  // a settled cell is cleared too
    }
  }
}

}  // namespace
}  // namespace pathspace
