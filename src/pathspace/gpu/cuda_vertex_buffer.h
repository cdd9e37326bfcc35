// DeviceVertexBuffer: a VertexBuffer in device memory, one DeviceBuffer per field (structure of
// arrays, as on the host: a warp's loads of one field are coalesced). A CUDA path tracer fills it
// through view().store(...) (the same device-safe code as VertexBuffer::store) and hands view() to
// CudaHashedFilter; upload/download copy a host buffer for tests and benchmarks.
#pragma once

#include <cstddef>
#include <cstdint>

#include "pathspace/filters/vertex_buffer.h"
#include "pathspace/gpu/device_buffer.h"

namespace pathspace::gpu {

class DeviceVertexBuffer {
 public:
  DeviceVertexBuffer() = default;
  // Contents are undefined after a resize that changes the layout; count must be written for every
  // path before the buffer is read (store() does).
  void resize(size_t paths, int records_per_path);
  void upload(const VertexBuffer& host);
  // Resizes *host to this buffer's layout and copies every field.
  void download(VertexBuffer* host) const;
  VertexBufferView view();

  size_t paths() const { return paths_; }
  int records_per_path() const { return records_per_path_; }
  size_t bytes() const;

 private:
  // Calls f(device field, host vector, per_path) for every field: one list, so that resize, upload
  // and download cannot miss one.
  template <typename Self, typename Host, typename F>
  static void for_each_field(Self& d, Host& h, F&& f);

  size_t paths_ = 0;
  int records_per_path_ = 0;
  DeviceBuffer<Rgb> prefix_;
  DeviceBuffer<uint32_t> pixel_;
  DeviceBuffer<uint8_t> count_;
  DeviceBuffer<Vec3> position_, geometric_normal_, shading_normal_, incident_, previous_position_;
  DeviceBuffer<float> prefix_distance_, roughness_;
  DeviceBuffer<Rgb> throughput_, contribution_;
  DeviceBuffer<uint8_t> layer_, segments_, selected_;
  DeviceBuffer<uint32_t> visible_lights_;
  DeviceBuffer<float> open_distance_;
};

}  // namespace pathspace::gpu
