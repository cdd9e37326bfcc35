#include "pathspace/filters/cuda_vertex_buffer.h"

namespace pathspace::gpu {

template <typename Self, typename Host, typename F>
void DeviceVertexBuffer::for_each_field(Self& d, Host& h, F&& f) {
#define PATHSPACE_EACH_PATH_FIELD(T, name, what) f(d.name##_, h.name, true);
#define PATHSPACE_EACH_SLOT_FIELD(T, name, member, what) f(d.name##_, h.name, false);
  PATHSPACE_VERTEX_PATH_FIELDS(PATHSPACE_EACH_PATH_FIELD)
  PATHSPACE_VERTEX_SLOT_FIELDS(PATHSPACE_EACH_SLOT_FIELD)
#undef PATHSPACE_EACH_PATH_FIELD
#undef PATHSPACE_EACH_SLOT_FIELD
}

void DeviceVertexBuffer::resize(size_t paths, int records_per_path) {
  if (records_per_path < 0) throw Error("DeviceVertexBuffer::resize: negative records per path");
  paths_ = paths;
  records_per_path_ = records_per_path;
  const size_t slots = paths * size_t(records_per_path);
  VertexBuffer none;  // only for the field list
  for_each_field(*this, none, [&](auto& d, auto&, bool per_path) { d.resize(per_path ? paths : slots); });
}

void DeviceVertexBuffer::upload(const VertexBuffer& host) {
  resize(host.paths(), host.records_per_path());
  for_each_field(*this, host, [&](auto& d, const auto& h, bool) { d.upload(h.data(), h.size()); });
}

void DeviceVertexBuffer::download(VertexBuffer* host) const {
  host->resize(paths_, records_per_path_);
  for_each_field(*this, *host, [&](auto& d, auto& h, bool) { d.download(h.data(), h.size()); });
}

size_t DeviceVertexBuffer::bytes() const {
  return paths_ * VertexBuffer::bytes_per_path() + paths_ * size_t(records_per_path_) * VertexBuffer::bytes_per_slot();
}

VertexBufferView DeviceVertexBuffer::view() {
  VertexBufferView v;
  v.paths = paths_;
  v.records_per_path = records_per_path_;
#define PATHSPACE_VIEW_OF_PATH_FIELD(T, name, what) v.name = name##_.data();
#define PATHSPACE_VIEW_OF_SLOT_FIELD(T, name, member, what) v.name = name##_.data();
  PATHSPACE_VERTEX_PATH_FIELDS(PATHSPACE_VIEW_OF_PATH_FIELD)
  PATHSPACE_VERTEX_SLOT_FIELDS(PATHSPACE_VIEW_OF_SLOT_FIELD)
#undef PATHSPACE_VIEW_OF_PATH_FIELD
#undef PATHSPACE_VIEW_OF_SLOT_FIELD
  return v;
}

}  // namespace pathspace::gpu
