// The hashed filter's query-only anti-aliasing paths (--psf-aa-paths, hashed_filter_query.cpp;
// Keller, Dahm, Binder 2014, sec. 3): at thin geometry they lower the error of a 1-spp render; with
// the table kept across frames they read the blended history, so the error at the end of a static
// sequence falls below what one primary hit per pixel allows; frames stay bit-identical for any
// thread count; the statistics count them. Their image mean is checked in the furnace tests
// (hashed_filter_furnace_test.cpp).
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "filter_render.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/session/frame_sequence.h"

namespace pathspace {
namespace {

using testing::frames_of;
using testing::still;

TEST(HashedFilterQueries, LowerTheErrorAtThinGeometry) {
  const Scene scene = make_builtin_scene("filter-fence", 128, 128);
  const testing::FilteredRender reference = testing::render_with(scene, testing::pt_config(11), 1024);
  const auto error = [&](int aa_paths) {
    double sum = 0.0;
    for (uint64_t seed = 0; seed < 3; ++seed) {
      HashedFilterSettings s;
      s.aa_paths = aa_paths;
      const testing::FilteredRender r = testing::render_with(scene, testing::hashed_config(30 + seed, s), 1);
      EXPECT_EQ(r.stats.dropped_samples, 0u);
      sum += image_error(r.mean, reference.mean, &reference.variance).rel_mse;
    }
    return sum / 3.0;
  };
  const double without = error(0), with = error(3);
  std::printf("relMSE at 1 spp: hashed %.4g, with 3 query paths per pixel %.4g (%.2fx)\n", without, with, without / with);
  EXPECT_LT(with, 0.5 * without);
}

HashedFilterSettings integrate(int aa_paths) {
  HashedFilterSettings s;
  s.key.psf_scale = 2.f;
  s.temporal.mode = TemporalMode::integrate;
  s.aa_paths = aa_paths;
  return s;
}

// A still Cornell box at 32 x 32, 16 frames of 1 spp: integration removes the voxels' noise, not
// the edge pixels' aliasing of one primary hit (hashed_temporal_test.cpp measures that floor);
// the queries average 1 + 3 hits per pixel, reading the voxels' blended histories.
TEST(HashedFilterQueries, ReadTheBlendedHistoryAcrossFrames) {
  const Scene scene = make_builtin_scene("cornell-empty-area", 32, 32);
  const testing::FilteredRender reference = testing::render_with(scene, testing::pt_config(7), 4096);
  const auto error = [&](const Image& img) { return image_error(img, reference.mean, &reference.variance).rel_mse; };
  Statistics stats;
  const std::vector<Image> plain = frames_of(still(scene), testing::hashed_config(3, integrate(0)), 16);
  const std::vector<Image> queried = frames_of(still(scene), testing::hashed_config(3, integrate(3)), 16, 0, &stats);
  std::printf("relMSE frame 1 -> 16: integrate %.4g -> %.4g, with 3 query paths %.4g -> %.4g\n", error(plain.front()),
              error(plain.back()), error(queried.front()), error(queried.back()));
  EXPECT_LT(error(queried.back()), 0.5 * error(plain.back()));
  EXPECT_LT(error(queried.back()), error(queried.front()) / 2.5);
  // Every query path but those that see the light first (no vertex to query) has one record; most
  // find a voxel (measured 94%: a jittered 2-pixel voxel may hold no vertex yet in the first frames,
  // and such a query path is left out of its pixel).
  const double paths = 16.0 * 3.0 * 32.0 * 32.0, records = stats.number("hashed.query_records");
  EXPECT_GT(records, 0.95 * paths);
  EXPECT_LE(records, paths);
  EXPECT_GT(stats.number("hashed.query_found"), 0.9 * records);
}

// An orbiting camera with eviction every frame: queries only read the table, so frames stay
// bit-identical for 1 and 2 threads.
TEST(HashedFilterQueries, FramesAreBitIdenticalForAnyThreadCount) {
  Animation animation;
  animation.scene_at = [](double t) { return make_builtin_scene_at("cornell-moving-light", 24, 24, t); };
  animation.orbit_degrees_per_frame = 3.f;
  for (const bool temporal : {false, true}) {
    HashedFilterSettings s = integrate(2);
    if (!temporal) s.temporal.mode = TemporalMode::off;
    s.table_factor = 2.f;
    s.temporal.occupancy = 0.25f;
    const RenderConfig config = testing::hashed_config(11, s);
    const std::vector<Image> one = frames_of(animation, config, 4, 1), two = frames_of(animation, config, 4, 2);
    ASSERT_EQ(one.size(), two.size());
    for (size_t f = 0; f < one.size(); ++f) EXPECT_TRUE(testing::bit_identical(one[f], two[f])) << "temporal " << temporal << " frame " << f;
  }
}

}  // namespace
}  // namespace pathspace
