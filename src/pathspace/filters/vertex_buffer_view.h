// VertexBufferView: raw pointers to the arrays of a VertexBuffer (host) or of a DeviceVertexBuffer
// (gpu/cuda_vertex_buffer.h), so that the same PS_HD code stores and reads the selected vertices of
// a pass on the CPU and on the GPU (Binder et al. 2021, sec. 3: the first phase stores the vertices,
// the filter reads them). Field names are VertexBuffer's. Path p owns the record slots
// [p * records_per_path, p * records_per_path + count[p]).
#pragma once

#include <cstddef>
#include <cstdint>

#include "pathspace/filters/path_sample.h"

namespace pathspace {

struct VertexBufferView {
  size_t paths = 0;
  int records_per_path = 0;
  // Per path.
  Rgb* prefix = nullptr;
  uint32_t* pixel = nullptr;
  uint8_t* count = nullptr;
  // Per record slot.
  Vec3 *position = nullptr, *geometric_normal = nullptr, *shading_normal = nullptr, *incident = nullptr,
       *previous_position = nullptr;
  float *prefix_distance = nullptr, *roughness = nullptr;
  Rgb *throughput = nullptr, *contribution = nullptr;
  uint8_t *layer = nullptr, *segments = nullptr, *selected = nullptr;
  uint32_t* visible_lights = nullptr;
  float* open_distance = nullptr;

  PS_HD size_t slots() const { return paths * size_t(records_per_path); }
  PS_HD size_t slot(size_t path, int record) const { return path * size_t(records_per_path) + size_t(record); }

  // Stores one path's sample (drops records beyond records_per_path; the caller sizes it right).
  PS_HD void store(size_t path, uint32_t pixel_index, const PathSample& s) const {
    prefix[path] = s.prefix;
    pixel[path] = pixel_index;
    const int n = min_int(s.count, records_per_path);
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
};

}  // namespace pathspace
