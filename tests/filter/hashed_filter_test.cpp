// The hashed path space filter in the renderer (Binder et al. 2021): every path through the vertex
// buffer and the resolve step, filtered by nothing, is plain path tracing (the same rays; values
// equal up to the rounding of the split, since plain path tracing no longer splits its paths), the filtered image is bit-identical for any thread count and across reruns,
// and the fallbacks of the table (probe limit, tiny table) keep images finite and unfiltered.
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "filter_render.h"
#include "pathspace/accel/accel.h"
#include "pathspace/session/render_session.h"
#include "pathspace/scene/builtin_scenes.h"
#include "support/test_names.h"

namespace pathspace {
namespace {

using testing::bit_identical;
using testing::hashed_config;
using testing::pt_config;
using testing::render_with;

struct SelectionCase {
  const char* name;
  const char* scene;
  VertexSelectionMode mode;
  int n;
  bool split_layers;
};

// gtest prints the parameter in test listings (not as "N-byte object <...>").
void PrintTo(const SelectionCase& c, std::ostream* os) { *os << c.name; }

class FilterNone : public ::testing::TestWithParam<SelectionCase> {};

TEST_P(FilterNone, EqualsPlainPathTracing) {
  const SelectionCase c = GetParam();
  const Scene scene = make_builtin_scene(c.scene, 40, 32);
  PtSettings pt;
  pt.selection.mode = c.mode;
  pt.selection.n = c.n;
  pt.selection.max_vertices = c.n;
  pt.selection.split_layers = c.split_layers;
  // One path, not its branches at glass: those are another estimator (camera_branches_test.cpp).
  pt.selection.camera_splits = 0;
  const RenderConfig plain = pt_config(3, pt);
  // Every path through the vertex buffer and the resolve step, filtered by nothing.
  RenderConfig buffered = plain;
  buffered.filter = FilterChoice{"passthrough", {}};
  const auto a = render_with(scene, plain, 3);
  const auto b = render_with(scene, buffered, 3);
  // Plain path tracing sums each path as it goes; the buffered path is split at its selected
  // vertices and recombined as prefix + (throughput x albedo) x (contribution / albedo): float
  // rounding of those products and of one division (tests/unit/pt_unsplit_paths_test.cpp checks
  // it path by path).
  EXPECT_LT(testing::largest_relative_difference(a.mean, b.mean), 1e-5);
  EXPECT_EQ(a.stats.rays, b.stats.rays);
  EXPECT_EQ(a.stats.shadow_rays, b.stats.shadow_rays);
}

INSTANTIATE_TEST_SUITE_P(Selections, FilterNone,
                         ::testing::Values(SelectionCase{"bs_c_first", "cornell-box", VertexSelectionMode::first, 1, true},
                                           SelectionCase{"gbs_c_first", "gbs_c", VertexSelectionMode::first, 1, true},
                                           SelectionCase{"gbs_c_merged_layers", "gbs_c", VertexSelectionMode::first, 1, false},
                                           SelectionCase{"gbs_c_second", "gbs_c", VertexSelectionMode::nth, 2, true},
                                           SelectionCase{"gbs_b_all3", "gbs_b", VertexSelectionMode::all, 3, true}),
                         [](const ::testing::TestParamInfo<SelectionCase>& i) { return testing::test_name(i.param.name); });

TEST(HashedFilter, BitIdenticalForOneAndTwoThreadsAndReruns) {
  const Scene scene = make_builtin_scene("gbs_c", 64, 48);
  HashedFilterSettings h;
  h.neighbour_search = true;
  RenderConfig s = hashed_config(11, h);
  const auto one = render_with(scene, s, 2, 1);
  const auto two = render_with(scene, s, 2, 2);
  const auto again = render_with(scene, s, 2, 2);
  EXPECT_TRUE(bit_identical(one.mean, two.mean));
  EXPECT_TRUE(bit_identical(two.mean, again.mean));
  s.seed = 12;
  EXPECT_FALSE(bit_identical(two.mean, render_with(scene, s, 2, 2).mean)) << "the seed must matter";
}

TEST(HashedFilter, LocalCombiningDoesNotChangeTheResult) {
  // Integer sums: combining vertices before the atomics must give exactly the same averages.
  const Scene scene = make_builtin_scene("gbs_c", 64, 48);
  HashedFilterSettings h;
  const auto combined = render_with(scene, hashed_config(4, h), 2);
  h.local_combining = false;
  EXPECT_TRUE(bit_identical(combined.mean, render_with(scene, hashed_config(4, h), 2).mean));
}

TEST(HashedFilter, FilteringChangesTheImage) {
  // Brightness is checked exactly by the furnace tests and image quality by the relMSE regression.
  const Scene scene = make_builtin_scene("cornell-empty-area", 64, 64);
  const auto p = render_with(scene, pt_config(), 4);
  const auto f = render_with(scene, hashed_config(), 4);
  EXPECT_FALSE(bit_identical(p.mean, f.mean));
}

TEST(HashedFilter, RendersEveryBuiltinSceneProgressively) {
  for (const BuiltinSceneInfo& info : builtin_scenes()) {
    SCOPED_TRACE(info.name);
    const Scene scene = make_builtin_scene(info.name, 32, 24);
    const auto f = render_with(scene, hashed_config(2), 3);  // 3 filtered passes accumulated
    EXPECT_EQ(f.stats.spp, 3u);
    EXPECT_EQ(f.stats.dropped_samples, 0u);
    double sum = 0;
    for (const Rgb& v : f.mean.pixels) {
      EXPECT_TRUE(all_finite(v));
      sum += average(v);
    }
    EXPECT_GT(sum, 0.0);
    EXPECT_EQ(f.stats.details.number("hashed.probe_limit_fallbacks"), 0.0) << format_statistics(f.stats.details);
  }
}

TEST(HashedFilter, TinyTableFallsBackToUnfilteredContributions) {
  const Scene scene = make_builtin_scene("cornell-empty-area", 32, 32);
  HashedFilterSettings h;
  h.table_factor = 16.f / 1024.f;  // one cache line of cells for 1024 pixels
  h.key.psf_scale = 0.5f;          // many distinct voxels
  const auto f = render_with(scene, hashed_config(5, h), 1);
  EXPECT_GT(f.stats.details.number("hashed.probe_limit_fallbacks"), 0.0) << format_statistics(f.stats.details);
  EXPECT_EQ(f.stats.dropped_samples, 0u);
  for (const Rgb& v : f.mean.pixels) EXPECT_TRUE(all_finite(v));
}

// Debug images (AOVs) keep per-vertex keys and counts only when asked for; asking must not change
// the image, and a render that asks for AOVs without them gets none rather than stale data.
TEST(HashedFilter, DebugImagesOnlyWhenRequestedAndImageUnchanged) {
  const Scene scene = make_builtin_scene("cornell-box", 48, 48);
  const Accel accel(scene);
  auto render_aovs = [&](bool debug_images, RenderSnapshot* snap) {
    HashedFilterSettings h;
    h.debug_images = debug_images;
    *snap = render(scene, accel, hashed_config(11, h), RunLimit::for_passes(2));
    return snap->mean;
  };
  RenderSnapshot plain, debug;
  const Image a = render_aovs(false, &plain);
  const Image b = render_aovs(true, &debug);
  EXPECT_TRUE(bit_identical(a, b));
  EXPECT_TRUE(plain.aovs.empty());
  ASSERT_EQ(debug.aovs.size(), 4u);
  for (const NamedImage& aov : debug.aovs) {
    if (aov.name != "count") continue;
    double sum = 0.0;
    for (const Rgb& v : aov.image.pixels) sum += v.r;
    EXPECT_GT(sum / double(aov.image.pixels.size()), 1.0) << "a voxel averages several vertices";
  }
}

// With --temporal the debug images add the voxel's history (sec. 3.4): its weight N grows from step
// to step over a still view, and the history's weight alpha is 0 at the first step and positive
// after it.
TEST(HashedFilter, TemporalDebugImagesShowTheHistory) {
  const auto scene = std::make_shared<const Scene>(make_builtin_scene("cornell-box", 48, 48));
  const auto accel = std::make_shared<const Accel>(*scene);
  HashedFilterSettings h;
  h.debug_images = true;
  h.temporal.mode = TemporalMode::integrate;
  RenderSession session(scene, accel, hashed_config(5, h));
  const auto mean_of = [](const RenderSnapshot& snap, const std::string& name) {
    for (const NamedImage& aov : snap.aovs) {
      if (aov.name != name) continue;
      double sum = 0.0;
      for (const Rgb& v : aov.image.pixels) sum += v.r;
      return sum / double(aov.image.pixels.size());
    }
    ADD_FAILURE() << "no debug image " << name;
    return -1.0;
  };
  std::vector<double> history, alpha;
  for (uint64_t frame = 0; frame < 3; ++frame) {
    if (frame > 0) session.begin_frame(scene, accel, frame);
    session.run(RunLimit::for_passes(1));
    const RenderSnapshot snap = session.snapshot();
    EXPECT_EQ(snap.aovs.size(), 6u);
    history.push_back(mean_of(snap, "history"));
    alpha.push_back(mean_of(snap, "alpha"));
  }
  EXPECT_EQ(alpha[0], 0.0) << "no history at the first step";
  EXPECT_GT(history[0], 1.0);
  EXPECT_GT(alpha[1], 0.2);
  EXPECT_GT(history[1], 1.5 * history[0]);
  EXPECT_GT(history[2], history[1]);
  EXPECT_GT(alpha[2], alpha[1]) << "integration: alpha = N_old / (N_old + N_new) grows";
}

}  // namespace
}  // namespace pathspace
