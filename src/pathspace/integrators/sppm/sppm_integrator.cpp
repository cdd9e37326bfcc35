// SPPM host orchestration (sppm_integrator.h): the four phases of one iteration, each a
// parallel_for whose result does not depend on the thread count (visible point i belongs to pixel
// i; flux is summed in fixed point, which is associative).
#include "pathspace/integrators/sppm/sppm_integrator.h"

#include <fmt/format.h>

#include <atomic>
#include <chrono>
#include <cmath>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/integrators/common/camera_sample.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/parallel/parallel_sort.h"
#include "pathspace/scene/scene.h"

namespace pathspace {

namespace {
constexpr size_t kPixelGrain = 256;
constexpr size_t kPhotonGrain = 256;
// Photons traced and then deposited together: their hits (about 1.8 per photon, 40 bytes each)
// stay within tens of megabytes whatever the photon count.
constexpr uint64_t kPhotonBatch = uint64_t(1) << 18;
// Separates the photon random stream from the camera stream (both are indexed from 0).
constexpr uint64_t kPhotonStream = 0x70686f746f6e73ULL;

struct SharedCounters {
  std::atomic<uint64_t> rays{0}, dropped{0}, deposits{0}, gathered{0}, points{0};
  void add(const PathCounters& c) {
    rays += c.rays;
    dropped += c.dropped;
  }
};

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}
}  // namespace

SppmIntegrator::SppmIntegrator(const Scene& scene, const Accel& accel, const SppmSettings& settings, uint64_t seed)
    : view_(scene.view()), accel_(accel), settings_(settings), seed_(seed) {
  const SppmSettings& s = settings;
  if (!(s.alpha > 0.f && s.alpha <= 1.f)) throw Error(fmt::format("SPPM alpha must be in (0, 1], not {}", s.alpha));
  const size_t pixels = size_t(scene.camera.width) * size_t(scene.camera.height);
  const float r0 = s.initial_radius > 0.f ? s.initial_radius : s.radius_fraction * view_.bounds.radius;
  if (!(r0 > 0.f && std::isfinite(r0))) throw Error(fmt::format("SPPM initial radius must be positive, not {}", r0));
  radius_ = ProgressiveRadius(r0, s.alpha);
  photons_ = s.photons > 0 ? s.photons : pixels;
  max_segments_ = s.max_segments > 0 ? s.max_segments : view_.max_path_segments;
  reference_power_ = max_photon_power(view_);
  points_.resize(pixels);
  direct_.resize(pixels);
  flux_.resize(3 * pixels);
}

