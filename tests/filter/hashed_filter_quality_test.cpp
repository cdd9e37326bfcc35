// Quality regression of hashed path space filtering (Binder et al. 2021, sec. 4, fig. 1): on
// cornell-box at 512x512 and 1 spp, the filtered image's relMSE against a long path-traced
// reference (tests/data) must be at least 10x lower than unfiltered path tracing at 1 spp, and
// lower than unfiltered path tracing at 16 spp. relMSE of one 1-spp image is heavy-tailed (caustic
// fireflies), so each figure is the mean over four fixed seeds. Measured when this test was written
// (docs/benchmarks.md): PT 1 spp 16.8, PT 16 spp 1.01, filtered 1 spp 0.57 at the default settings.
#include <gtest/gtest.h>

#include <string>

#include "filter_render.h"
#include "pathspace/film/block_metrics.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/io/image_io.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace {
namespace {

constexpr int kSeeds = 4;

double mean_rel_mse(const Scene& scene, const Image& reference, RenderConfig settings, uint32_t spp,
                    uint64_t first_seed) {
  double sum = 0;
  for (int i = 0; i < kSeeds; ++i) {
    settings.seed = first_seed + uint64_t(i);
    sum += image_error(testing::render_with(scene, settings, spp).mean, reference).rel_mse;
  }
  return sum / kSeeds;
}

TEST(HashedFilterQuality, CornellBox512At1sppBeatsTenfoldAnd16spp) {
  const Image reference = read_image(PATHSPACE_TEST_DATA_DIR "/cornell-box-512-pt4096.exr");
  const Scene scene = make_builtin_scene("cornell-box", reference.width, reference.height);
  const double pt1 = mean_rel_mse(scene, reference, testing::pt_config(), 1, 1);
  const double pt16 = mean_rel_mse(scene, reference, testing::pt_config(), 16, 101);
  const double filtered = mean_rel_mse(scene, reference, testing::hashed_config(), 1, 1);
  RecordProperty("relmse_pt1", std::to_string(pt1));
  RecordProperty("relmse_pt16", std::to_string(pt16));
  RecordProperty("relmse_filtered1", std::to_string(filtered));
  std::printf("relMSE: PT 1 spp %.4g, PT 16 spp %.4g, hashed filter 1 spp %.4g (%.1fx lower than PT 1 spp)\n", pt1,
              pt16, filtered, pt1 / filtered);
  EXPECT_LE(filtered * 10.0, pt1);
  EXPECT_LT(filtered, pt16);
}

// Issue 43's acceptance, "one path per pixel that looks like the reference": at its defaults
// (caustic photons, camera-side branches at glass) one pass of the hashed filter at 512x512 must
// have, as means over seeds 1-3 against the stored 4096-spp PT reference, per-pixel relMSE <= 0.15,
// relMSE of 8x8 block averages <= 0.015 and at most 2% blotched blocks (film/block_metrics.h). The
// renders are fixed by their seeds, so this is a regression check with the issue's limits.
struct OnePassError {
  double rel_mse = 0.0, block_rel_mse = 0.0, blotched = 0.0;
};

OnePassError one_pass_error(const std::string& scene_name, const std::string& reference_file) {
  const Image reference = read_image(reference_file);
  const Scene scene = make_builtin_scene(scene_name, reference.width, reference.height);
  constexpr int kAcceptanceSeeds = 3;
  OnePassError e;
  for (int seed = 1; seed <= kAcceptanceSeeds; ++seed) {
    const Image image = testing::render_with(scene, testing::hashed_config(uint64_t(seed)), 1).mean;
    e.rel_mse += image_error(image, reference).rel_mse / kAcceptanceSeeds;
    const BlockError blocks = block_error(image, reference);
    e.block_rel_mse += blocks.block_rel_mse / kAcceptanceSeeds;
    e.blotched += blocks.blotched_share / kAcceptanceSeeds;
  }
  std::printf("%s, one pass, hashed defaults: relMSE %.4g, block relMSE %.4g, blotched %.2f%%\n", scene_name.c_str(),
              e.rel_mse, e.block_rel_mse, 100.0 * e.blotched);
  return e;
}

void expect_issue_43_limits(const OnePassError& e) {
  EXPECT_LE(e.rel_mse, 0.15);
  EXPECT_LE(e.block_rel_mse, 0.015);
  EXPECT_LE(e.blotched, 0.02);
}

// Measured when written: 0.054, 0.0079, 0.58% (docs/results/one-path-per-pixel.md); without the
// caustic photons (--psf-caustic-photons 0) 1.00, 0.12 and 7.2%: the glass sphere's caustic
// averaged into voxels.
TEST(HashedFilterQuality, CornellBox512OnePassMeetsTheBlotchLimits) {
  expect_issue_43_limits(one_pass_error("cornell-box", PATHSPACE_TEST_DATA_DIR "/cornell-box-512-pt4096.exr"));
}

// Measured when written: 0.060, 0.0095, 0.61%; without the caustic photons 1.21, 0.148 and 7.9%.
TEST(HashedFilterQuality, CornellGlossy512OnePassMeetsTheBlotchLimits) {
  expect_issue_43_limits(one_pass_error("cornell-glossy", PATHSPACE_TEST_DATA_DIR "/cornell-glossy-512-pt4096.exr"));
}

}  // namespace
}  // namespace pathspace
