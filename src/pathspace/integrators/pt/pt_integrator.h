// Path tracing on the CPU: one camera path per pixel per pass, pixels in parallel (TBB). With a path
// space filter, a pass runs in two phases (Binder et al. 2021, sec. 3): trace and record the
// selected vertices, then filter them and resolve every path into the film.
#pragma once

#include <memory>

#include "pathspace/filters/path_space_filter.h"
#include "pathspace/filters/vertex_buffer.h"
#include "pathspace/integrators/integrator.h"
#include "pathspace/scene/scene_view.h"

namespace pathspace {

class HashedFilter;

class PtIntegrator final : public Integrator {
 public:
  PtIntegrator(const Scene& scene, const Accel& accel, const IntegratorSettings& settings);
  ~PtIntegrator() override;
  const char* name() const override { return "pt"; }
  void render_pass(uint32_t pass, Film& film, PathCounters& counters) override;
  std::string report() const override;
  std::vector<NamedImage> aovs() const override;

  const VertexBuffer& vertex_buffer() const { return buffer_; }
  const PathSpaceFilter* filter() const { return filter_.get(); }

 private:
  void render_plain(uint32_t pass, Film& film, PathCounters& counters);
  void render_filtered(uint32_t pass, Film& film, PathCounters& counters);

  SceneView view_;
  const Accel& accel_;
  IntegratorSettings settings_;
  std::unique_ptr<PathSpaceFilter> filter_;  // null: plain path tracing
  HashedFilter* hashed_ = nullptr;           // filter_ when it is the hashed filter
  VertexBuffer buffer_;
  std::vector<Rgb> filtered_;
};

}  // namespace pathspace
