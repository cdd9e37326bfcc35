// Path tracing on an NVIDIA GPU (`--device cuda --integrator pt`, optionally `--filter hashed`).
// Each pass traces every pixel's path with the same device functions the CPU runs
// (integrators/pt/pt_kernel.h), stage by stage (wavefront) or one thread per path, over the
// project's own BVH (accel/bvh_tracer.h, built on the host with Embree's builder), with the CPU's
// sampler, so the GPU image is the same estimator. With the
// hashed filter the paths' selected vertices go to a device vertex buffer, the GPU filter
// (cuda_hashed_filter.h) averages them, and a resolve kernel forms the pixels. The pass image is
// then copied to the host film. CUDA builds only.
#pragma once

#include <memory>

#include "pathspace/integrators/integrator.h"
#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/integrators/pt/pt_settings.h"

namespace pathspace::gpu {

// How the paths of a pass are traced: one thread per path through its whole length (a megakernel,
// the default), or stage by stage over queues of paths (wavefront, cuda_wavefront_pt.h). The two
// give the same image bit for bit. On an H100 at 1920x1080 the wavefront is 2-3x slower as built
// (docs/gpu.md: its kilobyte path states are read and written with a kilobyte stride per stage).
enum class CudaPtPipeline { megakernel, wavefront };

// Throws pathspace::Error when no CUDA device is present, OptionError for settings the GPU does not
// run (the filter's --temporal or --aov, say).
std::unique_ptr<Integrator> make_cuda_pt_integrator(const IntegratorContext& context, const PtSettings& settings,
                                                    CudaPtPipeline pipeline = CudaPtPipeline::megakernel);

}  // namespace pathspace::gpu
