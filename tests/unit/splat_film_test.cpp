// SplatFilm's per-worker shards (worker_view, merge_workers): the sums must be the very integers the
// shared atomic view gives, for any thread count, and nothing may survive into the next pass.
#include <gtest/gtest.h>

#include <vector>

#include "pathspace/film/splat_film.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/sampling/rng.h"

namespace pathspace {
namespace {

constexpr int kWidth = 37, kHeight = 23;  // odd sizes: pixel sums straddle cache lines

struct Splat {
  uint32_t pixel;
  Rgb value;
};

std::vector<Splat> random_splats(size_t n) {
  Pcg32 rng(12345, 7);
  std::vector<Splat> out(n);
  for (Splat& s : out) {
    s.pixel = rng.next_u32() % uint32_t(kWidth * kHeight);
    s.value = Rgb(rng.next_float(), 10.f * rng.next_float(), 1e-3f * rng.next_float());
  }
  return out;
}

std::vector<Rgb> values(const SplatFilm& film) {
  std::vector<Rgb> out;
  for (uint32_t i = 0; i < uint32_t(kWidth * kHeight); ++i) out.push_back(film.value(i));
  return out;
}

void expect_same_bits(const std::vector<Rgb>& a, const std::vector<Rgb>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i)
    for (int c = 0; c < 3; ++c) ASSERT_EQ(a[i][c], b[i][c]) << "pixel " << i << " channel " << c;
}

std::vector<Rgb> through_shared_view(const std::vector<Splat>& splats) {
  SplatFilm film(kWidth, kHeight);
  const SplatFilmView v = film.view();
  for (const Splat& s : splats) v.add(s.pixel, s.value);
  return values(film);
}

// Adds the splats from parallel workers through their own views, as the integrators do.
void through_worker_views(SplatFilm& film, const std::vector<Splat>& splats) {
  film.clear();
  parallel_for(splats.size(), 16, [&](size_t begin, size_t end) {
    const SplatFilmView v = film.worker_view();
    for (size_t i = begin; i < end; ++i) v.add(splats[i].pixel, splats[i].value);
  });
  film.merge_workers();
}

TEST(SplatFilm, WorkerShardsSumToTheSharedViewsBits) {
  const std::vector<Splat> splats = random_splats(100000);
  const std::vector<Rgb> expected = through_shared_view(splats);
  for (int threads : {1, 2, 4}) {
    ThreadLimit limit(threads);
    SplatFilm film(kWidth, kHeight);
    through_worker_views(film, splats);
    expect_same_bits(values(film), expected);
    EXPECT_EQ(film.overflows(), 0u);
  }
}

TEST(SplatFilm, NextPassStartsFromZero) {
  // Two passes on one film: the second must equal a fresh film's (the shards were zeroed by the merge).
  const std::vector<Splat> first = random_splats(5000), second = random_splats(7000);
  SplatFilm film(kWidth, kHeight);
  through_worker_views(film, first);
  through_worker_views(film, second);
  expect_same_bits(values(film), through_shared_view(second));
}

TEST(SplatFilm, ClearDropsShardsOfAnUnmergedPass) {
  // A pass that ended by an exception never merged: clear() must not let its shards leak on.
  SplatFilm film(kWidth, kHeight);
  parallel_for(1000, 16, [&](size_t begin, size_t end) {
    const SplatFilmView v = film.worker_view();
    for (size_t i = begin; i < end; ++i) v.add(uint32_t(i % 50), Rgb(1.f));
  });
  film.clear();
  film.merge_workers();
  for (const Rgb& v : values(film)) EXPECT_TRUE(is_black(v));
}

TEST(SplatFilm, FilmsBeyondTheShardBudgetAddAtomically) {
  // A film larger than kMaxShardBytes gets no shards: worker views are the shared atomic view.
  const int width = int(SplatFilm::kMaxShardBytes / (3 * sizeof(uint64_t))) + 1;
  SplatFilm film(width, 1);
  const SplatFilmView v = film.worker_view();
  EXPECT_FALSE(v.exclusive);
  v.add(uint32_t(width - 1), Rgb(2.f));
  film.merge_workers();
  EXPECT_EQ(film.value(uint32_t(width - 1))[0], 2.f);
}

TEST(SplatFilm, OverflowsAreCountedInShardsToo) {
  SplatFilm film(kWidth, kHeight);
  parallel_for(8, 1, [&](size_t, size_t) {
    const SplatFilmView v = film.worker_view();
    v.add(0, Rgb(-1.f));  // negative: rejected
  });
  film.merge_workers();
  EXPECT_EQ(film.overflows(), 8u);
  EXPECT_TRUE(is_black(film.value(0)));
}

}  // namespace
}  // namespace pathspace
