#include "pathspace/filters/vertex_buffer.h"

#include <numeric>

namespace pathspace {

int records_per_path(const VertexSelection& s) {
  const int vertices = s.mode == VertexSelectionMode::all ? min_int(s.max_vertices, kMaxSelectedVertices) : 1;
  return vertices * (s.split_layers ? kMaxBsdfLayers : 1);
}

void VertexBuffer::resize(size_t paths, int records_per_path) {
  records_per_path_ = records_per_path;
  const size_t slots = paths * size_t(records_per_path);
  prefix.assign(paths, Rgb());
  pixel.assign(paths, 0);
  count.assign(paths, 0);
  for (auto* v : {&position, &geometric_normal, &shading_normal, &incident, &previous_position}) v->assign(slots, Vec3());
  for (auto* v : {&prefix_distance, &roughness}) v->assign(slots, 0.f);
  for (auto* v : {&throughput, &contribution}) v->assign(slots, Rgb());
  for (auto* v : {&layer, &segments, &selected}) v->assign(slots, 0);
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
  return v;
}

}  // namespace pathspace
