// No oneTBB here: the standalone GPU filter benchmark (bench/cuda) compiles this file on a machine
// with only the CUDA toolkit. Parallel loops over the buffer live in vertex_buffer_copy.cpp.
#include "pathspace/filters/vertex_buffer.h"

#include <algorithm>
#include <numeric>

namespace pathspace {

int records_per_path(const VertexSelection& s) {
  if (s.mode == VertexSelectionMode::none) return 0;
  const int vertices = s.mode == VertexSelectionMode::all ? min_int(s.max_vertices, kMaxSelectedVertices) : 1;
  return (vertices << s.camera_splits) * (s.split_layers ? kMaxBsdfLayers : 1);
}

void VertexBuffer::resize(size_t paths, int records_per_path) {
  if (records_per_path != records_per_path_) {
    *this = VertexBuffer();
    records_per_path_ = records_per_path;
  }
  const size_t slots = paths * size_t(records_per_path);
  const bool zero_first_block = prefix.size() != paths;  // the first block moved or grew
#define PATHSPACE_RESIZE_PATH_FIELD(T, name, what) name.resize(paths);
#define PATHSPACE_RESIZE_SLOT_FIELD(T, name, member, what) \
  name.resize(slots);                                       \
  if (zero_first_block) std::fill_n(name.data(), std::min(paths, slots), T{});
  PATHSPACE_VERTEX_PATH_FIELDS(PATHSPACE_RESIZE_PATH_FIELD)
  PATHSPACE_VERTEX_SLOT_FIELDS(PATHSPACE_RESIZE_SLOT_FIELD)
#undef PATHSPACE_RESIZE_PATH_FIELD
#undef PATHSPACE_RESIZE_SLOT_FIELD
  count.assign(paths, 0);  // a path without a stored sample has no records
}

#define PATHSPACE_PATH_FIELD_BYTES(T, name, what) +sizeof(T)
#define PATHSPACE_SLOT_FIELD_BYTES(T, name, member, what) +sizeof(T)
size_t VertexBuffer::bytes_per_path() { return 0 PATHSPACE_VERTEX_PATH_FIELDS(PATHSPACE_PATH_FIELD_BYTES); }
size_t VertexBuffer::bytes_per_slot() { return 0 PATHSPACE_VERTEX_SLOT_FIELDS(PATHSPACE_SLOT_FIELD_BYTES); }
#undef PATHSPACE_PATH_FIELD_BYTES
#undef PATHSPACE_SLOT_FIELD_BYTES

size_t VertexBuffer::total_records() const { return std::accumulate(count.begin(), count.end(), size_t(0)); }

VertexBufferView VertexBuffer::view() {
  VertexBufferView v;
  v.paths = paths();
  v.records_per_path = records_per_path_;
#define PATHSPACE_VIEW_OF_PATH_FIELD(T, name, what) v.name = name.data();
#define PATHSPACE_VIEW_OF_SLOT_FIELD(T, name, member, what) v.name = name.data();
  PATHSPACE_VERTEX_PATH_FIELDS(PATHSPACE_VIEW_OF_PATH_FIELD)
  PATHSPACE_VERTEX_SLOT_FIELDS(PATHSPACE_VIEW_OF_SLOT_FIELD)
#undef PATHSPACE_VIEW_OF_PATH_FIELD
#undef PATHSPACE_VIEW_OF_SLOT_FIELD
  return v;
}

FilterVertex VertexBuffer::record(size_t i) const {
  FilterVertex v;
#define PATHSPACE_RECORD_SLOT_FIELD(T, name, member, what) v.member = name[i];
  PATHSPACE_VERTEX_SLOT_FIELDS(PATHSPACE_RECORD_SLOT_FIELD)
#undef PATHSPACE_RECORD_SLOT_FIELD
  return v;
}

}  // namespace pathspace
