// The consistent filter's gather (filters/consistent_gather.h) against the plain walk it replaced:
// every record of the grid's lists in the ball (HashGridView::for_each_in_radius), the binary
// weights tested one record at a time, the values summed in walk order. The two must agree bit for
// bit (same records, same order of additions) on cells of one record and of hundreds (the scalar
// and the vectorised path), with every weight on and off, and with non-finite values left out.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "pathspace/filters/consistent_gather.h"
#include "pathspace/hashgrid/hash_grid.h"
#include "pathspace/materials/bsdf_layers.h"

namespace pathspace {
namespace {

// The weights of sec. 2.1 as the scalar filter wrote them.
bool similar(const SimilarityKey& a, const SimilarityKey& b, const ConsistentFilterSettings& s) {
  if (a.layer != b.layer || a.selected != b.selected) return false;
  if ((s.weights & kWeightNormal) && dot(a.normal, b.normal) < s.normal_threshold) return false;
  if (s.weights & kWeightAlbedo) {
    const Rgb d = a.throughput - b.throughput;
    if (std::fabs(d.r) > s.albedo_threshold || std::fabs(d.g) > s.albedo_threshold || std::fabs(d.b) > s.albedo_threshold) return false;
    if (a.layer != kLayerDiffuse && dot(a.incident, b.incident) < s.direction_threshold) return false;
  }
  if (s.weights & kWeightVisibility) {
    if (a.visible_lights != b.visible_lights) return false;
    const float x = a.open_distance, y = b.open_distance;
    if (x != y && (std::isinf(x) || std::isinf(y) || std::fabs(x - y) > s.visibility_threshold * std::max(x, y))) return false;
  }
  return true;
}

struct Batch {
  std::vector<Vec3> positions;
  std::vector<SimilarityKey> keys;
  std::vector<Rgb> values;
};

// Points clustered so that some cells hold one record and others hundreds; keys drawn from a few
// values per field so that every weight both passes and fails often.
Batch random_batch(size_t n, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  Batch b;
  const Vec3 normals[3] = {{0.f, 0.f, 1.f}, {0.f, 0.3f, 0.954f}, {1.f, 0.f, 0.f}};
  for (size_t i = 0; i < n; ++i) {
    const bool dense = i % 3 != 0;
    const float spread = dense ? 0.05f : 1.f;
    b.positions.push_back(Vec3(u(rng), u(rng), u(rng)) * spread);
    SimilarityKey k;
    k.normal = normals[rng() % 3];
    k.incident = normals[rng() % 3];
    const float albedo = 0.5f + 0.04f * float(rng() % 3);
    k.throughput = Rgb(albedo, albedo, 0.5f);
    k.visible_lights = uint32_t(rng() % 2);
    const float lengths[4] = {1.f, 1.2f, 2.f, INFINITY};
    k.open_distance = lengths[rng() % 4];
    k.layer = uint8_t(rng() % 2);
    k.selected = uint8_t(rng() % 8 != 0);
    b.keys.push_back(k);
    // Magnitudes far apart, so that double sums round and a different order of additions shows.
    std::uniform_int_distribution<int> exponent(-60, 60);
    Rgb v(std::ldexp(u(rng), exponent(rng)), std::ldexp(u(rng), exponent(rng)), std::ldexp(u(rng), exponent(rng)));
    if (i % 97 == 0) v.g = std::nanf("");
    b.values.push_back(v);
  }
  return b;
}

void expect_same_as_walk(const Batch& b, float radius, uint32_t weights) {
  ConsistentFilterSettings settings;
  settings.weights = weights;
  const SimilarityWeights w(settings);
  HashGrid grid;
  grid.build(std::span<const Vec3>(b.positions), radius);
  const size_t linked = grid.compacted_records();
  ASSERT_EQ(linked, b.positions.size());
  GatherData data;
  data.resize(linked);
  std::vector<Rgb> values(linked);
  for (size_t c = 0; c < linked; ++c) {
    const uint32_t i = grid.record(c).payload;
    data.set(c, grid.record(c).position, b.keys[i]);
    values[c] = b.values[i];
  }
  data.set_values(values);
  const GridRecord* base = &grid.record(0);
  CellRangeCache cache;
  size_t nonempty = 0;
  for (size_t c = 0; c < linked; ++c) {
    const float r = radius * (0.5f + 0.5f * float(c % 3));  // up to the cell size: 8 or more cells
    double sum[3] = {0.0, 0.0, 0.0};
    uint32_t count = 0;
    grid.for_each_in_radius(base[c].position, r, [&](const GridRecord& rec, float) {
      const size_t d = size_t(&rec - base);
      const Rgb& v = values[d];
      if (!std::isfinite(v.r) || !std::isfinite(v.g) || !std::isfinite(v.b) || !similar(data.key(c), data.key(d), settings)) return;
      sum[0] += v.r, sum[1] += v.g, sum[2] += v.b;
      ++count;
    });
    const GatherSum g = data.gather(grid, GatherQuery{data.position(c), r, data.key(c)}, w, &cache);
    ASSERT_EQ(g.count, count) << "record " << c;
    // Bit for bit: the same additions in the same order.
    ASSERT_EQ(g.r, sum[0]) << "record " << c;
    ASSERT_EQ(g.g, sum[1]) << "record " << c;
    ASSERT_EQ(g.b, sum[2]) << "record " << c;
    nonempty += count > 1;
  }
  EXPECT_GT(nonempty, size_t(100));  // the test averaged something
}

TEST(ConsistentGather, EqualsTheScalarWalkBitForBit) {
  const Batch b = random_batch(6000, 7);
  for (const float radius : {0.002f, 0.01f, 0.05f})  // cells of a record or two up to hundreds
    for (const uint32_t weights : {0u, uint32_t(kWeightNormal), uint32_t(kWeightAlbedo), uint32_t(kWeightVisibility),
                                   uint32_t(kWeightNormal | kWeightAlbedo | kWeightVisibility)}) {
      SCOPED_TRACE(testing::Message() << "radius " << radius << " weights " << weights);
      expect_same_as_walk(b, radius, weights);
    }
}

}  // namespace
}  // namespace pathspace
