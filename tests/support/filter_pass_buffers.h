// Vertex buffers of one real pass of path tracing for the hashed filter's bit-exactness tests (the
// CPU steps in tests/unit, the GPU filter in tests/cuda): a built-in scene, a vertex selection, the
// passthrough filter (so every path goes through the buffer), and the filter settings of each case.
#pragma once

#include <cstring>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "pathspace/accel/accel.h"
#include "pathspace/film/film.h"
#include "pathspace/filters/filter_registry.h"
#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/filters/vertex_buffer.h"
#include "pathspace/integrators/pt/pt_integrator.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace::testing {

struct PassBuffer {
  std::unique_ptr<Scene> scene;
  VertexBuffer buffer;
  size_t pixels = 0;
};

// One pass (pass index `pass`) of `scene_name` at width x height; nth > 0 selects the nth diffuse
// vertex (--psf-select nth), 0 the first.
inline PassBuffer make_pass_buffer(const std::string& scene_name, int width, int height, int nth, uint32_t pass = 0) {
  PassBuffer out;
  out.scene = std::make_unique<Scene>(make_builtin_scene(scene_name, width, height));
  out.pixels = size_t(width) * size_t(height);
  const Accel accel(*out.scene);
  PtSettings s;
  if (nth > 0) {
    s.selection.mode = VertexSelectionMode::nth;
    s.selection.n = nth;
  }
  PtIntegrator pt(*out.scene, accel, s, 0, FilterChoice{"passthrough", {}});
  Film film(width, height);
  PathCounters counters;
  pt.render_pass(pass, film, counters);
  out.buffer = pt.vertex_buffer();
  return out;
}

struct FilterCase {
  std::string name, scene;
  int nth = 0;
  HashedFilterSettings settings;
  bool overflows = false;  // the table is so small that probe windows fill up
};

// gtest prints a case by its name (ctest's test names), not as bytes.
inline void PrintTo(const FilterCase& c, std::ostream* os) { *os << c.name; }

// Primary hits and second bounce, neighbour search (3.3.1), multi-level (3.3.2), and a table far
// too small for the pass (every window overflows and is settled).
inline std::vector<FilterCase> filter_cases() {
  std::vector<FilterCase> cases;
  cases.push_back({"cornell_primary", "cornell-box", 0, {}, false});
  cases.push_back({"cornell_second_bounce", "cornell-box", 2, {}, false});
  FilterCase neighbours{"cornell_neighbours", "cornell-box", 2, {}, false};
  neighbours.settings.neighbour_search = true;
  neighbours.settings.min_count = 8;
  cases.push_back(neighbours);
  FilterCase multi{"cornell_multi_level", "cornell-box", 2, {}, false};
  multi.settings.multi_level = true;
  multi.settings.min_count = 8;
  cases.push_back(multi);
  FilterCase tiny{"cornell_overflowing_table", "cornell-box", 2, {}, true};
  tiny.settings.table_factor = 0.001f;
  cases.push_back(tiny);
  FilterCase clamped{"cornell_clamped_overflowing", "cornell-box", 2, {}, true};  // --psf-clamp, settling included
  clamped.settings.table_factor = 0.001f;
  clamped.settings.max_luminance = 0.5f;
  cases.push_back(clamped);
  FilterCase tiny_primary{"cornell_overflowing_table_primary", "cornell-box", 0, {}, true};
  tiny_primary.settings.table_factor = 0.001f;
  cases.push_back(tiny_primary);
  cases.push_back({"glossy_primary", "cornell-glossy", 0, {}, false});
  FilterCase glossy_nth{"glossy_second_bounce_neighbours", "cornell-glossy", 2, {}, false};
  glossy_nth.settings.neighbour_search = true;
  cases.push_back(glossy_nth);
  return cases;
}

// Whether the filtered values of every valid record slot are the same bits; *differing counts them.
template <typename X, typename Y>  // std::vector<Rgb> or SlotValues
bool same_filtered_bits(const VertexBuffer& b, const X& x, const Y& y, size_t* differing) {
  *differing = 0;
  for (size_t path = 0; path < b.paths(); ++path)
    for (int r = 0; r < b.count[path]; ++r) {
      const size_t i = b.slot(path, r);
      if (std::memcmp(&x[i], &y[i], sizeof(Rgb)) != 0) ++*differing;
    }
  return *differing == 0;
}

}  // namespace pathspace::testing
