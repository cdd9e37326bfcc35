#include "pathspace/filters/path_space_filter.h"

#include <atomic>

#include "pathspace/filters/filter_resolve.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace {

void PassthroughFilter::filter(const VertexBuffer& buffer, uint64_t, uint32_t, SlotValues* filtered) {
  buffer.copy_contributions(filtered);
}

void resolve_filtered_pass(const VertexBuffer& buffer, const SlotValues& filtered, Film& film,
                           PathCounters* counters, const std::vector<uint8_t>* found) {
  std::atomic<uint64_t> dropped{0};
  const VertexBufferView view = buffer.view();
  const uint8_t* found_data = found ? found->data() : nullptr;
  parallel_for(buffer.paths(), 1024, [&](size_t begin, size_t end) {
    uint64_t local_dropped = 0;
    for (size_t path = begin; path < end; ++path) {
      const ResolvedPath r = resolved_path_value(view, path, filtered.data(), found_data);
      if (!r.complete) continue;
      local_dropped += r.dropped ? 1 : 0;
      film.add_sample(buffer.pixel[path], r.value);
    }
    dropped += local_dropped;
  });
  counters->dropped += dropped;
}

}  // namespace pathspace
