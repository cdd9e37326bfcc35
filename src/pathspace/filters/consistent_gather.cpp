#include "pathspace/filters/consistent_gather.h"

#include <algorithm>
#include <cmath>

#include "pathspace/materials/bsdf_layers.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace {

SimilarityWeights::SimilarityWeights(const ConsistentFilterSettings& s)
    : normal((s.weights & kWeightNormal) != 0),
      albedo((s.weights & kWeightAlbedo) != 0),
      visibility((s.weights & kWeightVisibility) != 0),
      normal_threshold(s.normal_threshold),
      albedo_threshold(s.albedo_threshold),
      direction_threshold(s.direction_threshold),
      visibility_threshold(s.visibility_threshold) {}

void GatherData::resize(size_t n) {
  points_.resize(n);
  keys_.resize(n);
  values_ = nullptr;
}

uint32_t GatherData::group_of(const SimilarityKey& k) { return uint32_t(k.layer) | uint32_t(k.selected) << 8; }

size_t GatherData::bytes_per_record() { return sizeof(Point) + sizeof(SimilarityKey); }

void GatherData::set(size_t c, const Vec3& p, const SimilarityKey& k) {
  points_[c] = {p.x, p.y, p.z, group_of(k)};
  keys_[c] = k;
}

void GatherData::set_values(const std::vector<Rgb>& values) {
  values_ = values.data();
  parallel_for(values.size(), 1 << 14, [&](size_t begin, size_t end) {
    for (size_t c = begin; c < end; ++c) {
      const Rgb& v = values[c];
      const bool usable = std::isfinite(v.r) && std::isfinite(v.g) && std::isfinite(v.b);
      points_[c].tag = (points_[c].tag & ~kUsable) | (usable ? kUsable : 0u);
    }
  });
}

void GatherData::cell_range(const HashGridView& grid, uint64_t key, CellRangeCache* cache, uint32_t* begin, uint32_t* end) const {
  CellRangeCache::Entry& e = cache->entries_[hash_cell_key(key) & (CellRangeCache::kEntries - 1)];
  if (e.key != key) {
    e.key = key;
    grid.find_cell(key, &e.begin, &e.end);
  }
  *begin = e.begin;
  *end = e.end;
}

// The in-ball test and the binary weights of sec. 2.1 for record j against one query.
struct GatherRecordTest {
  const GatherData::Point* points;
  const SimilarityKey* keys;
  Vec3 p;
  float r2;
  uint32_t tag;  // the query's group, usable
  const SimilarityKey& k;
  const SimilarityWeights& w;

  int in_ball(uint32_t j) const { return in_ball(points[j], p, r2, tag); }
  // distance_squared(record, p) <= r^2, the same group and a usable value.
  static int in_ball(const GatherData::Point& a, const Vec3& p, float r2, uint32_t tag) {
    const float dx = a.x - p.x, dy = a.y - p.y, dz = a.z - p.z;
    return (dx * dx + dy * dy + dz * dz <= r2) & (a.tag == tag);
  }
  // The weights beyond the group (layer and selection), w_ij in {0, 1}.
  bool similar(uint32_t j) const {
    const SimilarityKey& b = keys[j];
    if (w.normal && dot(k.normal, b.normal) < w.normal_threshold) return false;
    if (w.albedo) {
      const Rgb d = k.throughput - b.throughput;
      if (std::fabs(d.r) > w.albedo_threshold || std::fabs(d.g) > w.albedo_threshold || std::fabs(d.b) > w.albedo_threshold)
        return false;
      if (k.layer != kLayerDiffuse && dot(k.incident, b.incident) < w.direction_threshold) return false;
    }
    if (w.visibility) {
      if (k.visible_lights != b.visible_lights) return false;
      if (!similar_lengths(k.open_distance, b.open_distance, w.visibility_threshold)) return false;
    }
    return true;
  }
  // Hemisphere rays: an escaping ray (infinite length) matches only another one.
  static bool similar_lengths(float a, float b, float threshold) {
    if (a == b) return true;
    if (std::isinf(a) || std::isinf(b)) return false;
    return std::fabs(a - b) <= threshold * std::max(a, b);
  }
};

// hit[j] = whether record b0 + j is in the ball, j < n, as one vectorised loop. Its own function,
// with the query's fields copied into locals, so that the loop sees no store that could change
// them, and the points offset to b0 first (indices b0 + j in 32 bits could wrap, which keeps GCC
// from treating the addresses as linear).
__attribute__((noinline)) static void test_distances(const GatherRecordTest& in, uint32_t b0, uint32_t n, int32_t* __restrict hit) {
  const GatherData::Point* points = in.points + b0;
  const Vec3 p = in.p;
  const float r2 = in.r2;
  const uint32_t tag = in.tag;
#pragma omp simd
  for (uint32_t j = 0; j < n; ++j) hit[j] = GatherRecordTest::in_ball(points[j], p, r2, tag);
}

GatherSum GatherData::gather(const HashGrid& grid, const GatherQuery& q, const SimilarityWeights& w, CellRangeCache* cache) const {
  GatherSum sum;
  const GatherRecordTest t{points_.data(), keys_.data(), q.position, q.radius * q.radius, group_of(q.key) | kUsable, q.key, w};
  const HashGridView view = grid.view();
  CellCoord lo, hi;
  view.geometry.cell_range(q.position, q.radius, &lo, &hi);
  for (int32_t cx = lo.x; cx <= hi.x; ++cx)
    for (int32_t cy = lo.y; cy <= hi.y; ++cy)
      for (int32_t cz = lo.z; cz <= hi.z; ++cz) {
        uint32_t begin, end;
        cell_range(view, pack_cell_key(cx, cy, cz), cache, &begin, &end);
        if (begin < end) add_range(begin, end, t, &sum);
      }
  return sum;
}

void GatherData::add_range(uint32_t begin, uint32_t end, const GatherRecordTest& t, GatherSum* sum) const {
  const auto add = [&](uint32_t d) {
    sum->r += values_[d].r, sum->g += values_[d].g, sum->b += values_[d].b;
    ++sum->count;
  };
  // A few records (small cells, the default radius): one at a time, most leaving at the distance test.
  constexpr uint32_t kScalarBelow = 16;
  if (end - begin < kScalarBelow) {
    for (uint32_t j = begin; j < end; ++j)
      if (t.in_ball(j) && t.similar(j)) add(j);
    return;
  }
  // Many: the distance tests of a chunk as one vectorised loop, then the weights of the records in
  // the ball and the sum, in index order.
  constexpr uint32_t kChunk = 256;
  int32_t hit[kChunk];
  uint32_t hits[kChunk];
  for (uint32_t b0 = begin; b0 < end; b0 += kChunk) {
    const uint32_t n = std::min(kChunk, end - b0);
    test_distances(t, b0, n, hit);
    uint32_t m = 0;
    for (uint32_t j = 0; j < n; ++j) {
      hits[m] = b0 + j;
      m += uint32_t(hit[j]);
    }
    for (uint32_t h = 0; h < m; ++h)
      if (t.similar(hits[h])) add(hits[h]);
  }
}

}  // namespace pathspace
