// Stochastic progressive photon mapping on the CPU (Hachisuka & Jensen 2009) with the Knaus-Zwicker
// global radius update (PCLT paper eq. 1). One render pass = one SPPM iteration: eye pass, hash grid
// over the visible points (PCLT sec. 4), photon pass, resolve. Each iteration is an independent
// estimate with its own radius and the film averages them, so memory is bounded by the pixel count
// whatever the number of iterations.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "pathspace/hashgrid/hash_grid.h"
#include "pathspace/integrators/common/progressive_radius.h"
#include "pathspace/integrators/integrator.h"
#include "pathspace/integrators/sppm/sppm_kernel.h"
#include "pathspace/integrators/sppm/sppm_settings.h"
#include "pathspace/scene/scene_view.h"

namespace pathspace {

class Accel;
class Scene;

class SppmIntegrator final : public Integrator {
 public:
  SppmIntegrator(const Scene& scene, const Accel& accel, const SppmSettings& settings, uint64_t seed);
  const char* name() const override { return "sppm"; }
  void render_pass(uint32_t pass, Film& film, PathCounters& counters) override;
  void statistics(Statistics& out) const override;
  void save_state(StateWriter& out) const override;
  void load_state(StateReader& in) override;

  // Gathering radius of iteration `pass` (0-based): r_0 and r_{i+1} = r_i sqrt((i + alpha) / (i + 1))
  // with the 1-based iteration number i = pass + 1.
  float radius(uint32_t pass) { return radius_.at(pass); }
  float initial_radius() const { return radius_.initial(); }
  uint64_t photons_per_pass() const { return photons_; }

 private:
  void trace_and_deposit_photons(uint32_t pass, uint64_t first, uint64_t count, const SppmGatherView& gather,
                                 PathCounters* counters, PhotonCounters* photons);

  SceneView view_;
  const Accel& accel_;
  SppmSettings settings_;
  uint64_t seed_;
  ProgressiveRadius radius_;
  uint64_t photons_ = 0;
  int max_segments_ = 0;
  float reference_power_ = 0.f;

  std::vector<VisiblePoint> points_;
  std::vector<Rgb> direct_;
  std::vector<uint64_t> flux_;
  std::vector<VisiblePoint> cell_points_;  // visible points in the grid's record order
  std::vector<uint64_t> cell_flux_;        // 3 per record, scattered back to flux_ per pixel
  HashGrid grid_;
  // The photon pass's hits, per chunk of photons as traced, then in one array and its cell order.
  std::vector<std::vector<PhotonHit>> chunk_hits_;
  std::vector<PhotonHit> hits_;
  std::vector<std::pair<uint64_t, uint32_t>> hit_order_;  // (Morton code of the hit's cell, hit)

  // Totals for statistics().
  uint64_t passes_ = 0, eye_paths_ = 0, photon_paths_ = 0, visible_points_ = 0, deposits_ = 0, gathered_ = 0;
  uint64_t grid_failures_ = 0;
  double eye_s_ = 0, grid_s_ = 0, photon_s_ = 0, resolve_s_ = 0;
  float last_radius_ = 0.f;
};

}  // namespace pathspace
