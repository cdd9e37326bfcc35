// The hashed path space filter in the renderer (Binder et al. 2021): `--filter none` is plain path
// tracing bit for bit, the filtered image is bit-identical for any thread count and across reruns,
// and the fallbacks of the table (probe limit, tiny table) keep images finite and unfiltered.
#include <cstring>

#include <gtest/gtest.h>

#include "filter_render.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace {
namespace {

using testing::bit_identical;
using testing::hashed_settings;
using testing::render_with;

struct SelectionCase {
  const char* name;
  const char* scene;
  VertexSelectionMode mode;
  int n;
  bool split_layers;
};

class FilterNone : public ::testing::TestWithParam<SelectionCase> {};

TEST_P(FilterNone, EqualsPlainPathTracingBitForBit) {
  const SelectionCase c = GetParam();
  const Scene scene = make_builtin_scene(c.scene, 40, 32);
  IntegratorSettings plain;
  plain.seed = 3;
  plain.pt.selection.mode = c.mode;
  plain.pt.selection.n = c.n;
  plain.pt.selection.max_vertices = c.n;
  plain.pt.selection.split_layers = c.split_layers;
  IntegratorSettings buffered = plain;
  buffered.filter.force_vertex_buffer = true;
  const auto a = render_with(scene, plain, 3);
  const auto b = render_with(scene, buffered, 3);
  EXPECT_TRUE(bit_identical(a.mean, b.mean));
  EXPECT_TRUE(bit_identical(a.variance, b.variance));
  EXPECT_EQ(a.stats.rays, b.stats.rays);
}

INSTANTIATE_TEST_SUITE_P(Selections, FilterNone,
                         ::testing::Values(SelectionCase{"bs_c_first", "cornell-box", VertexSelectionMode::first, 1, true},
                                           SelectionCase{"gbs_c_first", "gbs_c", VertexSelectionMode::first, 1, true},
                                           SelectionCase{"gbs_c_merged_layers", "gbs_c", VertexSelectionMode::first, 1, false},
                                           SelectionCase{"gbs_c_second", "gbs_c", VertexSelectionMode::nth, 2, true},
                                           SelectionCase{"gbs_b_all3", "gbs_b", VertexSelectionMode::all, 3, true}),
                         [](const ::testing::TestParamInfo<SelectionCase>& i) { return std::string(i.param.name); });

TEST(HashedFilter, BitIdenticalForOneAndTwoThreadsAndReruns) {
  const Scene scene = make_builtin_scene("gbs_c", 64, 48);
  IntegratorSettings s = hashed_settings(11);
  s.filter.hashed.neighbour_search = true;
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
  IntegratorSettings s = hashed_settings(4);
  const auto combined = render_with(scene, s, 2);
  s.filter.hashed.local_combining = false;
  EXPECT_TRUE(bit_identical(combined.mean, render_with(scene, s, 2).mean));
}

TEST(HashedFilter, FilteringChangesTheImage) {
  // Brightness is checked exactly by the furnace tests and image quality by the relMSE regression.
  const Scene scene = make_builtin_scene("cornell-empty-area", 64, 64);
  const auto p = render_with(scene, IntegratorSettings{}, 4);
  const auto f = render_with(scene, hashed_settings(), 4);
  EXPECT_FALSE(bit_identical(p.mean, f.mean));
}

TEST(HashedFilter, RendersEveryBuiltinSceneProgressively) {
  for (const BuiltinSceneInfo& info : builtin_scenes()) {
    SCOPED_TRACE(info.name);
    const Scene scene = make_builtin_scene(info.name, 32, 24);
    const auto f = render_with(scene, hashed_settings(2), 3);  // 3 filtered passes accumulated
    EXPECT_EQ(f.stats.spp, 3u);
    EXPECT_EQ(f.stats.dropped_samples, 0u);
    double sum = 0;
    for (const Rgb& v : f.mean.pixels) {
      EXPECT_TRUE(all_finite(v));
      sum += average(v);
    }
    EXPECT_GT(sum, 0.0);
    EXPECT_NE(f.stats.report.find("probe-limit fallbacks 0"), std::string::npos) << f.stats.report;
  }
}

TEST(HashedFilter, TinyTableFallsBackToUnfilteredContributions) {
  const Scene scene = make_builtin_scene("cornell-empty-area", 32, 32);
  IntegratorSettings s = hashed_settings(5);
  s.filter.hashed.table_factor = 16.f / 1024.f;  // one cache line of cells for 1024 pixels
  s.filter.hashed.key.psf_scale = 0.5f;          // many distinct voxels
  const auto f = render_with(scene, s, 1);
  EXPECT_NE(f.stats.report.find("probe-limit fallbacks"), std::string::npos);
  EXPECT_EQ(f.stats.dropped_samples, 0u);
  for (const Rgb& v : f.mean.pixels) EXPECT_TRUE(all_finite(v));
}

// Debug images (AOVs) keep per-vertex keys and counts only when asked for; asking must not change
// the image, and a render that asks for AOVs without them gets none rather than stale data.
TEST(HashedFilter, DebugImagesOnlyWhenRequestedAndImageUnchanged) {
  const Scene scene = make_builtin_scene("cornell-box", 48, 48);
  const Accel accel(scene);
  auto render_aovs = [&](bool debug_images, RenderStats* stats) {
    Film film(scene.camera.width, scene.camera.height);
    RenderRequest req;
    req.spp = 2;
    req.want_aovs = true;
    req.settings = hashed_settings(11);
    req.settings.filter.hashed.debug_images = debug_images;
    *stats = render(scene, accel, req, film);
    return film.mean();
  };
  RenderStats plain, debug;
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

}  // namespace
}  // namespace pathspace
