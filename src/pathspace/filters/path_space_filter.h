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
#include "pathspace/camera/perspective_camera.h"
#include "pathspace/filters/caustic_settings.h"
#include "pathspace/filters/filter_workspace.h"
#include "pathspace/film/film.h"
#include "pathspace/film/image.h"
#include "pathspace/filters/vertex_buffer.h"
#include "pathspace/stats/path_counters.h"
#include "pathspace/stats/statistics.h"

namespace pathspace {

// What a filter asks of the integrator that feeds it, besides the selected vertices.
struct FilterNeeds {
  bool visibility = false;  // record VisibilityProbes data at each selected vertex
  int query_paths = 0;      // extra camera paths per pixel per pass that only query (query())
  CausticSettings caustics{.photons_per_pixel = 0.0};  // photon-mapped caustics (none unless the filter asks)
};

// Temporal finite differences (the hashed filter's --temporal hybrid, 2021 paper sec. 3.4.1): paths
// of the previous frame to trace again in this frame's scene with the same random numbers and camera.
struct ProbeRequest {
  uint64_t seed = 0;   // the previous frame's pass seed
  uint32_t pass = 0;   // and pass index
  PerspectiveCamera camera;  // the previous frame's camera: an unchanged scene gives the same path
  std::vector<uint32_t> pixels;
};

class PathSpaceFilter {
 public:
  virtual ~PathSpaceFilter() = default;
  virtual const char* name() const = 0;
  virtual FilterNeeds needs() const { return {}; }
  // The number of paths the filter takes at once, a batch, for records_per_path slots per path;
  // 0: the whole pass. The integrator traces, filters and resolves a pass batch by batch, so its
  // vertex buffer never holds more than one batch.
  virtual size_t batch_paths(int /*records_per_path*/) const { return 0; }
  // filtered[slot] receives the filtered contribution of every valid record slot of `buffer`, one
  // batch of the pass (the whole pass when batch_paths() is 0). `pass` and `seed` make jitter a pure
  // function of the vertex's path (determinism).
  virtual void filter(const VertexBuffer& buffer, uint64_t seed, uint32_t pass, SlotValues* filtered) = 0;
  // After the last batch of a pass.
  virtual void end_pass() {}
  // A pass of `paths` camera paths that another process of a distributed render filters
  // (Integrator::skip_pass): advance what depends on the paths so far.
  virtual void skip_pass(uint64_t /*paths*/) {}
  // Integrator::reports_passes, pass_report and agree_round of the filter.
  virtual bool reports_passes() const { return false; }
  virtual uint64_t pass_report() const { return 0; }
  virtual bool agree_round(const std::vector<uint64_t>& /*reports*/, int /*mine*/) { return false; }
  // Integrator::frame_warm_up of the filter.
  virtual uint32_t frame_warm_up() const { return 0; }
  // Integrator::distribution_limit of the filter's options.
  virtual std::string distribution_limit() const { return {}; }
  // Queries of extra camera paths (FilterNeeds::query_paths) against the batch filtered last:
  // values[slot] receives the estimate at each valid record slot, found[slot] whether it had any
  // data to average (an empty query is not accumulated).
  virtual void query(const VertexBuffer& /*queries*/, SlotValues* /*values*/, std::vector<uint8_t>* /*found*/) {}
  // Statistics accumulated over all passes so far, named "<filter>.<what>".
  virtual void statistics(Statistics&) const {}
  // Debug images of the last pass, when the filter's options asked for them.
  virtual std::vector<NamedImage> aovs() const { return {}; }
  // The paths to re-trace before pass `pass`'s filter() (null: none), and their vertices (path k is
  // pixels[k]), given before filter() of the same pass.
  virtual const ProbeRequest* probe_request(uint32_t /*pass*/) const { return nullptr; }
  virtual void temporal_probes(const VertexBuffer& /*probes*/) {}
  // A new frame of an animation begins with this camera (same image size; 2021 paper sec. 3.4): the
  // filter was carried over from the previous frame's integrator with everything it holds.
  virtual void begin_frame(const PerspectiveCamera& /*camera*/) {}
  // What the next pass needs besides the options (RenderSession::save_state).
  virtual void save_state(StateWriter&) const {}
  virtual void load_state(StateReader&) {}

  // The integrator's buffers for this filter's passes (filter_workspace.h: why the filter keeps them).
  FilterWorkspace& workspace() { return workspace_; }
  const FilterWorkspace& workspace() const { return workspace_; }

 private:
  FilterWorkspace workspace_;
};

// `--filter passthrough`: every vertex keeps its own contribution, so the image equals plain PT
// bit for bit while every path goes through the vertex buffer and the resolve step (tests).
class PassthroughFilter final : public PathSpaceFilter {
 public:
  const char* name() const override { return "passthrough"; }
  void filter(const VertexBuffer& buffer, uint64_t seed, uint32_t pass, SlotValues* filtered) override;
};

// Adds every path of the pass to the film: prefix + sum_i throughput_i * filtered_i, summed in
// record order exactly as PathSample::value(). Paths with a NaN/Inf result are dropped and counted.
// With `found`, a path with a record whose slot is not found is left out of the film (a query path
// whose query was empty).
void resolve_filtered_pass(const VertexBuffer& buffer, const SlotValues& filtered, Film& film,
                           PathCounters* counters, const std::vector<uint8_t>* found = nullptr);

}  // namespace pathspace
