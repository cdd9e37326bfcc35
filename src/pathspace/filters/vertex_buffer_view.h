// VertexBufferView: raw pointers to the arrays of a VertexBuffer (host) or of a DeviceVertexBuffer
// (filters/cuda_vertex_buffer.h), so that the same PS_HD code stores and reads the selected vertices of
// a pass on the CPU and on the GPU (Binder et al. 2021, sec. 3: the first phase stores the vertices,
// the filter reads them). Field names are VertexBuffer's. Record r of path p is slot r * paths + p
// (r < count[p]): the records of one rank lie together, so the first records of all paths, which
// nearly every path has, are one dense block, and the rarer ones (camera-side branches, a second
// layer) fill the blocks behind it sparsely. With the path's records side by side instead, a path
// through no glass left 3 of its 4 branch slots empty between every two paths' records, and each
// array walk read 4x the cache lines (docs/results/one-path-per-pixel.md).
#pragma once

#include <cstddef>
#include <cstdint>

#include "pathspace/filters/path_sample.h"
#include "pathspace/filters/vertex_fields.h"

namespace pathspace {

struct VertexBufferView {
  size_t paths = 0;
  int records_per_path = 0;
#define PATHSPACE_VIEW_PATH_FIELD(T, name, what) T* name = nullptr;
#define PATHSPACE_VIEW_SLOT_FIELD(T, name, member, what) T* name = nullptr;
  PATHSPACE_VERTEX_PATH_FIELDS(PATHSPACE_VIEW_PATH_FIELD)
  PATHSPACE_VERTEX_SLOT_FIELDS(PATHSPACE_VIEW_SLOT_FIELD)
#undef PATHSPACE_VIEW_PATH_FIELD
#undef PATHSPACE_VIEW_SLOT_FIELD

  PS_HD size_t slots() const { return paths * size_t(records_per_path); }
  PS_HD size_t slot(size_t path, int record) const { return size_t(record) * paths + path; }
  // The record's number in path order (path * records_per_path + record), not its slot: what a random
  // stream per record is keyed by (the hashed filter's jitter), so that it does not depend on the layout.
  PS_HD size_t record_stream(size_t path, int record) const { return path * size_t(records_per_path) + size_t(record); }
  PS_HD size_t record_stream(size_t slot) const { return record_stream(slot % paths, int(slot / paths)); }

  // Stores one path's sample (drops records beyond records_per_path; the caller sizes it right).
  PS_HD void store(size_t path, uint32_t pixel_index, const PathSample& s) const {
    prefix[path] = s.prefix;
    pixel[path] = pixel_index;
    const int n = min_int(s.count, records_per_path);
    count[path] = uint8_t(n);
    for (int r = 0; r < n; ++r) {
      const FilterVertex& v = s.records[r];
      const size_t i = slot(path, r);
#define PATHSPACE_STORE_SLOT_FIELD(T, name, member, what) name[i] = v.member;
      PATHSPACE_VERTEX_SLOT_FIELDS(PATHSPACE_STORE_SLOT_FIELD)
#undef PATHSPACE_STORE_SLOT_FIELD
    }
  }
};

}  // namespace pathspace
