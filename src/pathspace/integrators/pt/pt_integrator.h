// Path tracing on the CPU: one camera path per pixel per pass, pixels in parallel (TBB).
#pragma once

#include "pathspace/integrators/integrator.h"
#include "pathspace/scene/scene_view.h"

namespace pathspace {

class PtIntegrator final : public Integrator {
 public:
  PtIntegrator(const Scene& scene, const Accel& accel, const IntegratorSettings& settings);
  const char* name() const override { return "pt"; }
  void render_pass(uint32_t pass, Film& film, PathCounters& counters) override;

 private:
  SceneView view_;
  const Accel& accel_;
  IntegratorSettings settings_;
};

}  // namespace pathspace
