// Host-side integrator interface: an integrator renders one sample pass at a time into a Film, each
// pass a pure function of (scene, settings, seed, pass index). A RenderSession (session/) runs the
// passes and owns the integrator between them; integrators register themselves with their options
// in integrator_registry.h.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "pathspace/base/state_archive.h"
#include "pathspace/film/film.h"
#include "pathspace/film/image.h"
#include "pathspace/stats/path_counters.h"
#include "pathspace/stats/statistics.h"

namespace pathspace {

class PathSpaceFilter;

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual const char* name() const = 0;
  // Renders pass `pass` (one sample per pixel for PT) into film; adds to counters.
  virtual void render_pass(uint32_t pass, Film& film, PathCounters& counters) = 0;
  // Statistics beyond the common counters, accumulated over the passes so far, named
  // "<integrator or filter>.<what>" (e.g. "pclt.memory_bytes").
  virtual void statistics(Statistics&) const {}
  // Debug images (AOVs) over the passes so far, when the options asked for them.
  virtual std::vector<NamedImage> aovs() const { return {}; }
  // Everything the next pass reads besides the options, seed and film (radius recurrences, totals,
  // per-strategy sums), so that a restored render continues bit for bit.
  virtual void save_state(StateWriter&) const {}
  virtual void load_state(StateReader&) {}
  // What carries from one frame of an animation to the next (2021 paper sec. 3.4): the path space
  // filter with its table, handed to the next frame's integrator (IntegratorContext::carried_filter).
  // Null: the next frame starts afresh.
  virtual std::shared_ptr<PathSpaceFilter> carried_filter() const { return nullptr; }
};

}  // namespace pathspace
