// What the CUDA backend can use on this machine: whether this build has it (PATHSPACE_CUDA with
// nvcc found) and which GPU the CUDA runtime sees. `pathspace info` prints it; `--device cuda`
// asks it before creating anything on the device.
#pragma once

#include <string>

namespace pathspace::gpu {

struct GpuInfo {
  bool built = false;        // the CUDA backend was compiled into this binary
  bool available = false;    // built, and a usable device is present
  std::string reason;        // why not available ("no CUDA device", the driver's message, ...)
  std::string name;          // device 0
  int compute_major = 0, compute_minor = 0;
  int multiprocessors = 0;
  size_t memory_bytes = 0;
  int driver_version = 0, runtime_version = 0;  // CUDA's encoding: 1000 * major + 10 * minor

  // "NVIDIA H100 80GB HBM3 (sm_90, 132 SMs, 79.6 GiB; driver CUDA 13.0, runtime 13.0)" or the reason.
  std::string describe() const;
};

// Queried once per process (the CUDA runtime's first call costs tens of milliseconds).
const GpuInfo& gpu_info();

// Throws pathspace::Error ("no CUDA device: ...") unless the backend is built and a device is there.
void require_gpu();

}  // namespace pathspace::gpu
