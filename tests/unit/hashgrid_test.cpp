// Unit tests of the chained hash grid (PCLT listing 1) and the stochastic hash map (Hachisuka &
// Jensen 2010): radius queries against brute force, concurrent vs serial builds, reported probe
// failures, and the uniform choice and exact counts of the stochastic map.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <bit>
#include <map>
#include <set>
#include <vector>

#include "pathspace/hashgrid/hash_grid.h"
#include "pathspace/hashgrid/stochastic_hash_map.h"
#include "pathspace/sampling/rng.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

std::vector<Vec3> random_box(size_t n, float lo, float hi, uint64_t seed) {
  Pcg32 rng(seed, 1);
  std::vector<Vec3> p(n);
  for (Vec3& v : p) v = Vec3(lo + (hi - lo) * rng.next_float(), lo + (hi - lo) * rng.next_float(), lo + (hi - lo) * rng.next_float());
  return p;
}

std::vector<uint32_t> brute_force(const std::vector<Vec3>& points, const Vec3& q, float r) {
  std::vector<uint32_t> out;
  for (size_t i = 0; i < points.size(); ++i)
    if (distance_squared(points[i], q) <= r * r) out.push_back(uint32_t(i));
  return out;
}

std::vector<uint32_t> grid_query(const HashGrid& grid, const Vec3& q, float r) {
  std::vector<uint32_t> out;
  grid.for_each_in_radius(q, r, [&](const GridRecord& rec, float d2) {
    EXPECT_EQ(d2, distance_squared(rec.position, q));
    out.push_back(rec.payload);
  });
  std::sort(out.begin(), out.end());
  return out;
}

// Builds a grid over `points` and checks every query against brute force; returns total hits so
// callers can make sure the test was not vacuous.
size_t expect_matches_brute_force(const std::vector<Vec3>& points, const std::vector<Vec3>& queries, float r,
                                  HashGridConfig config = {}) {
  HashGrid grid(config);
  grid.build(points, r);
  EXPECT_EQ(grid.status(), kGridOk);
  size_t hits = 0;
  for (const Vec3& q : queries) {
    const std::vector<uint32_t> expected = brute_force(points, q, r);
    const std::vector<uint32_t> got = grid_query(grid, q, r);
    EXPECT_EQ(got, expected) << "query (" << q.x << ", " << q.y << ", " << q.z << ") r=" << r;
    if (got != expected) break;  // one report is enough
    hits += got.size();
  }
  return hits;
}

TEST(HashGrid, RandomPointsWithNegativeCoordinatesMatchBruteForce) {
  const std::vector<Vec3> points = random_box(20000, -3.f, 3.f, 1);
  std::vector<Vec3> queries = random_box(1000, -3.5f, 3.5f, 2);
  for (size_t i = 0; i < 500; ++i) queries.push_back(points[i * 37]);
  EXPECT_GT(expect_matches_brute_force(points, queries, 0.3f), 5000u);
  HashGridConfig linear;
  linear.probing = Probing::linear;
  EXPECT_GT(expect_matches_brute_force(points, queries, 0.3f, linear), 5000u);
  // Queries with a radius larger than the grid was built for visit more cells and stay exact.
  HashGrid grid;
  grid.build(points, 0.1f);
  for (size_t i = 0; i < 200; ++i) ASSERT_EQ(grid_query(grid, queries[i], 0.45f), brute_force(points, queries[i], 0.45f));
}

