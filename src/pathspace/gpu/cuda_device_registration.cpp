// `--device cuda`: registered in every build, so that asking for it without a CUDA build or without a
// GPU is a clear error ("no CUDA device", exit 1) rather than an unknown option.
#include "pathspace/gpu/gpu_info.h"
#include "pathspace/integrators/device_registry.h"
#include "pathspace/integrators/pt/pt_settings.h"

#if PATHSPACE_HAS_CUDA
#include "pathspace/gpu/cuda_pt_integrator.h"
#endif

namespace pathspace::gpu {

namespace {

std::unique_ptr<Integrator> create_on_gpu(const IntegratorContext& context, const std::string& integrator, const std::any& settings) {
  require_gpu();
#if PATHSPACE_HAS_CUDA
  if (integrator == "pt") return make_cuda_pt_integrator(context, settings_cast<PtSettings>(settings, integrator));
#endif
  throw Error("--device cuda does not run --integrator " + integrator);  // check_device rules this out first
}

// Media: PT's megakernel traces them with the CPU's device functions (docs/media.md).
const DeviceRegistrar kRegistrar{DeviceEntry{"cuda", "an NVIDIA GPU through CUDA (device 0; 'pathspace info' names it)", {"pt"}, {"hashed"},
                                             create_on_gpu, true}};

}  // namespace

}  // namespace pathspace::gpu
