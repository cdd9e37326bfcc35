// Path tracing on the GPU (--device cuda) against the CPU: the same estimator, so the images agree
// by the per-pixel z-test of the integrator consistency tests (alpha_pixel 1e-3; an image fails when
// its count of failing pixels is improbable at alpha = 0.01, Sidak-corrected over this file's
// comparisons). Skipped, with the reason printed, where no CUDA device is present.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "pathspace/io/scene_loader.h"
#include "pathspace/scene/builtin_scenes.h"
#include "gpu_comparison.h"
#include "support/integrator_comparison.h"
#include "support/shared_data.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

constexpr int kComparisons = 5;
const double kAlphaImage = testing::sidak(0.01, kComparisons);

// The shared scenes' folder: PATHSPACE_SHARED_SCENES_DIR in the environment (a GPU machine with a
// copy elsewhere) or the build's.
std::string shared_scenes_dir() {
  const char* v = std::getenv("PATHSPACE_SHARED_SCENES_DIR");
  return v && *v ? std::string(v) : std::string(PATHSPACE_SHARED_SCENES_DIR);
}

void expect_gpu_matches_cpu(const Scene& scene, const RenderConfig& cpu_config, uint32_t passes, const std::string& what) {
  testing::expect_gpu_matches_cpu(scene, cpu_config, passes, what, kAlphaImage);
}

TEST(CudaPt, CornellBoxMatchesCpu) {
  PATHSPACE_REQUIRE_GPU();
  expect_gpu_matches_cpu(make_builtin_scene("cornell-box", 64, 64), testing::default_config("pt", testing::test_seed(1)), 256,
                         "cornell-box pt cuda vs cpu");
}

TEST(CudaPt, CornellGlossyMatchesCpu) {
  PATHSPACE_REQUIRE_GPU();
  expect_gpu_matches_cpu(make_builtin_scene("cornell-glossy", 64, 64), testing::default_config("pt", testing::test_seed(2)), 256,
                         "cornell-glossy pt cuda vs cpu");
}

TEST(CudaPt, LivingRoomMatchesCpu) {
  PATHSPACE_REQUIRE_GPU();
  const std::string path = shared_scenes_dir() + "/bitterli/living-room/scene-v4.pbrt";
  PATHSPACE_REQUIRE_SHARED_DATA(path);
  SceneLoadOptions o;
  o.substitute_missing_textures = true;  // three of its images are not published with it
  o.width = 96, o.height = 54;
  std::vector<std::string> warnings;
  const Scene scene = load_scene(path, o, &warnings);
  expect_gpu_matches_cpu(scene, testing::default_config("pt", testing::test_seed(3)), 256, "living-room pt cuda vs cpu");
}

// With the hashed filter the GPU image is a different estimator only through the filter's inputs:
// both filter their own paths with the same settings, so the filtered images agree in expectation
// too (the filter is a deterministic function of the vertex buffer, tested bit for bit elsewhere).
TEST(CudaPt, FilteredCornellBoxMatchesCpu) {
  PATHSPACE_REQUIRE_GPU();
  RenderConfig config = with_filter(testing::default_config("pt", testing::test_seed(4)), "hashed", HashedFilterSettings{});
  expect_gpu_matches_cpu(make_builtin_scene("cornell-box", 64, 64), config, 256, "cornell-box pt + hashed cuda vs cpu");
}

// Caustic photons traced on the device, indexed by the CPU's grid build (gpu/cuda_caustic_map.h).
TEST(CudaPt, FilteredCornellBoxWithCausticPhotonsMatchesCpu) {
  PATHSPACE_REQUIRE_GPU();
  HashedFilterSettings s;
  s.caustics.photons_per_pixel = 1.0;
  RenderConfig config = with_filter(testing::default_config("pt", testing::test_seed(5)), "hashed", s);
  expect_gpu_matches_cpu(make_builtin_scene("cornell-box", 64, 64), config, 256, "cornell-box pt + hashed + caustic photons cuda vs cpu");
}

// The same with one-bounce photons: two photons per photon path, two grids, gathers at every receiver.
TEST(CudaPt, FilteredCornellBoxWithOneBouncePhotonsMatchesCpu) {
  PATHSPACE_REQUIRE_GPU();
  HashedFilterSettings s;
  s.caustics.photons_per_pixel = 1.0;
  s.caustics.one_bounce = true;
  RenderConfig config = with_filter(testing::default_config("pt", testing::test_seed(6)), "hashed", s);
  expect_gpu_matches_cpu(make_builtin_scene("cornell-box", 64, 64), config, 256,
                         "cornell-box pt + hashed + one-bounce photons cuda vs cpu");
}

TEST(CudaPt, WavefrontEqualsMegakernelBitForBit) {
  PATHSPACE_REQUIRE_GPU();
  testing::expect_pipelines_agree(make_builtin_scene("cornell-glossy", 64, 64), FilterChoice{});
  FilterChoice hashed;
  hashed.name = "hashed";
  testing::expect_pipelines_agree(make_builtin_scene("cornell-box", 64, 64), hashed);
  HashedFilterSettings with_photons;
  with_photons.caustics.photons_per_pixel = 1.0;
  hashed.settings = with_photons;
  testing::expect_pipelines_agree(make_builtin_scene("cornell-box", 64, 64), hashed);
  with_photons.caustics.one_bounce = true;
  hashed.settings = with_photons;
  testing::expect_pipelines_agree(make_builtin_scene("cornell-box", 64, 64), hashed);
}

TEST(CudaDevice, OptionsTheGpuDoesNotRunAreUsageErrors) {
  EXPECT_THROW(check_device("cuda", "bpt", "none"), OptionError);
  EXPECT_THROW(check_device("cuda", "pt", "consistent"), OptionError);
  EXPECT_NO_THROW(check_device("cuda", "pt", "hashed"));
  EXPECT_NO_THROW(check_device("cpu", "bpt", "none"));
  try {
    check_device("cuda", "sppm", "none");
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("there: --integrator pt"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pathspace