// The occupancy bitmap only skips cells that hold nothing: sparse points (most queries empty) and
// a dense cloud (every bit set) both match brute force, and the bitmap does reject empty cells.
TEST(HashGrid, OccupancyBitmapIsExact) {
  HashGridConfig with_bitmap;
  with_bitmap.occupancy_bits_per_slot = 8;
  const std::vector<Vec3> sparse = random_box(300, -3.f, 3.f, 11);
  std::vector<Vec3> queries = random_box(3000, -3.5f, 3.5f, 12);
  for (size_t i = 0; i < 300; ++i) queries.push_back(sparse[i]);
  EXPECT_GT(expect_matches_brute_force(sparse, queries, 0.05f, with_bitmap), 300u);
  EXPECT_GT(expect_matches_brute_force(random_box(20000, -1.f, 1.f, 13), queries, 0.2f, with_bitmap), 5000u);

  HashGrid grid(with_bitmap);
  grid.build(sparse, 0.05f);
  const HashGridView view = grid.view();
  ASSERT_NE(view.occupancy.words, nullptr);
  size_t rejected = 0;
  for (const Vec3& q : random_box(2000, -3.f, 3.f, 14))
    rejected += !view.occupancy.may_hold(hash_cell_key(view.geometry.key_of(q)));
  EXPECT_GT(rejected, 1900u);  // 300 occupied cells in 2^14 bits: about 2% false positives
  // A grid being filled through its view has no bitmap: it would be stale.
  grid.prepare(10, 0.05f);
  EXPECT_EQ(grid.view().occupancy.words, nullptr);
}

// Cell ranges of a compacted grid list exactly the candidates, in the same order (callers that sum
// over them get the same floats).
TEST(HashGrid, CellRangesListTheCandidatesInOrder) {
  const std::vector<Vec3> points = random_box(5000, -1.f, 1.f, 21);
  HashGrid grid;
  grid.build(points, 0.1f);
  const HashGridView view = grid.view();
  size_t total = 0;
  for (const Vec3& q : random_box(300, -1.2f, 1.2f, 22)) {
    std::vector<uint32_t> candidates, ranged;
    view.for_each_candidate(q, 0.1f, [&](const GridRecord& rec) { candidates.push_back(rec.payload); });
    view.for_each_cell_range(q, 0.1f, [&](uint32_t begin, uint32_t end) {
      for (uint32_t i = begin; i < end; ++i) ranged.push_back(grid.record(i).payload);
    });
    ASSERT_EQ(ranged, candidates);
    total += ranged.size();
  }
  EXPECT_GT(total, 1000u);
}

// A lattice with spacing r/2: many points sit exactly on cell borders (cell = 2r) and many pairs
// are exactly r apart along an axis, which the inclusive query must return.
TEST(HashGrid, CellBordersAndExactDistanceR) {
  const float r = 0.25f;
  std::vector<Vec3> points;
  for (int x = -8; x <= 8; ++x)
    for (int y = -8; y <= 8; ++y)
      for (int z = -8; z <= 8; ++z) points.push_back(Vec3(x * 0.125f, y * 0.125f, z * 0.125f));
  std::vector<Vec3> queries(points.begin(), points.end());
  // Points at float-distance ~r in random directions around random centres.
  Pcg32 rng(5, 6);
  std::vector<Vec3> shell = points;
  for (int i = 0; i < 300; ++i) {
    const Vec3 c(rng.next_float() * 2.f - 1.f, rng.next_float() * 2.f - 1.f, rng.next_float() * 2.f - 1.f);
    const Vec3 d = normalize(Vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() - 0.5f));
    shell.push_back(c + d * r);
    queries.push_back(c);
  }
  const size_t hits = expect_matches_brute_force(points, queries, r);
  EXPECT_GT(hits, points.size() * 7);  // every lattice point has >= 7 neighbours at distance <= r
  EXPECT_GT(expect_matches_brute_force(shell, queries, r), hits);
}

// Floats as integers with the same order (for bisection over every float in an interval).
int64_t to_ordered(float f) {
  const int32_t b = std::bit_cast<int32_t>(f);
  return b < 0 ? -int64_t(b & 0x7fffffff) : int64_t(b);
}
float from_ordered(int64_t k) {
  return k < 0 ? std::bit_cast<float>(int32_t(uint32_t(-k) | 0x80000000u)) : std::bit_cast<float>(int32_t(k));
}

