// Hashed path space filter speed (Binder et al. 2021, sec. 4: 1920x1080 vertices in ~3 ms on a
// Titan V). Vertices come from a real 1920x1080 render of cornell-box: primary hits (first diffuse
// vertex) and incoherent second-bounce hits (second diffuse vertex). Reported side by side, in one
// process, on the same vertices:
//   BM_HashedFilter      accumulate (keys + insert + atomic add) and lookup, ns per vertex
//   BM_RandomRmw         a plain random read-modify-write loop over a table of the same size:
//                        this machine's random-access limit for the same memory footprint
//   BM_RadiusSearch      nanoflann kd-tree radius queries with the radius that gives the same
//                        mean neighbour count as the filter's voxels (the classic path space filter)
//   BM_ConsistentFilter  the consistent filter (Keller et al. 2014; hash grid range search, eq. 1)
//                        with that radius, so that its balls hold as many vertices on average as
//                        the hashed filter's voxels: ns per vertex for the whole filter() call
// Arguments: {vertex set (0 primary, 1 second bounce), threads[, local combining on/off | weights on/off,
// radius (consistent only): 0 equal neighbour count, 1 the filter's default]}.
#include <benchmark/benchmark.h>

#include <nanoflann.hpp>

#include <algorithm>
#include <memory>
#include <vector>

#include "pathspace/filters/consistent_filter.h"
#include "pathspace/filters/hashed/hashed_filter.h"
#include "pathspace/parallel/parallel_for.h"
#include "studies/psf2021/vertex_sets.h"

