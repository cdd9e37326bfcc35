// The fields of a pass's selected vertices, listed once (Binder et al. 2021, sec. 3: the first
// phase stores what the filter needs). Every place that holds or moves them is generated from these
// two lists: VertexBuffer's vectors, VertexBufferView's pointers, DeviceVertexBuffer's device
// arrays, resize, store/record, and the vertex buffer file (whose arrays follow this order, so
// adding a field means adding one line here and a version step in vertex_buffer_file.cpp).
//
// PATHSPACE_VERTEX_PATH_FIELDS(X): one element per path, X(type, name, description).
// PATHSPACE_VERTEX_SLOT_FIELDS(X): one element per record slot,
//   X(type, name, FilterVertex member, description).
#pragma once

#define PATHSPACE_VERTEX_PATH_FIELDS(X) \
  X(Rgb, prefix, "prefix")              \
  X(uint32_t, pixel, "pixel")           \
  X(uint8_t, count, "count")

#define PATHSPACE_VERTEX_SLOT_FIELDS(X)                                   \
  X(Vec3, position, p, "position")                                         \
  X(Vec3, geometric_normal, ng, "geometric normal")                        \
  X(Vec3, shading_normal, ns, "shading normal")                            \
  X(Vec3, incident, wo, "incident direction")                              \
  X(Vec3, previous_position, prev_p, "previous position")                  \
  X(float, prefix_distance, prefix_distance, "prefix distance")            \
  X(float, roughness, roughness, "roughness")                              \
  X(Rgb, throughput, throughput, "throughput")                             \
  X(Rgb, contribution, contribution, "contribution")                       \
  X(uint8_t, layer, layer, "layer")                                        \
  X(uint8_t, segments, segments, "segments")                               \
  X(uint8_t, selected, selected, "selected")                               \
  X(uint32_t, visible_lights, visible_lights, "visible lights")            \
  X(float, open_distance, open_distance, "open distance")