void SppmIntegrator::render_pass(uint32_t pass, Film& film, PathCounters& counters) {
  const size_t n = film.pixel_count();
  const SppmSettings& s = settings_;
  const float r = radius(pass);
  last_radius_ = r;
  SharedCounters shared;

  // (a) Eye pass: one jittered camera path per pixel to its visible point. In a scene that moves, the
  // pass's eye paths and photons share one time (pass_time), so photons meet the visible points of
  // the same instant; the passes average over the shutter.
  const float time = pass_time(view_, seed_, pass);
  auto t = std::chrono::steady_clock::now();
  parallel_for(n, kPixelGrain, [&](size_t begin, size_t end) {
    PathCounters local;
    uint64_t points = 0;
    for (size_t pixel = begin; pixel < end; ++pixel) {
      const Sampler sampler(seed_, pixel, pass);
      sppm_trace_eye(view_, accel_, sampler, sample_camera_ray(view_, sampler, uint32_t(pixel), time), s, max_segments_, &local, &direct_[pixel],
                     &points_[pixel]);
      points += points_[pixel].valid;
      flux_[3 * pixel] = flux_[3 * pixel + 1] = flux_[3 * pixel + 2] = 0;
    }
    shared.add(local);
    shared.points += points;
  });
  eye_s_ += seconds_since(t);

  // (b) Hash grid over this iteration's visible points, cells 2r, built with record i = pixel i
  // (pixels without a visible point have no position and are skipped) and compacted cell by cell
  // so that the photon pass reads each cell's points from consecutive memory.
  t = std::chrono::steady_clock::now();
  const Vec3 no_point(NAN, NAN, NAN);
  grid_.build(n, r, [&](size_t pixel) { return points_[pixel].valid ? points_[pixel].p : no_point; });
  const HashGridView grid = grid_.view();
  const size_t linked = grid_.compacted_records();
  cell_points_.resize(linked);
  cell_flux_.assign(3 * linked, 0);
  parallel_for(linked, kPixelGrain, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) cell_points_[i] = points_[grid_.record(i).payload];
  });
  const HashGridStats gs = grid_.stats();
  grid_failures_ += gs.probe_failures + (gs.dropped - (n - size_t(shared.points)));
  grid_s_ += seconds_since(t);

  // (c) Photon pass.
  t = std::chrono::steady_clock::now();
  SppmGatherView gather;
  gather.grid = grid;
  gather.points = cell_points_.data();
  gather.flux = cell_flux_.data();
  gather.radius = r;
  gather.inv_quantum = reference_power_ > 0.f ? float(kFluxFixedScale / double(reference_power_)) : 0.f;
  gather.max_segments = max_segments_;
  if (reference_power_ > 0.f) {
    for (uint64_t first = 0; first < photons_; first += kPhotonBatch) {
      PathCounters walks;
      PhotonCounters deposited;
      trace_and_deposit_photons(pass, first, std::min<uint64_t>(kPhotonBatch, photons_ - first), gather, &walks, &deposited);
      shared.add(walks);
      shared.deposits += deposited.deposits;
      shared.gathered += deposited.gathered;
    }
  }
  // Back from record order to pixels (each pixel has at most one record).
  parallel_for(linked, kPixelGrain, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i)
      for (int c = 0; c < 3; ++c) flux_[3 * size_t(grid_.record(i).payload) + c] = cell_flux_[3 * i + c];
  });
  photon_s_ += seconds_since(t);

  // (d) Resolve: L = direct + tau * sum(f Phi) / (pi r^2 N), one film sample per pixel.
  t = std::chrono::steady_clock::now();
  const double to_radiance = double(reference_power_) / kFluxFixedScale / (double(kPi) * double(r) * double(r) * double(photons_));
  parallel_for(n, kPixelGrain, [&](size_t begin, size_t end) {
    uint64_t dropped = 0;
    for (size_t pixel = begin; pixel < end; ++pixel) {
      Rgb value = direct_[pixel];
      const VisiblePoint& vp = points_[pixel];
      if (vp.valid) {
        for (int c = 0; c < 3; ++c)
          value[c] += float(double(vp.throughput[c]) * double(flux_[3 * pixel + c]) * to_radiance);
      }
      if (!all_finite(value)) {
        ++dropped;
        value = Rgb();
      }
      film.add_sample(uint32_t(pixel), value);
    }
    shared.dropped += dropped;
  });
  resolve_s_ += seconds_since(t);

  counters.rays += shared.rays;
  counters.dropped += shared.dropped;
  counters.paths += n + photons_;
  ++passes_;
  eye_paths_ += n;
  photon_paths_ += photons_;
  visible_points_ += shared.points;
  deposits_ += shared.deposits;
  gathered_ += shared.gathered;
}

