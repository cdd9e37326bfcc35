#include "pathspace/integrators/pt/caustic_photon_map.h"

#include <atomic>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace {

namespace {
// Separates the photons' random stream from the camera paths' (both are indexed from 0).
constexpr uint64_t kCausticStream = 0x636175737469637aull;
}  // namespace

CausticPhotonMap::CausticPhotonMap(const SceneView& scene, const CausticSettings& settings, int max_segments)
    : scene_(scene),
      max_segments_(max_segments),
      photons_per_pass_(uint64_t(std::llround(settings.photons_per_pixel * double(scene.camera.width) * double(scene.camera.height)))) {
  const float r0 = settings.initial_radius > 0.f ? settings.initial_radius : settings.radius_fraction * scene.bounds.radius;
  if (!(r0 > 0.f && std::isfinite(r0))) throw Error(fmt::format("caustic photon radius must be positive, not {}", r0));
  if (!(settings.alpha > 0.f && settings.alpha <= 1.f)) throw Error(fmt::format("caustic photon alpha must be in (0, 1], not {}", settings.alpha));
  radius_ = ProgressiveRadius(r0, settings.alpha);
}

void CausticPhotonMap::build(const Accel& accel, uint64_t seed, uint32_t pass, PathCounters& counters) {
  const auto start = std::chrono::steady_clock::now();
  const size_t n = size_t(photons_per_pass_);
  traced_.resize(n);
  std::atomic<uint64_t> rays{0};
  const uint64_t photon_seed = seed ^ kCausticStream;
  parallel_for(n, 256, [&](size_t begin, size_t end) {
    PathCounters local;
    for (size_t i = begin; i < end; ++i) {
      const Sampler sampler(photon_seed, i, pass);
      trace_caustic_photon(scene_, accel, sampler, max_segments_, &local, &traced_[i]);
    }
    rays += local.rays;
  });
  counters.rays += rays.load();
  const float r = radius_.at(pass);
  const Vec3 nowhere(NAN, NAN, NAN);
  grid_.build(n, r, [&](size_t i) { return traced_[i].stored ? traced_[i].p : nowhere; });
  // Photons in the grid's record order, so a gather reads each cell's photons from consecutive memory.
  const size_t linked = grid_.compacted_records();
  in_cells_.resize(linked);
  parallel_for(linked, 4096, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) in_cells_[i] = traced_[grid_.record(i).payload];
  });
  view_.grid = grid_.view();
  view_.photons = in_cells_.data();
  view_.radius = linked ? r : 0.f;
  view_.inv_area_count = n ? float(1.0 / (double(kPi) * double(r) * double(r) * double(n))) : 0.f;
  view_.max_segments = max_segments_;
  last_radius_ = r;
  photons_ += n;
  stored_ += linked;
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void CausticPhotonMap::statistics(Statistics& out) const {
  out.counter("caustics.photons", photons_, "caustic photon paths traced (sec. 2.3)");
  out.counter("caustics.stored", stored_, "photons stored after light -> specular+ -> non-delta");
  out.value("caustics.initial_radius", radius_.initial(), "scene units");
  out.value("caustics.last_radius", last_radius_, "scene units, the last pass of this run");
  out.seconds("caustics.time", seconds_);
}

void CausticPhotonMap::save_state(StateWriter& out) const {
  out.put("caustics.photons", photons_);
  out.put("caustics.stored", stored_);
  out.put("caustics.last_radius", last_radius_);
  out.put("caustics.seconds", seconds_);
}

void CausticPhotonMap::load_state(StateReader& in) {
  in.get("caustics.photons", &photons_);
  in.get("caustics.stored", &stored_);
  in.get("caustics.last_radius", &last_radius_);
  in.get("caustics.seconds", &seconds_);
}

}  // namespace pathspace
