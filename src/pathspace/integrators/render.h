// The render driver: runs integrator passes until a sample count or a wall-clock budget is reached,
// reporting progress after every pass, and gathers the statistics written by --stats.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "pathspace/film/film.h"
#include "pathspace/integrators/integrator.h"

namespace pathspace {

struct RenderProgress {
  uint32_t passes_done = 0;
  uint32_t passes_total = 0;  // 0 when time-limited
  double elapsed_s = 0.0;
  double fraction = 0.0;      // 0..1 (of spp or of the time budget)
  uint64_t rays = 0;
  uint64_t paths = 0;
};

struct RenderRequest {
  std::string integrator = "pt";
  uint32_t spp = 16;          // passes when time_limit_s == 0
  double time_limit_s = 0.0;  // > 0: run whole passes until this much wall time has passed
  int threads = 0;            // <= 0: all cores
  IntegratorSettings settings;
  std::function<void(const RenderProgress&)> on_progress;  // called after each pass (may be empty)
  bool want_aovs = false;     // collect the integrator's debug images into RenderStats::aovs
};

struct RenderStats {
  std::string integrator;
  double wall_s = 0.0;
  uint32_t spp = 0;
  uint64_t rays = 0;
  uint64_t shadow_rays = 0;
  uint64_t paths = 0;
  uint64_t dropped_samples = 0;
  int threads = 0;
  uint64_t seed = 0;
  std::string report;             // integrator-specific statistics (e.g. the filter's hash table)
  std::vector<NamedImage> aovs;   // when requested
  double mrays_per_s() const { return wall_s > 0 ? double(rays) / wall_s * 1e-6 : 0.0; }
  double paths_per_s() const { return wall_s > 0 ? double(paths) / wall_s : 0.0; }
};

class Accel;
class Scene;

// Renders into `film` (which is not cleared: passes accumulate). Throws pathspace::Error on bad requests.
RenderStats render(const Scene& scene, const Accel& accel, const RenderRequest& request, Film& film);

// "release", "debug", ... as configured at build time.
const char* build_type();

}  // namespace pathspace
