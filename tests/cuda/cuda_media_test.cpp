// Participating media on the GPU (docs/media.md): PT's megakernel traces them with the same PS_HD
// code as the CPU (distance sampling, transmittance through interfaces, medium vertices selected by
// the hashed filter). The GPU's image must agree with the CPU's by the per-pixel z-test
// (gpu_comparison.h; alpha = 0.01, Sidak-corrected over this file's comparisons) on the Cornell box
// filled with a chromatic grid of fog and with a sphere of smoke, plain and with the hashed filter.
#include <gtest/gtest.h>

#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "gpu_comparison.h"
#include "support/integrator_comparison.h"
#include "support/media_scenes.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

constexpr int kComparisons = 4;
const double kAlphaImage = testing::sidak(0.01, kComparisons);

TEST(CudaMedia, FogAndSmokeMatchCpu) {
  PATHSPACE_REQUIRE_GPU();
  const Scene fog = testing::make_fog_cornell_box(32, 32, true);
  const Scene smoke = testing::make_smoke_sphere_box(32, 32);
  const RenderConfig hashed = with_filter(testing::default_config("pt", testing::test_seed(21)), "hashed", HashedFilterSettings{});
  testing::expect_gpu_matches_cpu(fog, testing::default_config("pt", testing::test_seed(20)), 1024, "fog grid pt cuda vs cpu",
                                  kAlphaImage);
  testing::expect_gpu_matches_cpu(fog, hashed, 256, "fog grid pt + hashed cuda vs cpu", kAlphaImage);
  testing::expect_gpu_matches_cpu(smoke, testing::default_config("pt", testing::test_seed(22)), 1024, "smoke pt cuda vs cpu",
                                  kAlphaImage);
  testing::expect_gpu_matches_cpu(smoke, hashed, 256, "smoke pt + hashed cuda vs cpu", kAlphaImage);
}

}  // namespace
}  // namespace pathspace
