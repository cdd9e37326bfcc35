// DeviceVertexBuffer: a VertexBuffer in device memory, one DeviceBuffer per field (structure of
// arrays, as on the host: a warp's loads of one field are coalesced). A CUDA path tracer fills it
// through view().store(...) (the same device-safe code as VertexBuffer::store) and hands view() to
// CudaHashedFilter; upload/download copy a host buffer for tests and benchmarks.
#pragma once

#include <cstddef>
#include <cstdint>

#include "pathspace/filters/vertex_buffer.h"
#include "pathspace/parallel/device_buffer.h"

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
  // Calls f(device field, host vector, per_path) for every field of filters/vertex_fields.h.
  template <typename Self, typename Host, typename F>
  static void for_each_field(Self& d, Host& h, F&& f);

  size_t paths_ = 0;
  int records_per_path_ = 0;
  // One device array per field of filters/vertex_fields.h, named as the host's with a trailing _.
#define PATHSPACE_DEVICE_PATH_FIELD(T, name, what) DeviceBuffer<T> name##_;
#define PATHSPACE_DEVICE_SLOT_FIELD(T, name, member, what) DeviceBuffer<T> name##_;
  PATHSPACE_VERTEX_PATH_FIELDS(PATHSPACE_DEVICE_PATH_FIELD)
  PATHSPACE_VERTEX_SLOT_FIELDS(PATHSPACE_DEVICE_SLOT_FIELD)
#undef PATHSPACE_DEVICE_PATH_FIELD
#undef PATHSPACE_DEVICE_SLOT_FIELD
};

}  // namespace pathspace::gpu
