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
  // What the visibility weight compares (Keller et al. 2014, sec. 2.1), recorded only when a filter
  // asks for it (VisibilityProbes): bit k is set when the k-th delta light of the probe list is
  // unoccluded from p; open_distance is the length of one ray along ns (infinite when it escapes).
  uint32_t visible_lights = 0;
  float open_distance = 0.f;
};

// The extra rays a selected vertex traces for the visibility weight: one shadow ray to each listed
// delta light (point, spot, directional; at most 32), and one ray along the shading normal when the
// scene has area or environment lights ("comparing the lengths of each one ray shot into the
// hemisphere", sec. 2.1). The ray along ns is the same for all neighbours with similar normals, so
// the lengths compare the vertices' surroundings, not the noise of random directions.
inline constexpr int kMaxVisibilityLights = 32;
struct VisibilityProbes {
  const uint32_t* delta_lights = nullptr;
  int delta_count = 0;
  bool open_ray = false;
  PS_HD bool any() const { return delta_count > 0 || open_ray; }
};

// Room for two selected vertices in each of four camera-side branches (two splits), or for the
// most vertices one path may select.
inline constexpr int kMaxPathRecords = 2 * kMaxSelectedVertices * kMaxBsdfLayers;

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
