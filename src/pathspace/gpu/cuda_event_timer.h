// Device-time laps measured with CUDA events on the default stream: start(), then lap(&sum) after
// each stage adds the stage's milliseconds to sum. Each lap waits for its event, so stages are timed
// as the device ran them, without host-side launch latency hiding or inflating them.
#pragma once

#include <cuda_runtime_api.h>

#include "pathspace/parallel/cuda_check.h"

namespace pathspace::gpu {

class CudaEventTimer {
 public:
  CudaEventTimer() {
    PS_CUDA_CHECK(cudaEventCreate(&previous_));
    PS_CUDA_CHECK(cudaEventCreate(&now_));
  }
  ~CudaEventTimer() {
    cudaEventDestroy(previous_);
    cudaEventDestroy(now_);
  }
  CudaEventTimer(const CudaEventTimer&) = delete;
  CudaEventTimer& operator=(const CudaEventTimer&) = delete;

  void start(cudaStream_t stream = 0) {
    stream_ = stream;
    PS_CUDA_CHECK(cudaEventRecord(previous_, stream_));
  }
  // Milliseconds since start() or the previous lap.
  double lap() {
    PS_CUDA_CHECK(cudaEventRecord(now_, stream_));
    PS_CUDA_CHECK(cudaEventSynchronize(now_));
    float ms = 0.f;
    PS_CUDA_CHECK(cudaEventElapsedTime(&ms, previous_, now_));
    cudaEvent_t t = previous_;
    previous_ = now_;
    now_ = t;
    return double(ms);
  }
  // The same, added to *sum_ms.
  double lap(double* sum_ms) {
    const double ms = lap();
    *sum_ms += ms;
    return ms;
  }

 private:
  cudaEvent_t previous_ = nullptr, now_ = nullptr;
  cudaStream_t stream_ = 0;
};

}  // namespace pathspace::gpu
