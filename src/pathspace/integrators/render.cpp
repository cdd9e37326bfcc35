#include "pathspace/integrators/render.h"

#include <chrono>

#include "pathspace/base/error.h"
#include "pathspace/parallel/parallel_for.h"

#ifndef PATHSPACE_BUILD_TYPE
#define PATHSPACE_BUILD_TYPE "unknown"
#endif

namespace pathspace {

const char* build_type() { return PATHSPACE_BUILD_TYPE; }

RenderStats render(const Scene& scene, const Accel& accel, const RenderRequest& request, Film& film) {
  if (request.time_limit_s <= 0.0 && request.spp == 0) throw Error("the sample count must be at least 1");
  ThreadLimit limit(request.threads);
  std::unique_ptr<Integrator> integrator = make_integrator(request.integrator, scene, accel, request.settings);

  RenderStats stats;
  stats.integrator = integrator->name();
  stats.threads = ThreadLimit::active();
  stats.seed = request.settings.seed;
  PathCounters counters;
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };

  const bool timed = request.time_limit_s > 0.0;
  uint32_t pass = 0;
  while (timed ? (pass == 0 || elapsed() < request.time_limit_s) : pass < request.spp) {
    integrator->render_pass(pass, film, counters);
    ++pass;
    if (request.on_progress) {
      RenderProgress p;
      p.passes_done = pass;
      p.passes_total = timed ? 0 : request.spp;
      p.elapsed_s = elapsed();
      p.fraction = timed ? std::min(1.0, p.elapsed_s / request.time_limit_s) : double(pass) / double(request.spp);
      p.rays = counters.rays;
      p.paths = counters.paths;
      request.on_progress(p);
    }
  }
  stats.wall_s = elapsed();
  stats.spp = pass;
  stats.rays = counters.rays;
  stats.shadow_rays = counters.shadow_rays;
  stats.paths = counters.paths;
  stats.dropped_samples = counters.dropped;
  stats.report = integrator->report();
  if (request.want_aovs) stats.aovs = integrator->aovs();
  return stats;
}

}  // namespace pathspace
