// Path tracing on the GPU (--device cuda) against the CPU: the same estimator, so the images agree
// by the per-pixel z-test of the integrator consistency tests (alpha_pixel 1e-3; an image fails when
// its count of failing pixels is improbable at alpha = 0.01, Sidak-corrected over this file's
// comparisons). Skipped, with the reason printed, where no CUDA device is present.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <string>

#include "pathspace/accel/accel.h"
#include "pathspace/film/film.h"
#include "pathspace/gpu/cuda_pt_integrator.h"
#include "pathspace/gpu/gpu_info.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/scene/builtin_scenes.h"
#include "support/integrator_comparison.h"
#include "support/shared_data.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

constexpr int kComparisons = 4;
const double kAlphaImage = testing::sidak(0.01, kComparisons);

#define PATHSPACE_REQUIRE_GPU()                                                   \
  do {                                                                            \
    if (!gpu::gpu_info().available) GTEST_SKIP() << gpu::gpu_info().reason;       \
  } while (0)

// The shared scenes' folder: PATHSPACE_SHARED_SCENES_DIR in the environment (a GPU machine with a
// copy elsewhere) or the build's.
std::string shared_scenes_dir() {
  const char* v = std::getenv("PATHSPACE_SHARED_SCENES_DIR");
  return v && *v ? std::string(v) : std::string(PATHSPACE_SHARED_SCENES_DIR);
}

void expect_gpu_matches_cpu(const Scene& scene, const RenderConfig& cpu_config, uint32_t passes, const std::string& what) {
  RenderConfig gpu_config = cpu_config;
  gpu_config.device = "cuda";
  gpu_config.seed = cpu_config.seed + 1000;  // independent samples: the z-test assumes them
  const testing::Rendered gpu_image = testing::render_integrator(scene, gpu_config, passes);
  const testing::Rendered cpu_image = testing::render_integrator(scene, cpu_config, passes);
  testing::expect_same_image(gpu_image, cpu_image, what, kAlphaImage, "cuda", "cpu");
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

// The wavefront and the megakernel run the same steps in the same order per path: equal images.
void expect_pipelines_agree(const Scene& scene, const FilterChoice& filter) {
  const Accel accel(scene);
  const IntegratorContext context{scene, accel, 5, filter};
  auto mega = gpu::make_cuda_pt_integrator(context, PtSettings{}, gpu::CudaPtPipeline::megakernel);
  auto wave = gpu::make_cuda_pt_integrator(context, PtSettings{}, gpu::CudaPtPipeline::wavefront);
  Film a(scene.camera.width, scene.camera.height), b(scene.camera.width, scene.camera.height);
  PathCounters ca, cb;
  for (uint32_t pass = 0; pass < 4; ++pass) {
    mega->render_pass(pass, a, ca);
    wave->render_pass(pass, b, cb);
  }
  EXPECT_EQ(ca.rays, cb.rays);
  EXPECT_EQ(ca.shadow_rays, cb.shadow_rays);
  const Image ma = a.mean(), mb = b.mean();
  size_t differing = 0;
  for (size_t i = 0; i < ma.size(); ++i) differing += std::memcmp(&ma.pixels[i], &mb.pixels[i], sizeof(Rgb)) != 0;
  EXPECT_EQ(differing, 0u) << "of " << ma.size() << " pixels";
}

TEST(CudaPt, WavefrontEqualsMegakernelBitForBit) {
  PATHSPACE_REQUIRE_GPU();
  expect_pipelines_agree(make_builtin_scene("cornell-glossy", 64, 64), FilterChoice{});
  FilterChoice hashed;
  hashed.name = "hashed";
  expect_pipelines_agree(make_builtin_scene("cornell-box", 64, 64), hashed);
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
