// DeviceBuffer<T>: n elements of device memory owned by one object (plain cudaMalloc, never managed
// memory: the GPU backend's data is copied explicitly, so no page faults hide in the timings).
// Move-only; the memory goes back with the object. Uploads and downloads are checked and sized.
#pragma once

#include <cuda_runtime_api.h>

#include <cstddef>
#include <utility>
#include <vector>

#include "pathspace/parallel/cuda_check.h"

namespace pathspace::gpu {

template <typename T>
class DeviceBuffer {
 public:
  DeviceBuffer() = default;
  explicit DeviceBuffer(size_t n) { resize(n); }
  explicit DeviceBuffer(const std::vector<T>& host) { upload(host); }
  ~DeviceBuffer() { release(); }
  DeviceBuffer(const DeviceBuffer&) = delete;
  DeviceBuffer& operator=(const DeviceBuffer&) = delete;
  DeviceBuffer(DeviceBuffer&& o) noexcept : data_(std::exchange(o.data_, nullptr)), size_(std::exchange(o.size_, 0)) {}
  DeviceBuffer& operator=(DeviceBuffer&& o) noexcept {
    if (this != &o) {
      release();
      data_ = std::exchange(o.data_, nullptr);
      size_ = std::exchange(o.size_, 0);
    }
    return *this;
  }

  // Contents are undefined after a resize that changes the size (no copy: buffers are refilled).
  void resize(size_t n) {
    if (n == size_) return;
    release();
    if (n > 0) PS_CUDA_CHECK(cudaMalloc(reinterpret_cast<void**>(&data_), n * sizeof(T)));
    size_ = n;
  }
  void upload(const T* host, size_t n) {
    resize(n);
    if (n > 0) PS_CUDA_CHECK(cudaMemcpy(data_, host, n * sizeof(T), cudaMemcpyHostToDevice));
  }
  void upload(const std::vector<T>& host) { upload(host.data(), host.size()); }
  void download(T* host, size_t n) const {
    if (n > size_) throw Error("DeviceBuffer::download: more elements asked for than the buffer holds");
    if (n > 0) PS_CUDA_CHECK(cudaMemcpy(host, data_, n * sizeof(T), cudaMemcpyDeviceToHost));
  }
  std::vector<T> download() const {
    std::vector<T> out(size_);
    download(out.data(), size_);
    return out;
  }
  void fill_bytes(int byte) {
    if (size_ > 0) PS_CUDA_CHECK(cudaMemset(data_, byte, size_ * sizeof(T)));
  }

  T* data() { return data_; }
  const T* data() const { return data_; }
  size_t size() const { return size_; }
  size_t bytes() const { return size_ * sizeof(T); }

 private:
  void release() noexcept {
    if (data_) cudaFree(data_);  // an error here (a dead context) cannot be reported from a destructor
    data_ = nullptr;
    size_ = 0;
  }
  T* data_ = nullptr;
  size_t size_ = 0;
};

}  // namespace pathspace::gpu
