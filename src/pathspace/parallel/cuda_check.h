// Every CUDA runtime call and every kernel launch of the GPU backend is checked: a failure throws
// pathspace::Error naming the call, the source line and CUDA's own message, so a bad launch or an
// out-of-memory never goes on to produce a silently wrong image. Only .cu files and CUDA-built
// .cpp files include this (it needs the CUDA runtime headers).
#pragma once

#include <cuda_runtime_api.h>

#include <string>

#include "pathspace/base/error.h"

namespace pathspace::gpu {

[[noreturn]] inline void throw_cuda_error(cudaError_t error, const char* call, const char* file, int line) {
  throw Error(std::string("CUDA error in ") + call + " (" + file + ":" + std::to_string(line) + "): " + cudaGetErrorName(error) +
              ": " + cudaGetErrorString(error));
}

inline void check_cuda(cudaError_t error, const char* call, const char* file, int line) {
  if (error != cudaSuccess) throw_cuda_error(error, call, file, line);
}

}  // namespace pathspace::gpu

// PS_CUDA_CHECK(cudaMemcpy(...)); after a launch: PS_CUDA_CHECK_LAUNCH("kernel name").
#define PS_CUDA_CHECK(call) ::pathspace::gpu::check_cuda((call), #call, __FILE__, __LINE__)
#define PS_CUDA_CHECK_LAUNCH(name) ::pathspace::gpu::check_cuda(cudaGetLastError(), "launch of " name, __FILE__, __LINE__)
