#include "pathspace/filters/path_space_filter.h"

#include <atomic>

#include "pathspace/parallel/parallel_for.h"

namespace pathspace {

void PassthroughFilter::filter(const VertexBuffer& buffer, uint64_t, uint32_t, std::vector<Rgb>* filtered) {
  *filtered = buffer.contribution;
}

void resolve_filtered_pass(const VertexBuffer& buffer, const std::vector<Rgb>& filtered, Film& film,
                           PathCounters* counters, const std::vector<uint8_t>* found) {
  std::atomic<uint64_t> dropped{0};
  parallel_for(buffer.paths(), 1024, [&](size_t begin, size_t end) {
    uint64_t local_dropped = 0;
    for (size_t path = begin; path < end; ++path) {
      Rgb v = buffer.prefix[path];
      bool complete = true;
      for (int r = 0; r < buffer.count[path]; ++r) {
        const size_t i = buffer.slot(path, r);
        v += buffer.throughput[i] * filtered[i];
        if (found && !(*found)[i]) complete = false;
      }
      if (!complete) continue;
      if (!all_finite(v)) {
        ++local_dropped;
        v = Rgb();
      }
      film.add_sample(buffer.pixel[path], v);
    }
    dropped += local_dropped;
  });
  counters->dropped += dropped;
}

}  // namespace pathspace
