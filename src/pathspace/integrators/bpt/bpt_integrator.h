// Bidirectional path tracing on the CPU (`--integrator bpt`): a pass traces one light subpath and one
// camera subpath per pixel (bpt_kernel.h), keeps the camera-side estimate per pixel, splats the t = 1
// connections into a fixed-point SplatFilm (deterministic for any thread count), then adds
// camera value + splats to the Film as ONE sample per pixel. Pixels within a pass are correlated
// through the splats; passes are independent (Film::variance_of_mean() stays unbiased).
#pragma once

#include <atomic>
#include <vector>

#include "pathspace/film/splat_film.h"
#include "pathspace/integrators/bpt/bpt_kernel.h"
#include "pathspace/integrators/integrator.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/scene/scene_view.h"

namespace pathspace {

class Accel;
class Scene;

// The path length limit a render with these settings uses (bpt_trace_pixel clamps it to kBptMaxSegments).
inline int bpt_max_segments(const BptSettings& s, const SceneView& view) {
  return s.max_segments > 0 ? s.max_segments : view.max_path_segments;
}

// Host buffers of BPT passes: the t = 1 splats of the current pass, the camera-side values, and the
// optional per-strategy images (sums over all passes so far, fixed point like the splats).
class BptBuffers {
 public:
  BptBuffers(int width, int height, const BptSettings& settings, int max_segments);
  SplatFilm& splats() { return splats_; }
  std::vector<Rgb>& camera() { return camera_; }
  // The films view of the kernels (strategy images included when kept) for the calling worker:
  // the t = 1 splats go to its shard (SplatFilm::worker_view).
  BptFilms worker_films();
  int strategy_max_length() const { return strategy_max_length_; }
  // Sum over passes of strategy (s, t) for one pixel.
  Rgb strategy_sum(int s, int t, uint32_t pixel) const { return strategies_[size_t(bpt_strategy_index(s, t))].value(pixel); }
  uint64_t rejected_strategy_splats() const;
  void hand_over(ProcessGroup& group) {
    for (SplatFilm& f : strategies_) f.hand_over(group);
  }
  void forget_strategies() {
    for (SplatFilm& f : strategies_) f.clear();
  }
  // The per-strategy sums accumulate over passes: they are state of a continued render.
  void save_state(StateWriter& out) const;
  void load_state(StateReader& in);

 private:
  SplatFilm splats_;
  std::vector<Rgb> camera_;
  int strategy_max_length_ = 0;
  std::vector<SplatFilm> strategies_;
  std::vector<SplatFilmView> strategy_views_;
};

// One BPT pass with any Tracer (tests may wrap Accel): traces every pixel's pair of subpaths and adds
// one sample per pixel to `film`. Adds to counters (paths = pixels).
template <typename Tracer>
void bpt_render_pass(const SceneView& view, const Tracer& tracer, const BptSettings& settings, uint64_t seed, uint32_t pass,
                     BptBuffers& buffers, Film& film, PathCounters& counters) {
  constexpr size_t kPixelGrain = 64;
  // The light subpath of a pixel draws from its own stream (top bit of the sample index).
  constexpr uint64_t kLightStream = uint64_t(1) << 63;
  const size_t n = film.pixel_count();
  buffers.splats().clear();
  std::vector<Rgb>& camera = buffers.camera();
  std::atomic<uint64_t> rays{0}, shadow_rays{0}, dropped{0};
  parallel_for(n, kPixelGrain, [&](size_t begin, size_t end) {
    PathCounters local;
    const BptFilms films = buffers.worker_films();
    for (size_t pixel = begin; pixel < end; ++pixel) {
      const Sampler cs(seed, pixel, pass), ls(seed, pixel, kLightStream | pass);
      Rgb v = bpt_trace_pixel(view, tracer, cs, ls, settings, uint32_t(pixel), films, &local);
      if (!all_finite(v)) {
        ++local.dropped;
        v = Rgb();
      }
      camera[pixel] = v;
    }
    rays += local.rays;
    shadow_rays += local.shadow_rays;
    dropped += local.dropped;
  });
  buffers.splats().merge_workers();
  const SplatFilm& splats = buffers.splats();
  parallel_for(n, 4096, [&](size_t begin, size_t end) {
    for (size_t pixel = begin; pixel < end; ++pixel) film.add_sample(uint32_t(pixel), camera[pixel] + splats.value(uint32_t(pixel)));
  });
  counters.rays += rays;
  counters.shadow_rays += shadow_rays;
  counters.paths += n;
  counters.dropped += dropped + splats.non_finite() + splats.overflows();
}

class BptIntegrator final : public Integrator {
 public:
  BptIntegrator(const Scene& scene, const Accel& accel, const BptSettings& settings, uint64_t seed);
  const char* name() const override { return "bpt"; }
  void render_pass(uint32_t pass, Film& film, PathCounters& counters) override;
  void statistics(Statistics& out) const override;
  void save_state(StateWriter& out) const override;
  void load_state(StateReader& in) override;
  void hand_over(ProcessGroup& group) override { buffers_.hand_over(group); }
  void forget_handed_over() override { buffers_.forget_strategies(); }
  // The strategy images are averages over all passes, wherever they were rendered.
  void skip_pass(uint32_t, size_t) override { ++passes_; }
  // Per-strategy images "bpt-sS-tT" (means over the passes so far) when settings.strategy_images > 0.
  std::vector<NamedImage> aovs() const override;

 private:
  SceneView view_;
  const Accel& accel_;
  BptSettings settings_;
  uint64_t seed_;
  int max_segments_;
  BptBuffers buffers_;
  uint64_t overflows_ = 0, non_finite_ = 0;
  uint32_t passes_ = 0;
};

}  // namespace pathspace