// Photons in two steps: the walks first, keeping their non-delta hits, then the deposits in the
// Morton order of the hits' grid cells. Traced in photon order, consecutive deposits land anywhere
// in the scene and each one misses the cache for its cells' slots, records and visible points
// (most of a pass's time at SPPM's default radius); sorted, consecutive deposits share their
// cells. The flux sums are integers, so the order of deposits changes no bit of the image.
void SppmIntegrator::trace_and_deposit_photons(uint32_t pass, uint64_t first, uint64_t count, const SppmGatherView& gather,
                                               PathCounters* counters, PhotonCounters* photons) {
  const uint64_t photon_seed = seed_ ^ kPhotonStream;
  const float time = pass_time(view_, seed_, pass);  // the eye pass's (trace_pass)
  const size_t chunks = size_t((count + kPhotonGrain - 1) / kPhotonGrain);
  if (chunk_hits_.size() < chunks) chunk_hits_.resize(chunks);
  std::atomic<uint64_t> rays{0};
  parallel_for(chunks, 1, [&](size_t c0, size_t c1) {
    PathCounters local;
    for (size_t c = c0; c < c1; ++c) {
      std::vector<PhotonHit>& hits = chunk_hits_[c];
      hits.clear();
      const uint64_t end = std::min(first + count, first + (c + 1) * kPhotonGrain);
      for (uint64_t i = first + c * kPhotonGrain; i < end; ++i)
        sppm_walk_photon(view_, accel_, Sampler(photon_seed, i, pass), settings_, max_segments_, time, &local,
                         [&](const PhotonHit& h) { hits.push_back(h); });
    }
    rays += local.rays;
  });
  counters->rays += rays;
  std::vector<size_t> offset(chunks + 1, 0);
  for (size_t c = 0; c < chunks; ++c) offset[c + 1] = offset[c] + chunk_hits_[c].size();
  const size_t total = offset[chunks];
  hits_.resize(total);
  hit_order_.resize(total);
  const GridGeometry& geometry = gather.grid.geometry;
  parallel_for(chunks, 1, [&](size_t c0, size_t c1) {
    for (size_t c = c0; c < c1; ++c)
      for (size_t k = 0; k < chunk_hits_[c].size(); ++k) {
        const size_t i = offset[c] + k;
        hits_[i] = chunk_hits_[c][k];
        hit_order_[i] = {morton_cell_order(geometry.cell_of(hits_[i].p)), uint32_t(i)};
      }
  });
  parallel_sort(hit_order_.begin(), hit_order_.end());
  std::atomic<uint64_t> gathered{0};
  parallel_for(total, kPhotonGrain, [&](size_t begin, size_t end) {
    uint64_t local = 0;
    for (size_t i = begin; i < end; ++i) {
      const PhotonHit& h = hits_[hit_order_[i].second];
      local += sppm_deposit(view_, gather, h.p, h.wi, h.power, int(h.segments));
    }
    gathered += local;
  });
  photons->deposits += total;
  photons->gathered += gathered;
}

void SppmIntegrator::statistics(Statistics& out) const {
  const double passes = double(std::max<uint64_t>(1, passes_));
  out.counter("sppm.iterations", passes_);
  out.counter("sppm.eye_paths", eye_paths_);
  out.counter("sppm.photons", photon_paths_);
  out.counter("sppm.photons_per_iteration", photons_);
  out.value("sppm.initial_radius", radius_.initial(), "scene units");
  out.value("sppm.last_radius", last_radius_, "scene units");
  out.ratio("sppm.visible_point_fraction", eye_paths_ ? double(visible_points_) / double(eye_paths_) : 0.0,
            "pixels with a visible point");
  out.value("sppm.photon_vertices_per_iteration", double(deposits_) / passes);
  out.value("sppm.gathers_per_iteration", double(gathered_) / passes);
  out.counter("sppm.grid_failures", grid_failures_, "visible points not stored in the hash grid");
  out.seconds("sppm.eye_s", eye_s_);
  out.seconds("sppm.grid_s", grid_s_);
  out.seconds("sppm.photon_s", photon_s_);
  out.seconds("sppm.resolve_s", resolve_s_);
}

// The radius recurrence and the totals; the per-iteration buffers are rebuilt every pass.
void SppmIntegrator::save_state(StateWriter& out) const {
  radius_.save_state(out, "sppm");
  out.put("sppm.last_radius", last_radius_);
  const uint64_t counts[] = {passes_, eye_paths_, photon_paths_, visible_points_, deposits_, gathered_, grid_failures_};
  const double times[] = {eye_s_, grid_s_, photon_s_, resolve_s_};
  out.put("sppm.counts", counts);
  out.put("sppm.times", times);
}

void SppmIntegrator::load_state(StateReader& in) {
  radius_.load_state(in, "sppm");
  in.get("sppm.last_radius", &last_radius_);
  uint64_t counts[7];
  double times[4];
  in.get("sppm.counts", &counts);
  in.get("sppm.times", &times);
  passes_ = counts[0], eye_paths_ = counts[1], photon_paths_ = counts[2], visible_points_ = counts[3];
  deposits_ = counts[4], gathered_ = counts[5], grid_failures_ = counts[6];
  eye_s_ = times[0], grid_s_ = times[1], photon_s_ = times[2], resolve_s_ = times[3];
}

}  // namespace pathspace
