// Photon-mapped caustics beside the consistent filter (Keller, Dahm, Binder 2014, sec. 2.3).
//
// The photon map holds only light -> specular+ -> non-delta photons: none in a scene without delta
// surfaces, some in cornell-box (its glass and mirror spheres). On cornell-box at a small size the
// path tracer's caustic paths (diffuse -> glass -> light, found by BSDF sampling, the fireflies the
// filter turns into splotches) come from the photon map instead: against a long path-traced
// reference the error is well below the consistent filter's without photons at every step, and it
// falls as the filter's and the photons' radii shrink (consistency). Means over two seeds.
#include <gtest/gtest.h>

#include <cstdio>

#include "filter_render.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/filters/consistent_filter_settings.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace {
namespace {

RenderConfig consistent_config(double photons_per_pixel, uint64_t seed) {
  ConsistentFilterSettings s;
  s.caustics.photons_per_pixel = photons_per_pixel;
  return with_filter(make_render_config("pt", PtSettings{}, seed), "consistent", s);
}

TEST(ConsistentFilterCaustics, PhotonsAreStoredOnlyAfterDeltaBounces) {
  const Scene empty = make_builtin_scene("cornell-empty-area", 16, 16);
  const auto none = testing::render_with(empty, consistent_config(78.125, 1), 2);  // 20000 photons per pass
  EXPECT_EQ(none.stats.details.number("caustics.photons"), 40000.0);
  EXPECT_EQ(none.stats.details.number("caustics.stored"), 0.0) << "no delta surface, so no caustic photon";
  const Scene box = make_builtin_scene("cornell-box", 16, 16);
  const auto some = testing::render_with(box, consistent_config(78.125, 1), 2);
  EXPECT_GT(some.stats.details.number("caustics.stored"), 400.0);
  EXPECT_LT(some.stats.details.number("caustics.stored"), 20000.0);
}

double mean_rel_mse(const Scene& scene, const testing::FilteredRender& reference, double photons, uint32_t spp) {
  double sum = 0.0;
  for (uint64_t seed = 0; seed < 2; ++seed)
    sum += image_error(testing::render_with(scene, consistent_config(photons, 500 + seed), spp).mean, reference.mean,
                       &reference.variance)
               .rel_mse;
  return sum / 2.0;
}

TEST(ConsistentFilterCaustics, PhotonMappedCausticsLowerTheErrorAndConverge) {
  constexpr int kSize = 48;
  const Scene scene = make_builtin_scene("cornell-box", kSize, kSize);
  const testing::FilteredRender reference = testing::render_with(scene, testing::pt_config(7), 8192);
  const double photons = 64.0;  // per pixel and pass
  double previous = 0.0;
  for (const uint32_t spp : {4u, 16u, 64u}) {
    const double without = mean_rel_mse(scene, reference, 0, spp);
    const double with = mean_rel_mse(scene, reference, photons, spp);
    std::printf("spp %3u: relMSE consistent %.4g, with caustic photons %.4g (%.2fx)\n", spp, without, with, without / with);
    EXPECT_LT(with, 0.7 * without) << spp << " spp";
    if (previous > 0.0) {
      EXPECT_LT(with, previous) << spp << " spp";
    }
    previous = with;
  }
}

}  // namespace
}  // namespace pathspace
