// The gather of the consistent filter's eq. 1 (Keller, Dahm, Binder 2014): the sum over the
// vertices in a ball that the binary weights of sec. 2.1 call similar. A batch's data is held in
// the hash grid's cell order, so the records of a cell are one contiguous range, found from the
// grid's slot alone (HashGridView::find_cell). The distance tests of a large cell run as one
// vectorised loop over 16-byte points (this file is compiled with -fopenmp-simd and
// -ffp-contract=off); only the records in the ball read their weights' data and value, in index
// order, the order of a plain walk over the cells' lists, so the filtered values are bit-identical
// to that walk's (docs/results/filter-speed.md, "Consistent filter against the hashed filter").
#pragma once

#include <cstdint>
#include <vector>

#include "pathspace/filters/consistent_filter_settings.h"
#include "pathspace/hashgrid/hash_grid.h"
#include "pathspace/math/rgb.h"
#include "pathspace/math/vec3.h"

namespace pathspace {

// What the weights of sec. 2.1 compare, for one vertex.
struct SimilarityKey {
  Vec3 normal, incident;
  Rgb throughput;
  uint32_t visible_lights = 0;
  float open_distance = 0.f;
  uint8_t layer = 0, selected = 0;
};

// The weights switched on and their thresholds (ConsistentFilterSettings).
struct SimilarityWeights {
  bool normal = false, albedo = false, visibility = false;
  float normal_threshold = 0.f, albedo_threshold = 0.f, direction_threshold = 0.f, visibility_threshold = 0.f;
  explicit SimilarityWeights(const ConsistentFilterSettings& s);
};

// A ball and the vertex whose similar neighbours it sums (its centre for the batch's own vertices,
// a query-only vertex for the anti-aliasing paths).
struct GatherQuery {
  Vec3 position;
  float radius = 0.f;
  SimilarityKey key;
};

struct GatherSum {
  double r = 0.0, g = 0.0, b = 0.0;
  uint32_t count = 0;
  // Eq. 1's average (count > 0). Divided, not multiplied by 1 / count: the mean of equal values is
  // then that value exactly.
  Rgb mean() const { return Rgb(float(r / count), float(g / count), float(b / count)); }
};

struct GatherRecordTest;  // consistent_gather.cpp

// The record ranges of recently visited cells. Queries go cell by cell in Morton order, so
// consecutive queries visit mostly the same cells: one cache per thread's run of queries saves
// most of the hash table probes.
class CellRangeCache {
 public:
  CellRangeCache() { for (Entry& e : entries_) e.key = kEmptyCellKey; }

 private:
  friend class GatherData;
  struct Entry {
    uint64_t key;
    uint32_t begin, end;
  };
  static constexpr size_t kEntries = 64;
  Entry entries_[kEntries];
};

// One batch's vertices in the grid's compacted record order (record c of HashGrid is entry c).
class GatherData {
  friend struct GatherRecordTest;

 public:
  // Sizes every array for `records` entries; set() fills entry c.
  void resize(size_t records);
  void set(size_t c, const Vec3& position, const SimilarityKey& key);
  // Entry c's key and position as set (read in order: a query of the batch's own vertex c).
  const SimilarityKey& key(size_t c) const { return keys_[c]; }
  Vec3 position(size_t c) const { return {points_[c].x, points_[c].y, points_[c].z}; }
  // The values the next gathers average (one iteration's input, kept by the caller until then);
  // non-finite ones are left out.
  void set_values(const std::vector<Rgb>& values);
  static size_t bytes_per_record();

  // What the in-ball test reads, in one 16-byte record: most records it reads fail it.
  struct Point {
    float x = 0.f, y = 0.f, z = 0.f;
    uint32_t tag = 0;  // group_of() | kUsable when the value is finite
  };

  // The sum over every record in the ball that is similar to the query, the cells visited in the
  // grid's order (x, then y, then z) and each cell's records in index order.
  GatherSum gather(const HashGrid& grid, const GatherQuery& query, const SimilarityWeights& weights, CellRangeCache* cache) const;

 private:
  // Records [begin, end) of the cell with this key (begin == end: empty).
  void cell_range(const HashGridView& grid, uint64_t key, CellRangeCache* cache, uint32_t* begin, uint32_t* end) const;
  void add_range(uint32_t begin, uint32_t end, const GatherRecordTest& test, GatherSum* sum) const;

  // Layer and selection flag: vertices of other layers or other places in their paths estimate
  // other quantities and are never averaged.
  static uint32_t group_of(const SimilarityKey& k);
  static constexpr uint32_t kUsable = 1u << 16;

  std::vector<Point> points_;
  std::vector<SimilarityKey> keys_;
  const Rgb* values_ = nullptr;  // the values averaged (the caller's)
};

}  // namespace pathspace