// The farthest floats along each axis that the inclusive float test distance_squared <= r*r still
// accepts, around centres placed so that p -/+ r lands on or next to a cell border, at magnitudes
// where the rounding of p - r is coarse. The query must find all of them (this is what the margin
// in GridGeometry::cell_range is for).
TEST(HashGrid, ExtremePointsAcceptedByTheDistanceTestAreFound) {
  const float r = 0.3f, cell = 2.f * r;
  Pcg32 rng(17, 18);
  std::vector<Vec3> centres, points;
  for (int i = 0; i < 3000; ++i) {
    const float scale = i % 3 == 0 ? 1.f : (i % 3 == 1 ? 100.f : 3000.f);
    Vec3 p(scale * (2.f * rng.next_float() - 1.f), scale * (2.f * rng.next_float() - 1.f), scale * (2.f * rng.next_float() - 1.f));
    const int axis = i % 3;
    const float border = floorf(p[axis] / cell) * cell;  // a cell border near p
    p[axis] = (i & 1) ? border + r : border - r;          // so that p -/+ r is (nearly) on it
    centres.push_back(p);
    for (int a = 0; a < 3; ++a)
      for (float sign : {-1.f, 1.f}) {
        // Acceptance is monotone in x[a] on each side of p: bisect over all floats between p and
        // p + 2r * sign (as ordered integers) for the farthest accepted one. Near 0 that can be
        // a denormal across the border while p - r rounds onto it.
        auto at = [&](int64_t key) {
          Vec3 x = p;
          x[a] = from_ordered(key);
          return x;
        };
        int64_t in = to_ordered(p[a]), out = to_ordered(p[a] + sign * 2.f * r);
        while (std::abs(out - in) > 1) {
          const int64_t mid = in + (out - in) / 2;
          (distance_squared(at(mid), p) <= r * r ? in : out) = mid;
        }
        points.push_back(at(in));
      }
  }
  EXPECT_GE(expect_matches_brute_force(points, centres, r), points.size());
}

TEST(HashGrid, AllPointsInOneCell) {
  const float r = 0.5f;  // cell [0, 1)^3
  const std::vector<Vec3> points = random_box(2000, 0.f, 0.999f, 3);
  HashGrid grid;
  grid.build(points, r);
  EXPECT_EQ(grid.stats().occupied_cells, 1u);
  EXPECT_GT(expect_matches_brute_force(points, random_box(200, -0.5f, 1.5f, 4), r), 10000u);
}

TEST(HashGrid, EmptyGrid) {
  HashGrid grid;
  grid.build(std::span<const Vec3>(), 1.f);
  int visited = 0;
  grid.for_each_in_radius(Vec3(0.f), 1.f, [&](const GridRecord&, float) { ++visited; });
  EXPECT_EQ(visited, 0);
  const HashGridStats s = grid.stats();
  EXPECT_EQ(s.records, 0u);
  EXPECT_EQ(s.occupied_cells, 0u);
  EXPECT_EQ(s.status, kGridOk);
}

// Radius tiny against the spread: cell coordinates reach ~5e6, past the 21-bit key wrap, and the
// float margin of the cell range matters at these magnitudes. Pairs closer than r give hits.
TEST(HashGrid, RadiusMuchSmallerThanSpread) {
  const float r = 0.01f;
  std::vector<Vec3> points = random_box(5000, -1e5f, 1e5f, 7);
  Pcg32 rng(8, 9);
  for (size_t i = 0; i < 2000; ++i)
    points.push_back(points[i] + Vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() - 0.5f) * 0.02f);
  std::vector<Vec3> queries(points.begin(), points.begin() + 2000);
  EXPECT_GE(expect_matches_brute_force(points, queries, r), 2000u);
}

// Runs f with 8 TBB threads even on a 2-core machine (oversubscribed on purpose: more interleavings).
template <typename F>
void build_on_8_threads(const F& f) {
  ThreadLimit limit(8);
  tbb::task_arena(8).execute(f);
}

