// Path tracing on the CPU: one camera path per pixel per pass, pixels in parallel (TBB). With a path
// space filter, a pass runs in two phases (Binder et al. 2021, sec. 3): trace and record the
// selected vertices, then filter them and resolve every path into the film.
#pragma once

#include <memory>

#include "pathspace/filters/filter_registry.h"
#include "pathspace/filters/path_space_filter.h"
#include "pathspace/filters/vertex_buffer.h"
#include "pathspace/integrators/integrator.h"
#include "pathspace/integrators/pt/caustic_photon_map.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/scene/scene_view.h"

namespace pathspace {

class Accel;
class Scene;

class PtIntegrator final : public Integrator {
 public:
  // `filter`: the path space filter of the selected vertices (FilterChoice::kNone: plain PT);
  // `carried`: the previous frame's filter of that kind, taken over (begin_frame) instead of a new one.
  PtIntegrator(const Scene& scene, const Accel& accel, const PtSettings& settings, uint64_t seed,
               const FilterChoice& filter = {}, std::shared_ptr<PathSpaceFilter> carried = nullptr);
  ~PtIntegrator() override;
  const char* name() const override { return "pt"; }
  void render_pass(uint32_t pass, Film& film, PathCounters& counters) override;
  void skip_pass(uint32_t pass, size_t pixels) override;
  std::string distribution_limit() const override;
  bool reports_passes() const override { return filter_ && filter_->reports_passes(); }
  uint64_t pass_report() const override { return filter_ ? filter_->pass_report() : 0; }
  bool agree_round(uint32_t, const std::vector<uint64_t>& reports, int mine) override { return filter_ && filter_->agree_round(reports, mine); }
  void statistics(Statistics& out) const override;
  std::vector<NamedImage> aovs() const override;
  void save_state(StateWriter& out) const override;
  void load_state(StateReader& in) override;
  std::shared_ptr<PathSpaceFilter> carried_filter() const override { return filter_; }
  std::shared_ptr<PathSpaceFilter> carried_filter_after_abort() const override { return filter_reached_ ? nullptr : filter_; }
  uint32_t frame_warm_up() const override { return filter_ ? filter_->frame_warm_up() : 0; }

  // The last batch's vertices (empty without a filter).
  const VertexBuffer& vertex_buffer() const;
  const PathSpaceFilter* filter() const { return filter_.get(); }

 private:
  void render_plain(uint32_t pass, Film& film, PathCounters& counters);
  void render_filtered(uint32_t pass, Film& film, PathCounters& counters);
  void trace_batch(uint32_t pass, size_t first, size_t paths, int stream, VertexBuffer* buffer, PathCounters& counters);
  void trace_probes(const ProbeRequest& request, VertexBuffer* buffer, PathCounters& counters);

  SceneView view_;
  const Accel& accel_;
  PtSettings settings_;
  uint64_t seed_;
  std::shared_ptr<PathSpaceFilter> filter_;  // null: plain path tracing
  bool filter_reached_ = false;  // the current (or last) pass has called the filter (carried_filter_after_abort)
  FilterNeeds needs_;
  std::vector<uint32_t> probe_lights_;  // the delta lights of the visibility weight
  VisibilityProbes probes_;             // none unless the filter needs visibility
  std::unique_ptr<CausticPhotonMap> caustics_;  // null unless the filter asks for photon-mapped caustics
};

}  // namespace pathspace
