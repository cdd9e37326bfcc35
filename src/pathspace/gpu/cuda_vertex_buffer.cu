#include "pathspace/gpu/cuda_vertex_buffer.h"

namespace pathspace::gpu {

template <typename Self, typename Host, typename F>
void DeviceVertexBuffer::for_each_field(Self& d, Host& h, F&& f) {
  f(d.prefix_, h.prefix, true);
  f(d.pixel_, h.pixel, true);
  f(d.count_, h.count, true);
  f(d.position_, h.position, false);
  f(d.geometric_normal_, h.geometric_normal, false);
  f(d.shading_normal_, h.shading_normal, false);
  f(d.incident_, h.incident, false);
  f(d.previous_position_, h.previous_position, false);
  f(d.prefix_distance_, h.prefix_distance, false);
  f(d.roughness_, h.roughness, false);
  f(d.throughput_, h.throughput, false);
  f(d.contribution_, h.contribution, false);
  f(d.layer_, h.layer, false);
  f(d.segments_, h.segments, false);
  f(d.selected_, h.selected, false);
  f(d.visible_lights_, h.visible_lights, false);
  f(d.open_distance_, h.open_distance, false);
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
  v.prefix = prefix_.data();
  v.pixel = pixel_.data();
  v.count = count_.data();
  v.position = position_.data();
  v.geometric_normal = geometric_normal_.data();
  v.shading_normal = shading_normal_.data();
  v.incident = incident_.data();
  v.previous_position = previous_position_.data();
  v.prefix_distance = prefix_distance_.data();
  v.roughness = roughness_.data();
  v.throughput = throughput_.data();
  v.contribution = contribution_.data();
  v.layer = layer_.data();
  v.segments = segments_.data();
  v.selected = selected_.data();
  v.visible_lights = visible_lights_.data();
  v.open_distance = open_distance_.data();
  return v;
}

}  // namespace pathspace::gpu