// The multiset of records per cell after a build on 8 threads equals that of a 1-thread build.
std::map<uint64_t, std::vector<uint32_t>> cell_contents(const HashGrid& grid) {
  const HashGridView v = grid.view();
  std::map<uint64_t, std::vector<uint32_t>> cells;
  for (uint32_t s = 0; s <= v.slot_mask; ++s) {
    if (v.slots[s].key == kEmptyCellKey) continue;
    std::vector<uint32_t>& list = cells[v.slots[s].key];
    for (uint32_t r = v.slots[s].head; r != kNoRecord; r = v.records[r].next) list.push_back(v.records[r].payload);
    std::sort(list.begin(), list.end());
  }
  return cells;
}

TEST(HashGrid, ConcurrentBuildEqualsSerialBuild) {
  // Points on a plane: many records per cell, so threads contend on the same list heads.
  Pcg32 rng(10, 11);
  std::vector<Vec3> points(200000);
  for (Vec3& p : points) p = Vec3(rng.next_float() * 4.f - 2.f, 0.25f, rng.next_float() * 4.f - 2.f);
  HashGrid serial, parallel;
  tbb::task_arena(1).execute([&] { serial.build(points, 0.05f); });
  build_on_8_threads([&] { parallel.build(points, 0.05f); });
  ASSERT_EQ(serial.status(), kGridOk);
  ASSERT_EQ(parallel.status(), kGridOk);
  const auto a = cell_contents(serial), b = cell_contents(parallel);
  EXPECT_EQ(a, b);
  size_t total = 0;
  for (const auto& [key, list] : b) total += list.size();
  EXPECT_EQ(total, points.size());
  EXPECT_EQ(serial.stats().occupied_cells, parallel.stats().occupied_cells);
}

// More cells than slots: the overflowing cells' records are counted as probe failures, the build
// terminates, and everything that was linked is still found exactly.
TEST(HashGrid, TooSmallTableReportsProbeFailures) {
  HashGridConfig config;
  config.table_slots = 16;
  config.max_probes = 16;  // quadratic probing visits all 16 slots in 16 probes
  const float r = 0.5f;    // cell = 1: point i in cell i
  std::vector<Vec3> points;
  for (int c = 0; c < 40; ++c)
    for (int k = 0; k < 5; ++k) points.push_back(Vec3(c + 0.1f * k, 0.5f, 0.5f));
  HashGrid grid(config);
  build_on_8_threads([&] { grid.build(points, r); });
  const HashGridStats s = grid.stats();
  EXPECT_TRUE(s.status & kGridProbeLimit);
  EXPECT_EQ(s.occupied_cells, 16u);
  EXPECT_EQ(s.probe_failures, (40u - 16u) * 5u);  // whole cells fail, never parts of one
  size_t found = 0;
  for (const Vec3& p : points) {
    const std::vector<uint32_t> got = grid_query(grid, p, 0.f);  // the point itself, if linked
    const std::vector<uint32_t> all = brute_force(points, p, 0.f);
    EXPECT_TRUE(got.empty() || got == all);
    found += got.size();
  }
  EXPECT_EQ(found, 16u * 5u);

  // Exactly as many cells as slots: quadratic probing must find every free slot.
  points.resize(16 * 5);
  HashGrid exact(config);
  exact.build(points, r);
  EXPECT_EQ(exact.status(), kGridOk);
  EXPECT_EQ(exact.stats().occupied_cells, 16u);
}

