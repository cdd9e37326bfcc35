#include "pathspace/filters/vertex_buffer.h"

#include <numeric>

namespace pathspace {

int records_per_path(const VertexSelection& s) {
  if (s.mode == VertexSelectionMode::none) return 0;
  const int vertices = s.mode == VertexSelectionMode::all ? min_int(s.max_vertices, kMaxSelectedVertices) : 1;
  return vertices * (s.split_layers ? kMaxBsdfLayers : 1);
}

void VertexBuffer::resize(size_t paths, int records_per_path) {
  if (records_per_path != records_per_path_) {
    *this = VertexBuffer();
    records_per_path_ = records_per_path;
  }
  const size_t slots = paths * size_t(records_per_path);
  prefix.resize(paths);
  pixel.resize(paths);
  count.assign(paths, 0);
  for (auto* v : {&position, &geometric_normal, &shading_normal, &incident, &previous_position}) v->resize(slots);
  for (auto* v : {&prefix_distance, &roughness, &open_distance}) v->resize(slots);
  for (auto* v : {&throughput, &contribution}) v->resize(slots);
  for (auto* v : {&layer, &segments, &selected}) v->resize(slots);
  visible_lights.resize(slots);
}

size_t VertexBuffer::bytes_per_path() { return sizeof(Rgb) + sizeof(uint32_t) + sizeof(uint8_t); }
size_t VertexBuffer::bytes_per_slot() {
  return 5 * sizeof(Vec3) + 3 * sizeof(float) + 2 * sizeof(Rgb) + 3 * sizeof(uint8_t) + sizeof(uint32_t);
}

size_t VertexBuffer::total_records() const { return std::accumulate(count.begin(), count.end(), size_t(0)); }

VertexBufferView VertexBuffer::view() {
  VertexBufferView v;
  v.paths = paths();
  v.records_per_path = records_per_path_;
  v.prefix = prefix.data();
  v.pixel = pixel.data();
  v.count = count.data();
  v.position = position.data();
  v.geometric_normal = geometric_normal.data();
  v.shading_normal = shading_normal.data();
  v.incident = incident.data();
  v.previous_position = previous_position.data();
  v.prefix_distance = prefix_distance.data();
  v.roughness = roughness.data();
  v.throughput = throughput.data();
  v.contribution = contribution.data();
  v.layer = layer.data();
  v.segments = segments.data();
  v.selected = selected.data();
  v.visible_lights = visible_lights.data();
  v.open_distance = open_distance.data();
  return v;
}

FilterVertex VertexBuffer::record(size_t i) const {
  FilterVertex v;
  v.p = position[i];
  v.ng = geometric_normal[i];
  v.ns = shading_normal[i];
  v.wo = incident[i];
  v.prev_p = previous_position[i];
  v.prefix_distance = prefix_distance[i];
  v.roughness = roughness[i];
  v.throughput = throughput[i];
  v.contribution = contribution[i];
  v.layer = layer[i];
  v.segments = segments[i];
  v.selected = selected[i];
  v.visible_lights = visible_lights[i];
  v.open_distance = open_distance[i];
  return v;
}

}  // namespace pathspace
