// Path tracing on an NVIDIA GPU (`--device cuda --integrator pt`, optionally `--filter hashed`).
// Each pass: one CUDA thread per pixel traces its path with the same device function the CPU runs
// (integrators/pt/pt_kernel.h) over the project's own BVH (accel/bvh_tracer.h, built on the host
// with Embree's builder), with the CPU's sampler, so the GPU image is the same estimator. With the
// hashed filter the paths' selected vertices go to a device vertex buffer, the GPU filter
// (cuda_hashed_filter.h) averages them, and a resolve kernel forms the pixels. The pass image is
// then copied to the host film. CUDA builds only.
#pragma once

#include <memory>

#include "pathspace/integrators/integrator.h"
#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/integrators/pt/pt_settings.h"

namespace pathspace::gpu {

// Throws pathspace::Error when no CUDA device is present, OptionError for settings the GPU does not
// run (the filter's --temporal or --aov, say).
std::unique_ptr<Integrator> make_cuda_pt_integrator(const IntegratorContext& context, const PtSettings& settings);

}  // namespace pathspace::gpu