TEST(HashGrid, AppendBufferFullAndInvalidPositionsAreReported) {
  HashGrid grid;
  grid.prepare(10, 1.f);
  const HashGridView v = grid.view();
  for (uint32_t i = 0; i < 20; ++i) v.insert(Vec3(float(i), 0.f, 0.f), i);
  v.insert(Vec3(kInfinity, 0.f, 0.f), 99);
  EXPECT_TRUE(grid.status() & kGridFull);
  EXPECT_TRUE(grid.status() & kGridInvalidPosition);
  EXPECT_EQ(grid.stats().dropped, 11u);
  EXPECT_EQ(grid.record_count(), 10u);
  // Reuse after the failure: prepare() clears status and contents without reallocating.
  const GridSlot* before = grid.view().slots;
  grid.prepare(10, 1.f);
  EXPECT_EQ(grid.view().slots, before);
  EXPECT_EQ(grid.status(), kGridOk);
  EXPECT_EQ(grid.record_count(), 0u);
}

TEST(HashGrid, StatsCountCellsAndProbes) {
  const std::vector<Vec3> points = random_box(5000, -2.f, 2.f, 12);
  HashGrid grid;
  grid.build(points, 0.1f);
  std::set<uint64_t> cells;
  for (const Vec3& p : points) cells.insert(grid.geometry().key_of(p));
  const HashGridStats s = grid.stats();
  EXPECT_EQ(s.records, points.size());
  EXPECT_EQ(s.occupied_cells, cells.size());
  EXPECT_GE(s.mean_probe, 1.0);
  EXPECT_GE(s.max_probe, 1u);
  EXPECT_EQ(s.probe_failures, 0u);
  EXPECT_GE(s.bytes, s.table_slots * sizeof(GridSlot) + points.size() * sizeof(GridRecord));
}

// k records in one slot; over many seeds each must win with frequency 1/k. Chi-square test with
// k-1 degrees of freedom at alpha = 0.001 (a false alarm once in a thousand runs; the seeds are
// fixed, so the outcome is reproducible). The count must be exactly k every time.
TEST(StochasticHashMap, EachCollidingRecordKeptWithProbabilityOneOverK) {
  constexpr int kK = 7, kTrials = 20000;
  const float r = 0.5f;
  std::vector<Vec3> points;
  for (int i = 0; i < kK; ++i) points.push_back(Vec3(0.1f * i, 0.3f, 0.7f));  // one cell
  StochasticHashMap map(16);
  std::vector<double> wins(kK, 0.0);
  for (int t = 0; t < kTrials; ++t) {
    map.build(points, r, uint64_t(t));
    int kept = 0;
    map.for_each_in_radius(Vec3(0.3f, 0.3f, 0.7f), r, [&](const StochasticSlot& s, float) {
      ASSERT_EQ(s.count, uint32_t(kK));
      ASSERT_LT(s.payload, uint32_t(kK));
      EXPECT_EQ(s.position, points[s.payload]);
      wins[s.payload] += 1;
      ++kept;
    });
    ASSERT_EQ(kept, 1);
  }
  const double expected = double(kTrials) / kK;
  double chi2 = 0;
  for (double w : wins) chi2 += (w - expected) * (w - expected) / expected;
  EXPECT_GT(testing::chi2_survival(chi2, kK - 1), 0.001) << "chi2 = " << chi2;
}

// sum over slots of count * [in ball] is an unbiased estimate of the number of records in the
// ball. One-sample t-test over seeds, alpha = 0.001, in a heavily colliding 64-slot table.
TEST(StochasticHashMap, CountWeightedEstimateIsUnbiased) {
  const float r = 0.2f;
  const std::vector<Vec3> points = random_box(3000, -1.f, 1.f, 13);
  const Vec3 q(0.05f, -0.1f, 0.2f);
  const double truth = double(brute_force(points, q, r).size());
  StochasticHashMap map(64);
  double sum = 0, sum_sq = 0;
  constexpr int kTrials = 4000;
  for (int t = 0; t < kTrials; ++t) {
    map.build(points, r, uint64_t(t) + 1000);
    double estimate = 0;
    map.for_each_in_radius(q, r, [&](const StochasticSlot& s, float) { estimate += s.count; });
    sum += estimate;
    sum_sq += estimate * estimate;
  }
  const testing::MeanTest test = testing::t_test_mean(sum, sum_sq, kTrials, truth);
  EXPECT_GT(test.p, 0.001) << "mean " << test.mean << " vs " << truth;
  EXPECT_GT(truth, 10.0);
}