namespace pathspace {
namespace {

constexpr int kWidth = 1920, kHeight = 1080;

struct VertexSet {
  std::unique_ptr<study::VertexSet> source;
  std::vector<Vec3> positions;  // valid records only
  std::vector<Rgb> contributions;
  double mean_voxel_count = 0;  // vertex-weighted, measured with the default filter
  const Scene& scene() const { return *source->scene; }
  const VertexBuffer& buffer() const { return source->buffer; }
};

const VertexSet& vertex_set(int kind) {
  static std::unique_ptr<VertexSet> sets[2];
  if (sets[kind]) return *sets[kind];
  auto set = std::make_unique<VertexSet>();
  set->source = study::make_vertex_set(study::VertexSetKind(kind), kWidth, kHeight);
  const VertexBuffer& b = set->buffer();
  for (size_t p = 0; p < b.paths(); ++p)
    for (int r = 0; r < b.count[p]; ++r) {
      set->positions.push_back(b.position[b.slot(p, r)]);
      set->contributions.push_back(b.contribution[b.slot(p, r)]);
    }
  HashedFilterSettings debug;
  debug.debug_images = true;  // for the count image below
  HashedFilter filter(debug, set->scene().camera, size_t(kWidth) * kHeight);
  SlotValues filtered;
  filter.filter(b, 0, 0, &filtered);
  const Image counts = filter.aov(FilterAov::count);
  double sum = 0, n = 0;
  for (const Rgb& c : counts.pixels)
    if (c.r > 0) sum += c.r, n += 1;
  set->mean_voxel_count = n > 0 ? sum / n : 0;
  sets[kind] = std::move(set);
  return *sets[kind];
}

void BM_HashedFilter(benchmark::State& state) {
  const VertexSet& set = vertex_set(int(state.range(0)));
  ThreadLimit limit(int(state.range(1)));
  HashedFilterSettings settings;
  settings.local_combining = state.range(2) != 0;
  HashedFilter filter(settings, set.scene().camera, size_t(kWidth) * kHeight);
  SlotValues filtered;
  uint32_t pass = 0;
  filter.filter(set.buffer(), 0, pass++, &filtered);  // warm-up: first touch of the per-vertex arrays
  filter.reset_stats();
  for (auto _ : state) filter.filter(set.buffer(), 0, pass++, &filtered);
  const HashedFilterStats& st = filter.stats();
  const double per_vertex = 1e6 / double(st.vertices);  // ms summed over passes -> ns per vertex
  state.counters["vertices"] = double(st.vertices) / double(st.passes);
  state.counters["accumulate_ns"] = st.accumulate_ms * per_vertex;
  state.counters["lookup_ns"] = st.lookup_ms * per_vertex;
  state.counters["clear_ms"] = st.clear_ms / double(st.passes);
  state.counters["mean_probes"] = st.mean_probes();
  state.counters["combined_pct"] = 100.0 * (1.0 - double(st.insertions) / double(st.vertices));
  state.counters["mean_voxel_count"] = set.mean_voxel_count;
  state.counters["occupancy_pct"] = 100.0 * double(st.occupied_cells_last) / double(st.cells);
}

void BM_RandomRmw(benchmark::State& state) {
  const VertexSet& set = vertex_set(int(state.range(0)));
  ThreadLimit limit(int(state.range(1)));
  const VoxelHashTable table(uint64_t(kWidth) * kHeight, 16);  // same cells, same bytes as the filter's
  const VoxelHashTableView view = table.view();
  const size_t n = set.positions.size();
  uint64_t round = 0;
  for (auto _ : state) {
    ++round;
    parallel_for(n, 2048, [&](size_t begin, size_t end) {
      for (size_t i = begin; i < end; ++i) {
        const uint64_t slot = mix64(i ^ (round << 40)) & view.mask;
        VoxelCell& c = view.cells[slot];
        c.sum[0] += 1;
        c.sum[1] += 2;
        c.sum[2] += 3;
        c.count += 1;
        view.fingerprints[slot] = uint32_t(i);
      }
    });
  }
  // Rate of giga-updates, inverted: nanoseconds per update.
  state.counters["update_ns"] = benchmark::Counter(double(n) * 1e-9, benchmark::Counter::kIsIterationInvariantRate |
                                                                         benchmark::Counter::kInvert);
}

// nanoflann adaptor over the vertex positions.
struct PointCloud {
  const std::vector<Vec3>* points;
  size_t kdtree_get_point_count() const { return points->size(); }
  float kdtree_get_pt(size_t i, size_t dim) const { return (*points)[i][int(dim)]; }
  template <class B>
  bool kdtree_get_bbox(B&) const { return false; }
};
using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, PointCloud>, PointCloud, 3, uint32_t>;
const nanoflann::SearchParams kUnsorted(32, 0.f, false);

// Queries: a fixed pseudo-random subset (a full 2M-query pass takes many seconds).
constexpr size_t kQueries = 1 << 15;

// The kd-tree over a vertex set, the query subset, and the radius whose balls hold as many vertices
// on average as the hashed filter's voxels (bisection).
struct RadiusSearchSetup {
  PointCloud cloud;
  std::unique_ptr<KdTree> tree;
  std::vector<size_t> queries;
  float radius = 0.f;

