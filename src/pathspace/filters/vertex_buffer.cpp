#include "pathspace/filters/vertex_buffer.h"

#include <numeric>

namespace pathspace {

int records_per_path(const VertexSelection& s) {
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

void VertexBuffer::store(size_t path, uint32_t pixel_index, const PathSample& s) {
  prefix[path] = s.prefix;
  pixel[path] = pixel_index;
  const int n = min_int(s.count, records_per_path_);
  count[path] = uint8_t(n);
  for (int r = 0; r < n; ++r) {
    const FilterVertex& v = s.records[r];
    const size_t i = slot(path, r);
    position[i] = v.p;
    geometric_normal[i] = v.ng;
    shading_normal[i] = v.ns;
    incident[i] = v.wo;
    previous_position[i] = v.prev_p;
    prefix_distance[i] = v.prefix_distance;
    roughness[i] = v.roughness;
    throughput[i] = v.throughput;
    contribution[i] = v.contribution;
    layer[i] = v.layer;
    segments[i] = v.segments;
    selected[i] = v.selected;
    visible_lights[i] = v.visible_lights;
    open_distance[i] = v.open_distance;
  }
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
