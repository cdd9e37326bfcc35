// What the CUDA tests share: skipping where no GPU is present, the GPU-against-CPU image test, and
// the test that the wavefront and the megakernel give the same image.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "pathspace/accel/accel.h"
#include "pathspace/film/film.h"
#include "pathspace/gpu/cuda_pt_integrator.h"
#include "pathspace/gpu/gpu_info.h"
#include "pathspace/gpu/wavefront_stages.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "support/integrator_comparison.h"

// Skips the test, printing why, where no CUDA device is present (CI, and any machine without a GPU).
#define PATHSPACE_REQUIRE_GPU()                                              \
  do {                                                                       \
    const ::pathspace::gpu::GpuInfo& gpu_info = ::pathspace::gpu::gpu_info(); \
    if (!gpu_info.available) {                                               \
      std::printf("no GPU: %s\n", gpu_info.reason.c_str());                  \
      GTEST_SKIP() << "no CUDA device: " << gpu_info.reason;                 \
    }                                                                        \
  } while (0)

namespace pathspace::testing {

// The GPU (--device cuda) and the CPU render the same estimator, so their images agree by the
// per-pixel z-test of the integrator consistency tests; the GPU gets an independent seed, as the
// z-test assumes. alpha_image: the image's level (the caller's Sidak correction over its file).
inline void expect_gpu_matches_cpu(const Scene& scene, const RenderConfig& cpu_config, uint32_t passes,
                                   const std::string& what, double alpha_image) {
  RenderConfig gpu_config = cpu_config;
  gpu_config.device = "cuda";
  gpu_config.seed = cpu_config.seed + 1000;
  const Rendered gpu_image = render_integrator(scene, gpu_config, passes);
  const Rendered cpu_image = render_integrator(scene, cpu_config, passes);
  expect_same_image(gpu_image, cpu_image, what, alpha_image, "cuda", "cpu");
}

// The wavefront and the megakernel run the same steps in the same order per path: equal images.
inline void expect_pipelines_agree(const Scene& scene, const FilterChoice& filter) {
  const Accel accel(scene);
  const IntegratorContext context{scene, accel, 5, filter};
  const PtSettings settings = without_camera_branches(PtSettings{});
  auto mega = gpu::make_cuda_pt_integrator(context, settings, gpu::CudaPtPipeline::megakernel);
  auto wave = gpu::make_cuda_pt_integrator(context, settings, gpu::CudaPtPipeline::wavefront);
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

}  // namespace pathspace::testing