  explicit RadiusSearchSetup(const VertexSet& set) : cloud{&set.positions}, queries(kQueries) {
    tree = std::make_unique<KdTree>(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    tree->buildIndex();
    for (size_t q = 0; q < kQueries; ++q) queries[q] = mix64(q) % set.positions.size();
    float lo = 1e-5f, hi = 1.f;
    for (int it = 0; it < 30; ++it) {
      const float mid = std::sqrt(lo * hi);
      (mean_neighbours(mid) < set.mean_voxel_count ? lo : hi) = mid;
    }
    radius = std::sqrt(lo * hi);
  }
  double mean_neighbours(float r) const {
    std::vector<std::pair<uint32_t, float>> found;
    double sum = 0;
    for (size_t q = 0; q < 512; ++q) {
      const Vec3& p = (*cloud.points)[queries[q]];
      const float pt[3] = {p.x, p.y, p.z};
      sum += double(tree->radiusSearch(pt, r * r, found, kUnsorted));
    }
    return sum / 512.0;
  }
};

const RadiusSearchSetup& radius_search(int kind) {
  static std::unique_ptr<RadiusSearchSetup> made[2];
  if (!made[kind]) made[kind] = std::make_unique<RadiusSearchSetup>(vertex_set(kind));
  return *made[kind];
}

void BM_RadiusSearch(benchmark::State& state) {
  const VertexSet& set = vertex_set(int(state.range(0)));
  ThreadLimit limit(int(state.range(1)));
  const RadiusSearchSetup& setup = radius_search(int(state.range(0)));
  const KdTree& tree = *setup.tree;
  const std::vector<size_t>& queries = setup.queries;
  const float radius = setup.radius;
  for (auto _ : state) {
    parallel_for(kQueries, 256, [&](size_t begin, size_t end) {
      std::vector<std::pair<uint32_t, float>> found;
      for (size_t q = begin; q < end; ++q) {
        const Vec3& p = set.positions[queries[q]];
        const float pt[3] = {p.x, p.y, p.z};
        tree.radiusSearch(pt, radius * radius, found, kUnsorted);
        Rgb sum;
        for (const auto& f : found) sum += set.contributions[f.first];
        benchmark::DoNotOptimize(sum);
      }
    });
  }
  state.counters["query_ns"] = benchmark::Counter(double(kQueries) * 1e-9, benchmark::Counter::kIsIterationInvariantRate |
                                                                               benchmark::Counter::kInvert);
  state.counters["radius"] = radius;
  state.counters["mean_neighbours"] = setup.mean_neighbours(radius);
}

void BM_ConsistentFilter(benchmark::State& state) {
  const VertexSet& set = vertex_set(int(state.range(0)));
  ThreadLimit limit(int(state.range(1)));
  ConsistentFilterSettings settings;
  // Radius mode 1: the filter's default (r0 from 3 x 3 pixels at the camera path's length, eq. 2's
  // shrinking held back as below), a few neighbours per vertex, where the cell lookups dominate.
  const bool default_radius = state.range(3) == 1;
  if (!default_radius) settings.radius = radius_search(int(state.range(0))).radius;
  settings.alpha = 1e-3f;  // the radius stays within 0.3% over the timed passes (n grows with each)
  if (state.range(2) == 0) settings.weights = 0;
  ConsistentFilter filter(settings, set.scene().camera, size_t(kWidth) * kHeight);
  SlotValues filtered;
  uint32_t pass = 0;
  filter.filter(set.buffer(), 0, pass++, &filtered);  // warm-up: the grid's and scratch allocations
  const ConsistentFilterStats before = filter.stats();
  for (auto _ : state) filter.filter(set.buffer(), 0, pass++, &filtered);
  const ConsistentFilterStats& st = filter.stats();
  const double vertices = double(st.vertices - before.vertices);
  state.counters["filter_ns"] = (st.filter_ms - before.filter_ms) * 1e6 / vertices;
  state.counters["mean_neighbours"] = double(st.averaged - before.averaged) / vertices;
  state.counters["radius"] = settings.radius;
}

void consistent_variants(benchmark::internal::Benchmark* b) {
  for (int kind : {0, 1})
    for (int threads : {1, 2})
      for (int weights : {0, 1}) b->Args({kind, threads, weights, 0});
  for (int kind : {0, 1}) b->Args({kind, 2, 1, 1});
}

void vertex_sets_and_threads(benchmark::internal::Benchmark* b) {
  for (int kind : {0, 1})
    for (int threads : {1, 2}) b->Args({kind, threads});
}

void filter_variants(benchmark::internal::Benchmark* b) {
  for (int kind : {0, 1})
    for (int threads : {1, 2})
      for (int combining : {1, 0}) b->Args({kind, threads, combining});
}

BENCHMARK(BM_HashedFilter)->Apply(filter_variants)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);
BENCHMARK(BM_RandomRmw)->Apply(vertex_sets_and_threads)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);
BENCHMARK(BM_RadiusSearch)->Apply(vertex_sets_and_threads)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);
BENCHMARK(BM_ConsistentFilter)->Apply(consistent_variants)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);

}  // namespace
}  // namespace pathspace

BENCHMARK_MAIN();
