// The caustic photon map of the path tracer (Keller, Dahm, Binder 2014, sec. 2.3; kernel in
// caustic_photons.h): per pass, N photon paths from the lights, the caustic photons among them in a
// hash grid with the pass's radius, and with CausticSettings::one_bounce the photons after one
// diffuse bounce in a second grid. The radius shrinks with the pass index as in progressive photon
// mapping (common/progressive_radius.h, as SPPM and PCLT), so the caustics converge as the filter's
// radius does; it is a function of the pass index only, so a resumed render continues it.
#pragma once

#include <cstdint>
#include <vector>

#include "pathspace/base/state_archive.h"
#include "pathspace/filters/caustic_settings.h"
#include "pathspace/hashgrid/hash_grid.h"
#include "pathspace/integrators/common/progressive_radius.h"
#include "pathspace/integrators/pt/caustic_photons.h"
#include "pathspace/scene/scene_view.h"
#include "pathspace/stats/statistics.h"

namespace pathspace {

class Accel;

// The caustic photons a filter asked for, as the scene allows them: none in a scene with
// participating media (they do not travel through media yet; docs/media.md), with a warning. A
// filter's default turns them on, so refusing them would refuse every filtered render of such a scene.
CausticSettings caustics_for_scene(const CausticSettings& asked, const SceneView& scene);

class CausticPhotonMap {
 public:
  // selection: the camera paths' vertex selection (where photons are stored: caustic_photons.h).
  CausticPhotonMap(const SceneView& scene, const CausticSettings& settings, int max_segments, const VertexSelection& selection);
  // The vertices that gather and store photons (CausticMapView::receivers).
  const VertexSelection& receivers() const { return receivers_; }

  // Traces the pass's photons and builds the map; the view stays valid until the next build.
  void build(const Accel& accel, uint64_t seed, uint32_t pass, PathCounters& counters);
  // The two halves of build() for a caller that traces the photons elsewhere (the GPU path tracer,
  // gpu/cuda_caustic_map.h): photon path i of the pass from Sampler(caustic_photon_seed(seed), i,
  // pass) into traced_photons()[photons_per_path() * i] on, then index() builds the same map as
  // build() would.
  uint64_t photons_per_pass() const { return photons_per_pass_; }
  int max_segments() const { return max_segments_; }
  bool one_bounce() const { return one_bounce_; }
  // Slots per photon path in traced_photons(): its caustic photon, and its one-bounce photon if asked for.
  size_t photons_per_path() const { return caustic_photons_per_path(one_bounce_); }
  std::vector<CausticPhoton>& traced_photons() {
    traced_.resize(photons_per_path() * size_t(photons_per_pass_));
    return traced_;
  }
  void index(uint32_t pass, double trace_seconds);
  const CausticMapView& view() const { return view_; }
  // The grids of the two kinds (the second empty without one-bounce photons).
  const HashGrid& caustic_grid() const { return caustic_set_.grid; }
  const HashGrid& one_bounce_grid() const { return one_bounce_set_.grid; }
  void statistics(Statistics& out) const;
  // The totals behind the statistics (the radius follows from the pass index).
  void save_state(StateWriter& out) const;
  void load_state(StateReader& in);

 private:
  // The stored photons of one kind (traced_[stride i + kind]) in a grid, in the grid's record order.
  struct PhotonSet {
    // Most caustic gathers land where no caustic falls: an occupancy bitmap (8 bits per slot, a few
    // tens of KiB) answers them without a cache miss in the slot table.
    HashGrid grid{HashGridConfig{.occupancy_bits_per_slot = 8}};
    std::vector<CausticPhoton> in_cells;
    std::vector<uint32_t> stored_index;  // of traced_, in order
    PhotonSetView view;
    // cell_radii: the grid's cells are built for a radius this many times the gather radius.
    void index(const std::vector<CausticPhoton>& traced, size_t kind, size_t stride, float radius, float cell_radii);
  };

  SceneView scene_;
  int max_segments_;
  bool one_bounce_;
  VertexSelection receivers_;
  uint64_t photons_per_pass_;
  ProgressiveRadius radius_;
  std::vector<CausticPhoton> traced_;  // photons_per_path() per photon path
  PhotonSet caustic_set_, one_bounce_set_;
  CausticMapView view_;
  uint64_t photons_ = 0, stored_ = 0, stored_one_bounce_ = 0;
  float last_radius_ = 0.f;
  double seconds_ = 0.0;
};

}  // namespace pathspace
