// Vertex buffer files: one pass's selected vertices (VertexBuffer), the CPU hashed filter's output
// for them and what produced it (the settings that matter, seed, pass), so that the GPU filter can be
// checked and timed against the CPU on a machine without the renderer (bench/cuda/). A small binary
// format: magic, version, sizes, then each array with its byte count; every size is checked on
// read and a bad file is a pathspace::Error, never a crash. Plain C++ (no TBB, fmt or Embree): the
// standalone GPU benchmark compiles it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/filters/vertex_buffer.h"

namespace pathspace {

struct VertexBufferFile {
  VertexBuffer buffer;
  SlotValues filtered;      // per record slot: HashedFilter::filter's output (empty: none)
  HashedFilterSettings settings;  // key.pixel_angle is the camera's (2 tan_y / height)
  uint64_t pixels = 0;            // the table is sized for this many (table_factor * pixels cells)
  uint64_t seed = 0;
  uint32_t pass = 0;
};

void write_vertex_buffer_file(const std::string& path, const VertexBufferFile& file);
VertexBufferFile read_vertex_buffer_file(const std::string& path);

}  // namespace pathspace
