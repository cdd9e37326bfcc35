// The resolve step of path space filtering (Binder et al. 2021, sec. 3, eq. 9): a path's value is
// prefix + sum_i throughput_i * filtered_i, summed in record order exactly as PathSample::value().
// One PS_HD function for resolve_filtered_pass (CPU) and the GPU backend, so both drop the same
// paths and give the same pixels.
#pragma once

#include <cstddef>
#include <cstdint>

#include "pathspace/filters/vertex_buffer_view.h"

namespace pathspace {

struct ResolvedPath {
  Rgb value;              // zero when dropped
  bool complete = true;   // false: a record's query was empty (`found`), the path is left out
  bool dropped = false;   // NaN or Inf: the path adds zero and is counted
};

// `found` (may be null): per record slot, whether its filtered value exists (query paths).
PS_INLINE ResolvedPath resolved_path_value(const VertexBufferView& b, size_t path, const Rgb* filtered,
                                           const uint8_t* found = nullptr) {
  ResolvedPath r;
  Rgb v = b.prefix[path];
  for (int k = 0; k < b.count[path]; ++k) {
    const size_t i = b.slot(path, k);
    v += b.throughput[i] * filtered[i];
    if (found && !found[i]) r.complete = false;
  }
  if (!r.complete) return r;
  if (!all_finite(v)) {
    r.dropped = true;
    v = Rgb();
  }
  r.value = v;
  return r;
}

}  // namespace pathspace
