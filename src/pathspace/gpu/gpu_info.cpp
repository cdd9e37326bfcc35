#include "pathspace/gpu/gpu_info.h"

#include <cstdio>

#include "pathspace/base/error.h"

#if PATHSPACE_HAS_CUDA
#include <cuda_runtime_api.h>
#endif

namespace pathspace::gpu {

namespace {

std::string cuda_version(int v) { return std::to_string(v / 1000) + "." + std::to_string((v % 1000) / 10); }

GpuInfo query() {
  GpuInfo info;
#if PATHSPACE_HAS_CUDA
  info.built = true;
  cudaRuntimeGetVersion(&info.runtime_version);
  cudaDriverGetVersion(&info.driver_version);  // 0 when no driver is installed
  int count = 0;
  const cudaError_t e = cudaGetDeviceCount(&count);
  if (e != cudaSuccess || count == 0) {
    // Without a driver the runtime reports an "insufficient" driver: say what is missing instead.
    const std::string why = info.driver_version == 0 ? "no NVIDIA driver" : e != cudaSuccess ? cudaGetErrorString(e) : "";
    info.reason = why.empty() ? "no CUDA device" : "no CUDA device (" + why + ")";
    cudaGetLastError();  // clear the sticky error of the failed query
    return info;
  }
  cudaDeviceProp p{};
  if (cudaGetDeviceProperties(&p, 0) != cudaSuccess) {
    info.reason = "no CUDA device (its properties could not be read)";
    return info;
  }
  info.available = true;
  info.name = p.name;
  info.compute_major = p.major;
  info.compute_minor = p.minor;
  info.multiprocessors = p.multiProcessorCount;
  info.memory_bytes = p.totalGlobalMem;
#else
  info.reason = "no CUDA device: this build has no CUDA backend (configure with nvcc installed and PATHSPACE_CUDA=ON)";
#endif
  return info;
}

}  // namespace

std::string GpuInfo::describe() const {
  if (!available) return reason;
  char memory[32];
  std::snprintf(memory, sizeof memory, "%.1f GiB", double(memory_bytes) / double(1ull << 30));
  return name + " (sm_" + std::to_string(compute_major) + std::to_string(compute_minor) + ", " + std::to_string(multiprocessors) +
         " SMs, " + memory + "; driver CUDA " + cuda_version(driver_version) + ", runtime " + cuda_version(runtime_version) + ")";
}

const GpuInfo& gpu_info() {
  static const GpuInfo info = query();
  return info;
}

void require_gpu() {
  const GpuInfo& info = gpu_info();
  if (!info.available) throw Error("--device cuda: " + info.reason);
}

}  // namespace pathspace::gpu
