// Host orchestration of light tracing (lt_integrator.h); the per-path logic is lt_kernel.h.
#include "pathspace/integrators/lt/lt_integrator.h"

#include <fmt/format.h>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/scene/scene.h"

namespace pathspace {

LtIntegrator::LtIntegrator(const Scene& scene, const Accel& accel, const LtSettings& settings, uint64_t seed)
    : view_(scene.view()), accel_(accel), settings_(settings), seed_(seed),
      splats_(scene.camera.width, scene.camera.height, settings.splat_scale > 0.0 ? settings.splat_scale : SplatFilm::kDefaultScale) {}

void LtIntegrator::render_pass(uint32_t pass, Film& film, PathCounters& counters) {
  lt_render_pass(view_, accel_, settings_, seed_, pass, splats_, film, counters);
  overflows_ += splats_.overflows();
  non_finite_ += splats_.non_finite();
  ++passes_;
}

void LtIntegrator::statistics(Statistics& out) const {
  out.counter("lt.passes", passes_);
  out.counter("lt.light_paths_per_pass", lt_paths_per_pass(settings_, splats_.pixel_count()));
  out.counter("lt.splat_overflows", overflows_, "splats rejected: too large or negative");
  out.counter("lt.splat_non_finite", non_finite_, "splats rejected: NaN or Inf");
}

// Passes are independent; only the totals carry over.
void LtIntegrator::save_state(StateWriter& out) const {
  out.put("lt.passes", passes_);
  out.put("lt.overflows", overflows_);
  out.put("lt.non_finite", non_finite_);
}
void LtIntegrator::load_state(StateReader& in) {
  in.get("lt.passes", &passes_);
  in.get("lt.overflows", &overflows_);
  in.get("lt.non_finite", &non_finite_);
}

}  // namespace pathspace
