// The consistent filter (Keller, Dahm, Binder 2014; filters/consistent_filter.h) against an
// independent brute-force evaluation of eq. 1 and eq. 2 on synthetic vertices: every vertex gets
// exactly the mean of the similar vertices of its batch inside its ball (itself included), with the
// radius r0 (P / n)^alpha, n counting the paths so far over passes, batches and a save/restore; for
// any thread count, batch size and number of iterations. Contributions are multiples of 2^-10, so
// every sum is exact in any order and the comparison is exact. Also: a constant is a fixed point of
// the averaging for any radius and weights (the furnace property of sec. 2), and filtering switches
// itself off once every ball holds only its own vertex (sec. 2.2).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "pathspace/filters/consistent_filter.h"
#include "pathspace/filters/vertex_buffer.h"
#include "pathspace/materials/bsdf_layers.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/sampling/rng.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace {
namespace {

constexpr size_t kPixels = 1024;

// Vertices on the floor and the back wall of a unit box, clustered so balls hold 1 to ~100 vertices;
// a third of the slots empty; two records per path (the second glossy); normals of some flipped.
VertexBuffer make_buffer(size_t paths, uint64_t seed, bool constant = false) {
  VertexBuffer b;
  b.resize(paths, 2);
  Pcg32 rng(seed, 3);
  for (size_t path = 0; path < paths; ++path) {
    const int count = int(rng.next_bounded(3));
    b.count[path] = uint8_t(count);
    for (int r = 0; r < count; ++r) {
      const size_t i = b.slot(path, r);
      const float u = rng.next_float(), v = rng.next_float();
      const bool floor = rng.next_float() < 0.5f;
      Vec3 n = floor ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
      if (rng.next_bounded(10) == 0) n = -n;
      b.position[i] = floor ? Vec3(u * u, 0.f, v) : Vec3(u, v * v, -1.f);
      b.previous_position[i] = b.position[i] + Vec3(0.f, 0.5f, 2.f);
      b.prefix_distance[i] = float(r);
      b.geometric_normal[i] = b.shading_normal[i] = n;
      b.incident[i] = normalize(rng.next_float() < 0.5f ? Vec3(0.f, 0.5f, 2.f) : Vec3(1.f, 0.5f, 0.f));
      b.layer[i] = r == 0 ? kLayerDiffuse : kLayerGlossy;
      b.selected[i] = uint8_t(r);
      b.throughput[i] = rng.next_float() < 0.7f ? Rgb(0.5f, 0.5f, 0.5f) : Rgb(0.8f, 0.2f, 0.2f);
      // Visibility: most see the one light; hemisphere rays of a few lengths, some escaping.
      b.visible_lights[i] = rng.next_bounded(5) == 0 ? 0u : 1u;
      const float lengths[4] = {1.f, 1.1f, 2.f, std::numeric_limits<float>::infinity()};
      b.open_distance[i] = lengths[rng.next_bounded(8) == 0 ? 2 + rng.next_bounded(2) : rng.next_bounded(2)];
      b.contribution[i] = constant ? Rgb(0.3f, 1.7f, 0.05f)
                                   : Rgb(float(rng.next_bounded(4096)), float(rng.next_bounded(4096)), float(rng.next_bounded(4096))) *
                                         (1.f / 1024.f);
    }
  }
  return b;
}

bool similar(const FilterVertex& a, const FilterVertex& b, const ConsistentFilterSettings& s) {
  if (a.layer != b.layer || a.selected != b.selected) return false;
  if ((s.weights & kWeightNormal) && dot(a.ns, b.ns) < s.normal_threshold) return false;
  if (s.weights & kWeightAlbedo) {
    const Rgb d = a.throughput - b.throughput;
    if (std::fabs(d.r) > s.albedo_threshold || std::fabs(d.g) > s.albedo_threshold || std::fabs(d.b) > s.albedo_threshold) return false;
    if (a.layer != kLayerDiffuse && dot(a.wo, b.wo) < s.direction_threshold) return false;
  }
  if (s.weights & kWeightVisibility) {
    if (a.visible_lights != b.visible_lights) return false;
    const float la = a.open_distance, lb = b.open_distance;
    const bool same_length =
        la == lb || (std::isfinite(la) && std::isfinite(lb) && std::fabs(la - lb) <= s.visibility_threshold * std::max(la, lb));
    if (!same_length) return false;
  }
  return true;
}

bool similar(const VertexBuffer& b, size_t i, size_t j, const ConsistentFilterSettings& s) { return similar(b.record(i), b.record(j), s); }

SlotValues contributions(const VertexBuffer& b) {
  SlotValues v;
  b.copy_contributions(&v);
  return v;
}

// Eq. 1 by brute force over each batch, eq. 2 with n = paths_before + paths up to the batch's end.
SlotValues brute_force(const VertexBuffer& b, const ConsistentFilterSettings& s, uint64_t paths_before) {
  SlotValues out = contributions(b);
  // Batch budget 0 is "an eighth of the RAM": one batch for these sizes.
  const size_t per_batch = s.batch_memory_mb > 0.0
                               ? std::max<size_t>(1, size_t(s.batch_memory_mb * 1048576.0) / ConsistentFilter::bytes_per_record())
                               : std::numeric_limits<size_t>::max();
  for (size_t p = 0; p < b.paths();) {
    std::vector<size_t> slots;
    size_t q = p;
    for (; q < b.paths() && (slots.empty() || slots.size() + b.count[q] <= per_batch); ++q)
      for (int r = 0; r < b.count[q]; ++r) slots.push_back(b.slot(q, r));
    const double scale = std::pow(double(kPixels) / double(paths_before + q), double(s.alpha));
    std::vector<Rgb> in(slots.size());
    for (size_t k = 0; k < slots.size(); ++k) in[k] = b.contribution[slots[k]];
    for (int it = 0; it < s.iterations; ++it) {
      std::vector<Rgb> next(slots.size());
      for (size_t k = 0; k < slots.size(); ++k) {
        const float r = float(double(s.radius) * scale);
        double sum[3] = {0, 0, 0};
        int count = 0;
        for (size_t l = 0; l < slots.size(); ++l) {
          if (distance_squared(b.position[slots[l]], b.position[slots[k]]) > r * r || !similar(b, slots[k], slots[l], s)) continue;
          sum[0] += in[l].r, sum[1] += in[l].g, sum[2] += in[l].b;
          ++count;
        }
        next[k] = Rgb(float(sum[0] / count), float(sum[1] / count), float(sum[2] / count));
      }
      in.swap(next);
    }
    for (size_t k = 0; k < slots.size(); ++k) out[slots[k]] = in[k];
    p = q;
  }
  return out;
}

void expect_same(const VertexBuffer& b, const SlotValues& got, const SlotValues& want) {
  ASSERT_EQ(got.size(), want.size());
  int wrong = 0;
  for (size_t p = 0; p < b.paths(); ++p)
    for (int r = 0; r < b.count[p]; ++r) {
      const size_t i = b.slot(p, r);
      if (std::memcmp(&got[i], &want[i], sizeof(Rgb)) != 0 && ++wrong <= 5)
        ADD_FAILURE() << "slot " << i << ": " << got[i].r << "," << got[i].g << "," << got[i].b << " want " << want[i].r << ","
                      << want[i].g << "," << want[i].b;
    }
  EXPECT_EQ(wrong, 0);
}

struct Case {
  const char* name;
  uint32_t weights;
  int iterations;
  double batch_mb;  // small: several batches per pass
  int threads;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class ConsistentAverages : public ::testing::TestWithParam<Case> {};

TEST_P(ConsistentAverages, EqualBruteForceOverThreePasses) {
  const Case& c = GetParam();
  const Scene scene = make_builtin_scene("cornell-box", 32, 32);
  ConsistentFilterSettings s;
  s.radius = 0.06f;
  s.weights = c.weights;
  s.iterations = c.iterations;
  s.batch_memory_mb = c.batch_mb;
  ConsistentFilter filter(s, scene.camera, kPixels);
  ThreadLimit limit(c.threads);
  uint64_t paths = 0;
  for (uint32_t pass = 0; pass < 3; ++pass) {
    SCOPED_TRACE("pass " + std::to_string(pass));
    const VertexBuffer b = make_buffer(kPixels, 100 + pass);
    SlotValues got;
    filter.filter(b, 0, pass, &got);
    filter.end_pass();
    expect_same(b, got, brute_force(b, s, paths));
    paths += b.paths();
    EXPECT_EQ(filter.paths_so_far(), paths);
  }
  EXPECT_GT(filter.stats().max_neighbours_last, c.batch_mb < 1.0 ? 2u : 5u) << "the balls must hold several vertices, or nothing was tested";
  EXPECT_EQ(filter.stats().switched_off_after, 0u);
}

INSTANTIATE_TEST_SUITE_P(Variants, ConsistentAverages,
                         ::testing::Values(Case{"weights_1_thread", kWeightNormal | kWeightAlbedo | kWeightVisibility, 1, 4.0, 1},
                                           Case{"weights_2_threads", kWeightNormal | kWeightAlbedo | kWeightVisibility, 1, 4.0, 2},
                                           Case{"normal_albedo", kWeightNormal | kWeightAlbedo, 1, 4.0, 2},
                                           Case{"visibility_only", kWeightVisibility, 1, 4.0, 2},
                                           Case{"no_weights", 0u, 1, 4.0, 2}, Case{"normal_only", kWeightNormal, 1, 4.0, 2},
                                           Case{"three_iterations", kWeightNormal | kWeightAlbedo, 3, 4.0, 2},
                                           Case{"small_batches", kWeightNormal, 2, 0.05, 2}),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

// Anti-aliasing queries (sec. 3, fig. 5): a query point gets the mean of the similar data vertices
// in its ball (it has no contribution of its own), with the radius of the batch filtered last;
// with no similar vertex it is not found. With iterations, it averages the last iteration's input.
TEST(ConsistentFilter, QueriesAverageTheFilteredBatchAroundPointsOutsideIt) {
  const Scene scene = make_builtin_scene("cornell-box", 32, 32);
  for (const int iterations : {1, 2}) {
    SCOPED_TRACE("iterations " + std::to_string(iterations));
    ConsistentFilterSettings s;
    s.radius = 0.06f;
    s.iterations = iterations;
    s.aa_paths = 1;
    ConsistentFilter filter(s, scene.camera, kPixels);
    EXPECT_EQ(filter.needs().query_paths, 1);
    EXPECT_TRUE(filter.needs().visibility);
    const VertexBuffer data = make_buffer(kPixels, 21), queries = make_buffer(kPixels, 22);
    SlotValues filtered, values;
    std::vector<uint8_t> found;
    filter.filter(data, 0, 0, &filtered);
    filter.query(queries, &values, &found);
    filter.end_pass();
    // What the queries average: the contributions after iterations - 1 rounds of eq. 1.
    ConsistentFilterSettings before = s;
    before.iterations = iterations - 1;
    const SlotValues averaged = iterations > 1 ? brute_force(data, before, 0) : contributions(data);
    const float r = float(double(s.radius) * std::pow(double(kPixels) / double(kPixels), double(s.alpha)));
    int checked = 0, empty = 0;
    for (size_t qp = 0; qp < queries.paths(); ++qp)
      for (int qr = 0; qr < queries.count[qp]; ++qr) {
        const size_t i = queries.slot(qp, qr);
        double sum[3] = {0, 0, 0};
        int count = 0;
        for (size_t dp = 0; dp < data.paths(); ++dp)
          for (int dr = 0; dr < data.count[dp]; ++dr) {
            const size_t j = data.slot(dp, dr);
            if (distance_squared(data.position[j], queries.position[i]) > r * r) continue;
            if (!similar(queries.record(i), data.record(j), s)) continue;
            sum[0] += averaged[j].r, sum[1] += averaged[j].g, sum[2] += averaged[j].b;
            ++count;
          }
        ASSERT_EQ(found[i] != 0, count > 0) << "slot " << i;
        if (count == 0) {
          ++empty;
          continue;
        }
        const Rgb want(float(sum[0] / count), float(sum[1] / count), float(sum[2] / count));
        ASSERT_EQ(std::memcmp(&values[i], &want, sizeof(Rgb)), 0) << "slot " << i << ": " << values[i].r << " want " << want.r;
        ++checked;
      }
    EXPECT_GT(checked, 100);
    EXPECT_GT(empty, 0) << "some queries must find nothing similar, or that case was not tested";
  }
}

TEST(ConsistentFilter, SmallBudgetFiltersInSeveralBatches) {
  const Scene scene = make_builtin_scene("cornell-box", 32, 32);
  ConsistentFilterSettings s;
  s.radius = 0.06f;
  s.batch_memory_mb = 0.01;
  ConsistentFilter filter(s, scene.camera, kPixels);
  const VertexBuffer b = make_buffer(kPixels, 5);
  SlotValues got;
  filter.filter(b, 0, 0, &got);
  const size_t per_batch = size_t(0.01 * 1048576.0) / ConsistentFilter::bytes_per_record();
  EXPECT_GE(filter.stats().batches, b.total_records() / per_batch);
  EXPECT_LE(filter.stats().largest_batch, per_batch);
}

TEST(ConsistentFilter, ConstantIsAFixedPointForAnyRadiusAndWeights) {
  const Scene scene = make_builtin_scene("cornell-box", 32, 32);
  for (const float radius : {0.f, 1e-4f, 0.05f, 0.5f, 100.f})
    for (const uint32_t weights : {0u, uint32_t(kWeightNormal | kWeightAlbedo | kWeightVisibility)})
      for (const int iterations : {1, 3}) {
        SCOPED_TRACE("radius " + std::to_string(radius) + " weights " + std::to_string(weights));
        ConsistentFilterSettings s;
        s.radius = radius;  // 0: from 3x3 pixels
        s.weights = weights;
        s.iterations = iterations;
        ConsistentFilter filter(s, scene.camera, kPixels);
        const VertexBuffer b = make_buffer(kPixels, 9, true);
        SlotValues got;
        filter.filter(b, 0, 0, &got);
        for (size_t p = 0; p < b.paths(); ++p)
          for (int r = 0; r < b.count[p]; ++r) {
            const Rgb& c = got[b.slot(p, r)];
            ASSERT_TRUE(c.r == 0.3f && c.g == 1.7f && c.b == 0.05f) << c.r << "," << c.g << "," << c.b;
          }
      }
}

TEST(ConsistentFilter, SwitchesOffWhenEveryBallHoldsOnlyItself) {
  const Scene scene = make_builtin_scene("cornell-box", 32, 32);
  ConsistentFilterSettings s;
  s.radius = 1e-9f;
  ConsistentFilter filter(s, scene.camera, kPixels);
  const VertexBuffer b = make_buffer(kPixels, 11);
  SlotValues got;
  filter.filter(b, 0, 0, &got);
  filter.end_pass();
  EXPECT_EQ(filter.stats().max_neighbours_last, 1u);
  EXPECT_EQ(filter.stats().switched_off_after, 1u);
  expect_same(b, got, contributions(b));
  filter.filter(b, 0, 1, &got);
  filter.end_pass();
  expect_same(b, got, contributions(b));
  EXPECT_EQ(filter.paths_so_far(), 2 * kPixels);
}

TEST(ConsistentFilter, SavedStateContinuesTheRadiusSequence) {
  const Scene scene = make_builtin_scene("cornell-box", 32, 32);
  ConsistentFilterSettings s;
  s.radius = 0.06f;
  ConsistentFilter a(s, scene.camera, kPixels), b(s, scene.camera, kPixels);
  SlotValues got_a, got_b;
  a.filter(make_buffer(kPixels, 1), 0, 0, &got_a);
  StateWriter out;
  a.save_state(out);
  StateReader in(out.bytes());
  b.load_state(in);
  const VertexBuffer next = make_buffer(kPixels, 2);
  a.filter(next, 0, 1, &got_a);
  b.filter(next, 0, 1, &got_b);
  {
    SCOPED_TRACE("restored against continued");
    expect_same(next, got_b, got_a);
  }
  SCOPED_TRACE("continued against brute force");
  expect_same(next, got_a, brute_force(next, s, kPixels));
  EXPECT_DOUBLE_EQ(b.stats().radius_scale_last, std::pow(0.5, 0.25));
}

}  // namespace
}  // namespace pathspace
