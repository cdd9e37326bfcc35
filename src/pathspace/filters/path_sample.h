// The result of one camera path, split at its selected vertices (Binder et al. 2021, sec. 3):
//   pixel value = prefix + sum_i throughput_i * contribution_i
// `prefix` is what the path gathered before its first selected vertex (emission seen directly,
// specular chains); each record is one selected vertex and material layer, with the demodulated
// contribution L_i f_i cos (eq. 9) that a filter may replace by a voxel average.
#pragma once

#include <cstdint>

#include "pathspace/filters/vertex_selection.h"
#include "pathspace/materials/bsdf_layers.h"

namespace pathspace {

struct FilterVertex {
  Vec3 p;             // position
  Vec3 ng, ns;        // geometric and shading normal (ns faces the side the path arrived from)
  Vec3 wo;            // unit direction towards the previous vertex (world)
  Vec3 prev_p;        // previous vertex (the camera for a primary hit), for the level of detail
  float prefix_distance = 0.f;  // path length from the camera to prev_p
  Rgb throughput;     // camera to vertex, times the layer albedo
  Rgb contribution;   // L_i f_i cos / albedo: the quantity averaged by the filter
  float roughness = 1.f;
  uint8_t layer = 0;     // BsdfLayerId
  uint8_t segments = 0;  // camera path length to this vertex
  uint8_t selected = 0;  // 0 for the first selected vertex of the path, 1 for the next, ...
};

inline constexpr int kMaxPathRecords = kMaxSelectedVertices * kMaxBsdfLayers;

struct PathSample {
  Rgb prefix;
  int count = 0;
  FilterVertex records[kMaxPathRecords];

  // The unfiltered estimate; the same arithmetic a filter's resolve uses with contribution unchanged.
  PS_HD Rgb value() const {
    Rgb v = prefix;
    for (int i = 0; i < count; ++i) v += records[i].throughput * records[i].contribution;
    return v;
  }
};

}  // namespace pathspace
