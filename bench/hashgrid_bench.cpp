// Build and radius-query throughput of the chained hash grid (PCLT listing 1) and the stochastic
// hash map (Hachisuka & Jensen 2010) vs point count, for uniform points in a box and points on a
// plane (the realistic case: hit points lie on surfaces), at 1 and 2 threads. The radius gives
// ~30 records per query ball. items_per_second = records built or queries answered per second.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <map>
#include <vector>

#include "pathspace/hashgrid/hash_grid.h"
#include "pathspace/hashgrid/stochastic_hash_map.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/sampling/rng.h"

namespace pathspace {
namespace {

enum Distribution { kBox = 0, kPlane = 1 };
constexpr double kNeighbours = 30.0;

struct PointSet {
  std::vector<Vec3> points, queries;
  float radius = 0.f;
};

std::vector<Vec3> sample(Distribution d, size_t n, uint64_t seed) {
  Pcg32 rng(seed, 3);
  std::vector<Vec3> p(n);
  for (Vec3& v : p) {
    const float a = rng.next_float(), b = rng.next_float(), c = rng.next_float();
    v = d == kBox ? Vec3(a, b, c) : Vec3(a, 0.5f, b);
  }
  return p;
}

const PointSet& point_set(Distribution d, size_t n) {
  static std::map<std::pair<int, size_t>, PointSet> cache;
  PointSet& s = cache[{int(d), n}];
  if (s.points.empty()) {
    s.points = sample(d, n, 1);
    s.queries = sample(d, std::min<size_t>(n, 100000), 2);  // at most 1e5 queries keeps runs short
    // Unit box: n records per unit volume; unit square: n per unit area.
    s.radius = d == kBox ? float(std::cbrt(kNeighbours / (4.0 / 3.0 * M_PI * double(n))))
                         : float(std::sqrt(kNeighbours / (M_PI * double(n))));
  }
  return s;
}

// One slot per 4 records: fixed memory well below the chained grid's (the point of the method).
size_t stochastic_slots(size_t n) { return std::bit_ceil(std::max<size_t>(n / 4, 16)); }

template <typename Query>
size_t run_queries(const std::vector<Vec3>& queries, const Query& query) {
  std::atomic<size_t> found{0};
  parallel_for(queries.size(), 256, [&](size_t b, size_t e) {
    size_t local = 0;
    for (size_t i = b; i < e; ++i) local += query(queries[i]);
    found += local;
  });
  return found.load();
}

void BM_ChainedBuild(benchmark::State& state) {
  const PointSet& s = point_set(Distribution(state.range(0)), size_t(state.range(1)));
  ThreadLimit limit(int(state.range(2)));
  HashGrid grid;
  for (auto _ : state) {
    grid.build(s.points, s.radius);
    benchmark::ClobberMemory();
  }
  const HashGridStats st = grid.stats();
  if (st.status != kGridOk) state.SkipWithError("hash grid reported a failure");
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(s.points.size()));
  state.counters["cells"] = double(st.occupied_cells);
  state.counters["mean_probe"] = st.mean_probe;
  state.counters["MiB"] = double(st.bytes) / (1 << 20);
}

void BM_ChainedQuery(benchmark::State& state) {
  const PointSet& s = point_set(Distribution(state.range(0)), size_t(state.range(1)));
  ThreadLimit limit(int(state.range(2)));
  HashGrid grid;
  grid.build(s.points, s.radius);
  size_t found = 0;
  for (auto _ : state) {
    found = run_queries(s.queries, [&](const Vec3& q) {
      size_t k = 0;
      grid.for_each_in_radius(q, s.radius, [&](const GridRecord&, float) { ++k; });
      return k;
    });
    benchmark::DoNotOptimize(found);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(s.queries.size()));
  state.counters["found_per_query"] = double(found) / double(s.queries.size());
}

void BM_StochasticBuild(benchmark::State& state) {
  const PointSet& s = point_set(Distribution(state.range(0)), size_t(state.range(1)));
  ThreadLimit limit(int(state.range(2)));
  StochasticHashMap map(stochastic_slots(s.points.size()));
  uint64_t seed = 0;
  for (auto _ : state) {
    map.build(s.points, s.radius, ++seed);
    benchmark::ClobberMemory();
  }
  const StochasticHashMapStats st = map.stats();
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(s.points.size()));
  state.counters["kept"] = double(st.occupied_slots);
  state.counters["MiB"] = double(st.bytes) / (1 << 20);
}

void BM_StochasticQuery(benchmark::State& state) {
  const PointSet& s = point_set(Distribution(state.range(0)), size_t(state.range(1)));
  ThreadLimit limit(int(state.range(2)));
  StochasticHashMap map(stochastic_slots(s.points.size()));
  map.build(s.points, s.radius, 1);
  size_t found = 0;
  for (auto _ : state) {
    found = run_queries(s.queries, [&](const Vec3& q) {
      size_t k = 0;
      map.for_each_in_radius(q, s.radius, [&](const StochasticSlot& slot, float) { k += slot.count; });
      return k;
    });
    benchmark::DoNotOptimize(found);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(s.queries.size()));
  state.counters["estimate_per_query"] = double(found) / double(s.queries.size());
}

// Args: distribution (0 box, 1 plane), point count, threads.
void sweep(benchmark::internal::Benchmark* b) {
  b->ArgNames({"dist", "n", "threads"});
  for (int d : {kBox, kPlane})
    for (int64_t n : {10000, 100000, 1000000})
      for (int t : {1, 2}) b->Args({d, n, t});
  b->UseRealTime()->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_ChainedBuild)->Apply(sweep);
BENCHMARK(BM_ChainedQuery)->Apply(sweep);
BENCHMARK(BM_StochasticBuild)->Apply(sweep);
BENCHMARK(BM_StochasticQuery)->Apply(sweep);

}  // namespace
}  // namespace pathspace

BENCHMARK_MAIN();
