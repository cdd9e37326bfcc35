// PathSpaceFilter: replaces the contributions of a pass's selected vertices by filtered estimates
// (Binder et al. 2021 sec. 3; Keller et al. 2014). The integrator then resolves each path as
// prefix + sum throughput * filtered contribution (resolve_filtered_pass). Filters register
// themselves with their options in filters/filter_registry.h.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "pathspace/base/state_archive.h"
#include "pathspace/film/film.h"
#include "pathspace/film/image.h"
#include "pathspace/filters/vertex_buffer.h"
#include "pathspace/stats/path_counters.h"
#include "pathspace/stats/statistics.h"

namespace pathspace {

class PathSpaceFilter {
 public:
  virtual ~PathSpaceFilter() = default;
  virtual const char* name() const = 0;
  // filtered[slot] receives the filtered contribution of every valid record slot of `buffer`.
  // `pass` and `seed` make jitter a pure function of the vertex's path (determinism).
  virtual void filter(const VertexBuffer& buffer, uint64_t seed, uint32_t pass, std::vector<Rgb>* filtered) = 0;
  // Statistics accumulated over all passes so far, named "<filter>.<what>".
  virtual void statistics(Statistics&) const {}
  // Debug images of the last pass, when the filter's options asked for them.
  virtual std::vector<NamedImage> aovs() const { return {}; }
  // What the next pass needs besides the options (RenderSession::save_state).
  virtual void save_state(StateWriter&) const {}
  virtual void load_state(StateReader&) {}
};

// `--filter passthrough`: every vertex keeps its own contribution, so the image equals plain PT
// bit for bit while every path goes through the vertex buffer and the resolve step (tests).
class PassthroughFilter final : public PathSpaceFilter {
 public:
  const char* name() const override { return "passthrough"; }
  void filter(const VertexBuffer& buffer, uint64_t seed, uint32_t pass, std::vector<Rgb>* filtered) override;
};

// Adds every path of the pass to the film: prefix + sum_i throughput_i * filtered_i, summed in
// record order exactly as PathSample::value(). Paths with a NaN/Inf result are dropped and counted.
void resolve_filtered_pass(const VertexBuffer& buffer, const std::vector<Rgb>& filtered, Film& film,
                           PathCounters* counters);

}  // namespace pathspace
