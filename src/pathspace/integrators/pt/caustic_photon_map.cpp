#include "pathspace/integrators/pt/caustic_photon_map.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/base/log.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace {

CausticSettings caustics_for_scene(const CausticSettings& asked, const SceneView& scene) {
  if (!asked.enabled() || !scene.media.any()) return asked;
  log::warning("the caustic photons (--psf-caustic-photons) do not travel through participating media yet: "
               "filtering without them (docs/media.md)");
  CausticSettings none = asked;
  none.photons_per_pixel = 0.0;
  return none;
}

CausticPhotonMap::CausticPhotonMap(const SceneView& scene, const CausticSettings& settings, int max_segments,
                                   const VertexSelection& selection)
    : scene_(scene),
      max_segments_(max_segments),
      one_bounce_(settings.one_bounce),
      receivers_(selection),
      photons_per_pass_(uint64_t(std::llround(settings.photons_per_pixel * double(scene.camera.width) * double(scene.camera.height)))) {
  const float r0 = settings.initial_radius > 0.f ? settings.initial_radius : settings.radius_fraction * scene.bounds.radius;
  if (!(r0 > 0.f && std::isfinite(r0))) throw Error(fmt::format("caustic photon radius must be positive, not {}", r0));
  if (!(settings.alpha > 0.f && settings.alpha <= 1.f)) throw Error(fmt::format("caustic photon alpha must be in (0, 1], not {}", settings.alpha));
  radius_ = ProgressiveRadius(r0, settings.alpha);
  receivers_.min_roughness = std::max(selection.min_roughness, settings.min_roughness);
}

void CausticPhotonMap::build(const Accel& accel, uint64_t seed, uint32_t pass, PathCounters& counters) {
  const auto start = std::chrono::steady_clock::now();
  const size_t n = size_t(photons_per_pass_);
  const size_t stride = photons_per_path();
  traced_.resize(stride * n);
  std::atomic<uint64_t> rays{0};
  const uint64_t photon_seed = caustic_photon_seed(seed);
  parallel_for(n, 256, [&](size_t begin, size_t end) {
    PathCounters local;
    for (size_t i = begin; i < end; ++i) {
      const Sampler sampler(photon_seed, i, pass);
      trace_caustic_photon(scene_, accel, sampler, max_segments_, receivers_, one_bounce_, &local, &traced_[stride * i]);
    }
    rays += local.rays;
  });
  counters.rays += rays.load();
  index(pass, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

void CausticPhotonMap::PhotonSet::index(const std::vector<CausticPhoton>& traced, size_t kind, size_t stride, float radius,
                                        float cell_radii) {
  const size_t paths = traced.size() / stride;
  // The grid holds the stored photons only (a few in ten of the traced ones): its table, sized by
  // its points, then stays small enough for the caches that every gather's probes go through.
  stored_index.clear();
  for (size_t i = kind; i < traced.size(); i += stride)
    if (traced[i].stored) stored_index.push_back(uint32_t(i));
  grid.build(stored_index.size(), cell_radii * radius, [&](size_t i) { return traced[stored_index[i]].p; });
  // Photons in the grid's record order, so a gather reads each cell's photons from consecutive memory.
  const size_t linked = grid.compacted_records();
  in_cells.resize(linked);
  parallel_for(linked, 4096, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) in_cells[i] = traced[stored_index[grid.record(i).payload]];
  });
  view.grid = grid.view();
  view.photons = in_cells.data();
  view.radius = linked ? radius : 0.f;
  view.inv_area_count = paths ? float(1.0 / (double(kPi) * double(radius) * double(radius) * double(paths))) : 0.f;
}

void CausticPhotonMap::index(uint32_t pass, double trace_seconds) {
  const auto start = std::chrono::steady_clock::now();
  const size_t stride = photons_per_path(), n = traced_.size() / stride;
  const float r = radius_.at(pass);
  caustic_set_.index(traced_, 0, stride, r, 1.f);
  // The one-bounce photons are everywhere: in cells four radii wide (not two) a gather reads one or
  // two cells' consecutive photons more often than up to eight cells' (a pass 2.6x -> 2.4x PT).
  if (one_bounce_) one_bounce_set_.index(traced_, 1, stride, r, 2.f);
  view_.caustic = caustic_set_.view;
  view_.one_bounce = one_bounce_set_.view;
  view_.max_segments = max_segments_;
  view_.receivers = receivers_;
  view_.with_one_bounce = one_bounce_;
  last_radius_ = r;
  photons_ += n;
  stored_ += caustic_set_.grid.compacted_records();
  if (one_bounce_) stored_one_bounce_ += one_bounce_set_.grid.compacted_records();
  seconds_ += trace_seconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void CausticPhotonMap::statistics(Statistics& out) const {
  out.counter("caustics.photons", photons_, "caustic photon paths traced (sec. 2.3)");
  out.counter("caustics.stored", stored_, "photons stored after light -> specular+ -> non-delta");
  if (one_bounce_) out.counter("caustics.stored_one_bounce", stored_one_bounce_, "photons stored after one diffuse bounce");
  out.value("caustics.initial_radius", radius_.initial(), "scene units");
  out.value("caustics.last_radius", last_radius_, "scene units, the last pass of this run");
  out.seconds("caustics.time", seconds_);
}

void CausticPhotonMap::save_state(StateWriter& out) const {
  out.put("caustics.photons", photons_);
  out.put("caustics.stored", stored_);
  if (one_bounce_) out.put("caustics.stored_one_bounce", stored_one_bounce_);
  out.put("caustics.last_radius", last_radius_);
  out.put("caustics.seconds", seconds_);
}

void CausticPhotonMap::load_state(StateReader& in) {
  in.get("caustics.photons", &photons_);
  in.get("caustics.stored", &stored_);
  if (one_bounce_) in.get("caustics.stored_one_bounce", &stored_one_bounce_);
  in.get("caustics.last_radius", &last_radius_);
  in.get("caustics.seconds", &seconds_);
}

}  // namespace pathspace
