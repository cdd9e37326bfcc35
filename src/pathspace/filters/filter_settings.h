// Which path space filter an integrator applies to its selected vertices, and its options.
#pragma once

#include <cstdint>

#include "pathspace/filters/hashed_filter_settings.h"

namespace pathspace {

enum class FilterKind : uint8_t { none, hashed };

struct FilterSettings {
  FilterKind kind = FilterKind::none;
  HashedFilterSettings hashed;
  // With kind none, still route every path through the vertex buffer and the resolve step (tests:
  // the result must equal plain path tracing bit for bit).
  bool force_vertex_buffer = false;
};

}  // namespace pathspace
