// Fig. 4 of Keller, Dahm, Binder 2014 as numbers, and fig. 7 as a measurement.
//
// Weights (sec. 2.1): the built-in scene filter-leak is a room split by a thin wall with a point
// light on one side, so every path in the dark half carries exactly zero; the light a filter puts
// there has leaked through the wall. Each weight alone leaks less than none, each one added leaks
// less than before (uniform, +normal, +albedo, +visibility, the order of fig. 4), and with all
// three nothing leaks at all, since the point light's visibility separates the two halves.
//
// Anti-aliasing (sec. 3, fig. 7): on filter-fence (bars about a pixel wide), one filtered path per
// pixel plus three query-only camera paths per pixel has a lower error against a converged
// reference than the filtered path alone.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "filter_render.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/filters/consistent_filter_settings.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace {
namespace {

RenderConfig consistent_config(const ConsistentFilterSettings& s, uint64_t seed = 3) {
  return with_filter(make_render_config("pt", PtSettings{}, seed), "consistent", s);
}

TEST(ConsistentFilterWeights, EachWeightReducesTheLightLeakedThroughAThinWall) {
  const Scene scene = make_builtin_scene("filter-leak", 96, 96);
  constexpr uint32_t kSpp = 4;
  const testing::FilteredRender pt = testing::render_with(scene, testing::pt_config(3), kSpp);
  // The dark half: pixels whose every path carried zero (the same paths the filter sees).
  std::vector<size_t> dark;
  double total = 0.0;
  for (size_t i = 0; i < pt.mean.size(); ++i) {
    total += average(pt.mean.pixels[i]);
    if (is_black(pt.mean.pixels[i])) dark.push_back(i);
  }
  ASSERT_GT(dark.size(), pt.mean.size() / 5) << "the dark half must fill a good part of the image";
  ASSERT_GT(total, 0.0);
  const auto leak = [&](uint32_t weights) {
    ConsistentFilterSettings s;
    s.weights = weights;
    const Image filtered = testing::render_with(scene, consistent_config(s), kSpp).mean;
    double sum = 0.0;
    for (const size_t i : dark) sum += average(filtered.pixels[i]);
    return sum / total;
  };
  const double none = leak(0u), normal = leak(kWeightNormal), albedo = leak(kWeightAlbedo), visibility = leak(kWeightVisibility);
  const double normal_albedo = leak(kWeightNormal | kWeightAlbedo);
  const double all = leak(kWeightNormal | kWeightAlbedo | kWeightVisibility);
  std::printf("leaked / total: none %.4g, normal %.4g, albedo %.4g, visibility %.4g, normal+albedo %.4g, all %.4g\n", none, normal,
              albedo, visibility, normal_albedo, all);
  EXPECT_GT(none, 1e-3) << "the filter must leak without weights, or the scene tests nothing";
  EXPECT_LT(normal, none);
  EXPECT_LT(albedo, none);
  EXPECT_LT(visibility, none);
  EXPECT_LT(normal_albedo, normal);
  EXPECT_LT(all, normal_albedo);
  EXPECT_EQ(all, 0.0);
}

TEST(ConsistentFilterAntiAliasing, QueryPathsLowerTheErrorAtThinGeometry) {
  const Scene scene = make_builtin_scene("filter-fence", 128, 128);
  const testing::FilteredRender reference = testing::render_with(scene, testing::pt_config(11), 1024);
  const auto error = [&](int aa_paths) {
    double sum = 0.0;
    for (uint64_t seed = 0; seed < 3; ++seed) {
      ConsistentFilterSettings s;
      s.aa_paths = aa_paths;
      const testing::FilteredRender r = testing::render_with(scene, consistent_config(s, 20 + seed), 1);
      EXPECT_EQ(r.stats.dropped_samples, 0u);
      sum += image_error(r.mean, reference.mean, &reference.variance).rel_mse;
    }
    return sum / 3.0;
  };
  const double without = error(0), with = error(3);
  std::printf("relMSE at 1 spp: filtered %.4g, with 3 query paths per pixel %.4g (%.2fx)\n", without, with, without / with);
  EXPECT_LT(with, 0.8 * without);
}

}  // namespace
}  // namespace pathspace