// Counts are exact and the winners do not depend on the thread count (atomic min, not arrival order).
TEST(StochasticHashMap, ConcurrentBuildIsExactAndDeterministic) {
  Pcg32 rng(14, 15);
  std::vector<Vec3> points(100000);
  for (Vec3& p : points) p = Vec3(rng.next_float() * 0.5f, 0.1f, rng.next_float() * 0.5f);
  StochasticHashMap serial(1024), parallel(1024);
  tbb::task_arena(1).execute([&] { serial.build(points, 0.01f, 42); });
  build_on_8_threads([&] { parallel.build(points, 0.01f, 42); });
  std::vector<uint32_t> expected_count(1024, 0);
  const StochasticHashMapView v = serial.view();
  for (const Vec3& p : points) ++expected_count[v.slot_of(v.geometry.key_of(p))];
  for (size_t s = 0; s < 1024; ++s) {
    ASSERT_EQ(parallel.slot(s).count, expected_count[s]);
    ASSERT_EQ(serial.slot(s).count, expected_count[s]);
    ASSERT_EQ(parallel.slot(s).payload, serial.slot(s).payload);
  }
  EXPECT_EQ(parallel.stats().records, points.size());
}

// The stochastic map returns exactly the in-radius records that won their slot (with few
// collisions, nearly all records): brute force restricted to the winners.
TEST(StochasticHashMap, QueriesReturnExactlyTheWinnersInRadius) {
  const float r = 0.05f;  // cell 0.1; points on a 0.3 lattice: at most one per cell
  std::vector<Vec3> points;
  for (int x = -5; x <= 5; ++x)
    for (int y = -5; y <= 5; ++y)
      for (int z = -5; z <= 5; ++z) points.push_back(Vec3(x * 0.3f + 0.01f, y * 0.3f + 0.02f, z * 0.3f + 0.03f));
  StochasticHashMap map(1 << 16);
  map.build(points, r, 1);
  const StochasticHashMapView v = map.view();
  std::vector<bool> winner(points.size());
  size_t winners = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    winner[i] = map.slot(v.slot_of(v.geometry.key_of(points[i]))).payload == i;
    winners += winner[i];
  }
  EXPECT_EQ(winners, map.stats().occupied_slots);
  EXPECT_GT(winners, points.size() * 9 / 10);  // birthday collisions in 2^16 slots: ~1%
  const std::vector<Vec3> queries = random_box(3000, -1.6f, 1.6f, 16);
  size_t hits = 0;
  for (size_t i = 0; i < queries.size() + points.size(); ++i) {
    const Vec3 q = i < queries.size() ? queries[i] : points[i - queries.size()] + Vec3(0.03f, 0.f, 0.f);
    std::vector<uint32_t> got, expected;
    map.for_each_in_radius(q, r, [&](const StochasticSlot& s, float) { got.push_back(s.payload); });
    std::sort(got.begin(), got.end());
    for (uint32_t j : brute_force(points, q, r))
      if (winner[j]) expected.push_back(j);
    ASSERT_EQ(got, expected);
    hits += got.size();
  }
  EXPECT_GE(hits, winners);
  // A radius of 4 cells: up to 729 cells, past the 27 remembered slots; still each slot once.
  for (size_t i = 0; i < 100; ++i) {
    std::vector<uint32_t> got, expected;
    map.for_each_in_radius(queries[i], 8 * r, [&](const StochasticSlot& s, float) { got.push_back(s.payload); });
    std::sort(got.begin(), got.end());
    ASSERT_TRUE(std::adjacent_find(got.begin(), got.end()) == got.end());
    for (uint32_t j : brute_force(points, queries[i], 8 * r))
      if (winner[j]) expected.push_back(j);
    ASSERT_EQ(got, expected);
  }
}

}  // namespace
}  // namespace pathspace
