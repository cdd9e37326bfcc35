// VertexBuffer's parallel loops, kept out of vertex_buffer.cpp so that the standalone GPU filter
// benchmark (bench/cuda), which compiles that file without oneTBB, still links.
#include "pathspace/filters/vertex_buffer.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace {

void VertexBuffer::copy_contributions(SlotValues* out) const {
  out->resize(contribution.size());
  parallel_for(paths(), 4096, [&](size_t begin, size_t end) {
    for (size_t path = begin; path < end; ++path)
      for (int r = 0; r < count[path]; ++r) (*out)[slot(path, r)] = contribution[slot(path, r)];
  });
}

}  // namespace pathspace
