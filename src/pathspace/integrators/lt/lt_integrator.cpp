// Host orchestration of light tracing (lt_integrator.h); the per-path logic is lt_kernel.h.
#include "pathspace/integrators/lt/lt_integrator.h"

#include <fmt/format.h>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/scene/scene.h"

namespace pathspace {

LtIntegrator::LtIntegrator(const Scene& scene, const Accel& accel, const IntegratorSettings& settings)
    : view_(scene.view()), accel_(accel), settings_(settings),
      splats_(scene.camera.width, scene.camera.height,
              settings.lt.splat_scale > 0.0 ? settings.lt.splat_scale : SplatFilm::kDefaultScale) {
  if (settings.filter.kind != FilterKind::none) throw Error("path space filtering is not available with the lt integrator");
  if (settings.lt.filter != LtFilter::box && !(settings.lt.filter_radius > 0.f && settings.lt.filter_radius <= 16.f))
    throw Error(fmt::format("lt filter radius {} must be in (0, 16] pixels", settings.lt.filter_radius));
}

void LtIntegrator::render_pass(uint32_t pass, Film& film, PathCounters& counters) {
  lt_render_pass(view_, accel_, settings_.lt, settings_.seed, pass, splats_, film, counters);
  overflows_ += splats_.overflows();
  non_finite_ += splats_.non_finite();
  ++passes_;
}

std::string LtIntegrator::report() const {
  const char* filters[] = {"box", "tent", "gaussian"};
  return fmt::format("lt: {} passes, {} light paths per pass, filter {}{}, emitter {}, splats rejected: {} overflow, {} non-finite",
                     passes_, lt_paths_per_pass(settings_.lt, splats_.pixel_count()), filters[int(settings_.lt.filter)],
                     settings_.lt.filter == LtFilter::box ? std::string() : fmt::format(" (radius {})", settings_.lt.filter_radius),
                     settings_.lt.skip_emitter ? "skipped" : "splatted", overflows_, non_finite_);
}

}  // namespace pathspace
