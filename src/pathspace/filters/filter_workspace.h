// The buffers an integrator traces into and resolves from in a filtered pass. The filter keeps them
// (PathSpaceFilter::workspace) because it is what an animation carries from frame to frame: a
// frame's new integrator then reuses them instead of allocating and faulting in a pass's worth of
// vertex records again (about 50 MB at 640x360; docs/benchmarks.md).
#pragma once

#include <cstdint>
#include <vector>

#include "pathspace/filters/vertex_buffer.h"
#include "pathspace/math/rgb.h"

namespace pathspace {

struct FilterWorkspace {
  VertexBuffer paths;             // one batch of the pass
  SlotValues filtered;            // its filtered contributions, per record slot
  VertexBuffer queries;           // one batch of query-only paths
  SlotValues queried;             // their query results
  std::vector<uint8_t> found;     // and whether each query found data
  VertexBuffer probes;            // the previous frame's paths traced again (--temporal hybrid)
};

}  // namespace pathspace
