// Pixel cache light tracing on the CPU (`--integrator pclt`; PCLT paper sec. 3-5). One render pass =
// one iteration: eye pass (one jittered path per pixel -> at most one ES+D record per pixel, ES+L
// emission, first hits for the visibility shortcuts), cache build (chained hash grid of listing 1
// or the stochastic hash map), light pass (gather + projection into one fixed-point SplatFilm),
// resolve (each pixel's iteration estimate is one film sample). Passes are independent estimates
// with their own Knaus-Zwicker radius, so memory is bounded by the pixel count.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "pathspace/film/splat_film.h"
#include "pathspace/hashgrid/hash_grid.h"
#include "pathspace/hashgrid/stochastic_hash_map.h"
#include "pathspace/integrators/common/progressive_radius.h"
#include "pathspace/integrators/integrator.h"
#include "pathspace/integrators/pclt/pclt_kernel.h"
#include "pathspace/integrators/pclt/pclt_settings.h"
#include "pathspace/scene/scene_view.h"

namespace pathspace {

class Accel;
class Scene;

// Bytes held by the pixel cache and its helpers (statistics(); paper fig. 7).
struct PcltMemory {
  size_t cache = 0;       // the records (capacity)
  size_t map = 0;         // hash grid table + links, or the stochastic table
  size_t eye_output = 0;  // per-pixel eye-pass output the records are compacted from
  size_t visibility = 0;  // z-buffer or planes
  size_t total() const { return cache + map + eye_output + visibility; }
};

class PcltIntegrator final : public Integrator {
 public:
  PcltIntegrator(const Scene& scene, const Accel& accel, const PcltSettings& settings, uint64_t seed);
  const char* name() const override { return "pclt"; }
  void render_pass(uint32_t pass, Film& film, PathCounters& counters) override;
  void statistics(Statistics& out) const override;
  void save_state(StateWriter& out) const override;
  void load_state(StateReader& in) override;

  // Gathering radius of iteration `pass` (0-based), the recurrence of SppmIntegrator::radius.
  float radius(uint32_t pass) { return radius_.at(pass); }
  uint64_t light_paths_per_pass() const { return light_paths_; }
  size_t capacity() const { return capacity_; }
  // The records of the last iteration (tests: at most one per pixel, ES+D only).
  const PixelCacheEntry* records() const { return cache_.data(); }
  size_t record_count() const { return record_count_; }
  // ES+D candidates of the last iteration before the capacity limit.
  size_t candidate_count() const { return candidates_; }
  PcltMemory memory() const;

 private:
  void build_cache(uint32_t pass, float r);

  SceneView view_;
  const Accel& accel_;
  PcltSettings s_;
  uint64_t seed_;
  ProgressiveRadius radius_;
  uint64_t light_paths_ = 0;
  int max_segments_ = 0;
  size_t capacity_ = 0;

  SplatFilm splats_;
  std::vector<PixelCacheEntry> staging_;  // per pixel eye-pass output
  std::vector<uint8_t> stored_;           // per pixel: staging_ holds an ES+D record
  std::vector<PixelCacheEntry> cache_;    // capacity_ records
  size_t record_count_ = 0, candidates_ = 0;
  std::vector<uint64_t> priorities_;      // stochastic store scratch
  std::vector<float> zbuffer_;
  std::vector<Vec3> plane_p_, plane_n_;
  HashGrid grid_;
  std::unique_ptr<StochasticHashMap> stochastic_;

  // Totals for statistics().
  uint64_t passes_ = 0, eye_paths_ = 0, light_path_total_ = 0, records_total_ = 0, candidates_total_ = 0,
           dropped_total_ = 0, gather_queries_ = 0, gathered_ = 0, projections_ = 0, visibility_tests_ = 0,
           grid_failures_ = 0, splat_rejects_ = 0;
  size_t max_records_ = 0;
  double eye_s_ = 0, build_s_ = 0, light_s_ = 0, resolve_s_ = 0;
  float last_radius_ = 0.f;
};

}  // namespace pathspace
