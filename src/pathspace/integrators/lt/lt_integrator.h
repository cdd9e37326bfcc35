// Light tracing on the CPU (`--integrator lt`): a pass traces N light paths in parallel (default N =
// pixel count), splats their camera connections into a fixed-point SplatFilm (deterministic for any
// thread count), then adds each pixel's pass estimate (sum of splats / N) to the Film as ONE sample.
// Passes are independent, so Film::variance_of_mean() over passes is an unbiased variance of the
// pixel mean; pixels within one pass are correlated (they share light paths).
#pragma once

#include <atomic>

#include "pathspace/film/splat_film.h"
#include "pathspace/integrators/integrator.h"
#include "pathspace/integrators/lt/lt_kernel.h"
#include "pathspace/integrators/lt/lt_settings.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/scene/scene_view.h"

namespace pathspace {

class Accel;
class Scene;

// Light paths of one pass for the given settings and film size.
inline uint64_t lt_paths_per_pass(const LtSettings& s, size_t pixels) { return s.light_paths > 0 ? s.light_paths : pixels; }

// One light-tracing pass with any Tracer (tests wrap Accel, e.g. to add shading normals): clears
// `splats`, traces the pass's light paths and resolves them into `film`. Adds to counters.
template <typename Tracer>
void lt_render_pass(const SceneView& view, const Tracer& tracer, const LtSettings& settings, uint64_t seed, uint32_t pass,
                    SplatFilm& splats, Film& film, PathCounters& counters) {
  constexpr size_t kPathGrain = 256;
  const uint64_t n = lt_paths_per_pass(settings, film.pixel_count());
  const float inv_paths = float(1.0 / double(n));
  splats.clear();
  std::atomic<uint64_t> rays{0}, shadow_rays{0};
  parallel_for(size_t(n), kPathGrain, [&](size_t begin, size_t end) {
    PathCounters local;
    const SplatFilmView sv = splats.worker_view();
    for (size_t path = begin; path < end; ++path)
      lt_trace_path(view, tracer, Sampler(seed, path, pass), settings, inv_paths, sv, &local);
    rays += local.rays;
    shadow_rays += local.shadow_rays;
  });
  splats.merge_workers();
  splats.resolve_into(film);
  counters.rays += rays;
  counters.shadow_rays += shadow_rays;
  counters.paths += n;
  counters.dropped += splats.non_finite() + splats.overflows();
}

class LtIntegrator final : public Integrator {
 public:
  LtIntegrator(const Scene& scene, const Accel& accel, const LtSettings& settings, uint64_t seed);
  const char* name() const override { return "lt"; }
  void render_pass(uint32_t pass, Film& film, PathCounters& counters) override;
  void statistics(Statistics& out) const override;
  void save_state(StateWriter& out) const override;
  void load_state(StateReader& in) override;

 private:
  SceneView view_;
  const Accel& accel_;
  LtSettings settings_;
  uint64_t seed_;
  SplatFilm splats_;
  uint64_t overflows_ = 0, non_finite_ = 0, passes_ = 0;
};

}  // namespace pathspace
