// Path space filtering in participating media (2014 paper sec. 3; docs/media.md): on the Cornell
// box filled with chromatic, anisotropic fog, medium vertices are selected and filtered like surface
// vertices. At 4 paths per pixel the hashed filter lowers the relMSE against a long PT reference at
// least 5-fold, and the consistent filter's error falls with the path count (least-squares slope
// of log relMSE over log spp at most -0.6 over 4-256 spp). Each relMSE is the mean over two seeds.
// Equal-time figures are in docs/results/media-filtering.md.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "filter_render.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/filters/consistent_filter_settings.h"
#include "support/media_scenes.h"

namespace pathspace {
namespace {

constexpr int kRes = 64;

const Image& reference() {
  static const Image r = testing::render_with(testing::make_fog_cornell_box(kRes, kRes, false), testing::pt_config(1000), 4096).mean;
  return r;
}

double rel_mse(const RenderConfig& base, uint32_t spp) {
  const Scene scene = testing::make_fog_cornell_box(kRes, kRes, false);
  double sum = 0;
  for (uint64_t seed : {1, 2}) {
    RenderConfig c = base;
    c.seed = seed;
    sum += image_error(testing::render_with(scene, c, spp).mean, reference()).rel_mse;
  }
  return sum / 2;
}

TEST(MediaFiltering, HashedFilterLowersTheErrorFivefoldAt4spp) {
  const double pt = rel_mse(testing::pt_config(), 4);
  const double hashed = rel_mse(testing::hashed_config(), 4);
  std::printf("fog box relMSE at 4 spp: PT %.4g, hashed %.4g (%.1fx lower)\n", pt, hashed, pt / hashed);
  EXPECT_LE(hashed * 5.0, pt);
}

TEST(MediaFiltering, ConsistentFilterConverges) {
  const RenderConfig consistent = with_filter(testing::pt_config(), "consistent", ConsistentFilterSettings{});
  std::vector<double> x, y;
  for (uint32_t spp : {4u, 16u, 64u, 256u}) {
    const double e = rel_mse(consistent, spp);
    std::printf("consistent filter, %u spp: relMSE %.4g\n", spp, e);
    x.push_back(std::log(double(spp)));
    y.push_back(std::log(e));
  }
  const double n = double(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  std::printf("slope %.3f\n", slope);
  EXPECT_LE(slope, -0.6);
}

}  // namespace
}  // namespace pathspace
