// Host-side integrator interface: an integrator renders one sample pass at a time into a Film, each
// pass a pure function of (scene, settings, seed, pass index). A RenderSession (session/) runs the
// passes and owns the integrator between them; integrators register themselves with their options
// in integrator_registry.h.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "pathspace/base/state_archive.h"
#include "pathspace/film/film.h"
#include "pathspace/film/image.h"
#include "pathspace/parallel/process_group.h"
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
  // Pass `pass` is rendered by another process of a distributed render (docs/distributed.md): keep
  // what the next pass reads as if this process had rendered it (the consistent filter's path
  // count). Recurrences that are a function of the pass index alone (ProgressiveRadius) need nothing.
  virtual void skip_pass(uint32_t /*pass*/, size_t /*pixels*/) {}
  // At the end of a distributed run: what this process accumulated outside the film for aovs()
  // (BPT's fixed-point strategy sums) goes to rank 0, and the other ranks start again from zero.
  virtual void hand_over(ProcessGroup&) {}
  // A rank other than 0 of a distributed render that restored a checkpoint: drop what hand_over sums
  // (rank 0 holds the restored part and hands it over), so the restored passes count once.
  virtual void forget_handed_over() {}
  // A distributed render of passes whose work depends on an earlier pass's outcome (the consistent
  // filter's switch-off, sec. 2.2): after each round the ranks all-gather pass_report() of the pass
  // each rendered, and agree_round() gets them in pass order (`first`: the round's first pass index;
  // `mine`: this rank's position in the round, -1 for none). It returns true when an earlier pass of
  // the round changed what this rank's pass does: its state is then as before that pass, and the
  // session renders it again. false from reports_passes(): nothing to agree (no collective).
  virtual bool reports_passes() const { return false; }
  virtual uint64_t pass_report() const { return 0; }
  virtual bool agree_round(uint32_t /*first*/, const std::vector<uint64_t>& /*reports*/, int /*mine*/) { return false; }
  // Why these options cannot be dealt to several processes (state that one pass hands to the next
  // beyond skip_pass), or empty. A distributed render refuses them at start-up.
  virtual std::string distribution_limit() const { return {}; }
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
  // The same after a pass that RenderSession::abort cut short: the filter only when that pass had
  // not reached it yet (its table is as the last whole pass left it); null otherwise.
  virtual std::shared_ptr<PathSpaceFilter> carried_filter_after_abort() const { return nullptr; }
  // Frames dealt to processes in chunks (render_frames, docs/distributed.md): how many frames before
  // its chunk a process renders, unreported, so that what carried_filter() carries is warm. 0: each
  // frame starts afresh, chunks are exact; kAllFrames: only every frame before gives that state.
  static constexpr uint32_t kAllFrames = UINT32_MAX;
  virtual uint32_t frame_warm_up() const { return 0; }
};

}  // namespace pathspace
