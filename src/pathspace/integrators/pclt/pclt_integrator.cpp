// PCLT host orchestration (pclt_integrator.h): the phases of one iteration, each a parallel_for
// whose result does not depend on the thread count (pixel i writes slot i; records are compacted in
// pixel order; gathers and projections are summed in fixed point, which is associative).
#include "pathspace/integrators/pclt/pclt_integrator.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/base/log.h"
#include "pathspace/integrators/common/camera_sample.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/scene/scene.h"

namespace pathspace {

namespace {
constexpr size_t kPixelGrain = 256;
constexpr size_t kPathGrain = 256;
// Separates the light-path random stream from the camera stream (both are indexed from 0).
constexpr uint64_t kLightStream = 0x70636c746c696768ULL;
constexpr uint64_t kStoreStream = 0x70636c7473746f72ULL;

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}
}  // namespace

PcltIntegrator::PcltIntegrator(const Scene& scene, const Accel& accel, const PcltSettings& settings, uint64_t seed)
    : view_(scene.view()), accel_(accel), s_(settings), seed_(seed),
      splats_(scene.camera.width, scene.camera.height, settings.splat_scale > 0.0 ? settings.splat_scale : SplatFilm::kDefaultScale) {
  if (!(s_.alpha > 0.f && s_.alpha <= 1.f)) throw Error(fmt::format("PCLT alpha must be in (0, 1], not {}", s_.alpha));
  if (!(s_.epsilon >= 0.f && s_.epsilon < 1.f)) throw Error(fmt::format("pclt epsilon {} must be in [0, 1)", s_.epsilon));
  // The z-buffer and plane shortcuts (sec. 5.3) compare with the first hit of one camera ray per
  // pixel, i.e. they assume every projection goes through the same pinhole. With a thin lens each
  // projection has its own lens point and a pixel sees a blend of surfaces, so those tests would be
  // wrong, not just approximate: fall back to the shadow ray towards the sampled lens point.
  if (s_.visibility != PcltVisibility::shadow_ray && !scene.camera.is_pinhole()) {
    log::warning("pclt: the {} visibility shortcut assumes a pinhole camera; using shadow rays with the thin lens",
                 s_.visibility == PcltVisibility::z_buffer ? "z-buffer" : "plane");
    s_.visibility = PcltVisibility::shadow_ray;
  }
  const size_t pixels = size_t(scene.camera.width) * size_t(scene.camera.height);
  const float r0 = s_.initial_radius > 0.f ? s_.initial_radius : s_.radius_fraction * view_.bounds.radius;
  if (!(r0 > 0.f && std::isfinite(r0))) throw Error(fmt::format("PCLT initial radius must be positive, not {}", r0));
  radius_ = ProgressiveRadius(r0, s_.alpha);
  light_paths_ = s_.light_paths > 0 ? s_.light_paths : pixels;
  max_segments_ = s_.max_segments > 0 ? s_.max_segments : view_.max_path_segments;
  // At most one record per pixel, so a capacity above the pixel count would never be used.
  capacity_ = s_.cache_capacity > 0 ? std::min<size_t>(size_t(s_.cache_capacity), pixels) : pixels;
  cache_.resize(capacity_);
  staging_.resize(pixels);
  stored_.resize(pixels);
  if (s_.visibility == PcltVisibility::z_buffer) zbuffer_.resize(pixels);
  if (s_.visibility == PcltVisibility::plane) {
    plane_p_.resize(pixels);
    plane_n_.resize(pixels);
  }
  if (s_.hash_map == PcltHashMap::stochastic) {
    const size_t slots = s_.stochastic_slots > 0 ? size_t(s_.stochastic_slots) : std::bit_ceil(std::max<size_t>(capacity_, 16));
    if (!std::has_single_bit(slots) || slots > (size_t(1) << 31))
      throw Error(fmt::format("pclt stochastic hash map slots {} must be a power of two up to 2^31", slots));
    stochastic_ = std::make_unique<StochasticHashMap>(slots);
  }
}

PcltMemory PcltIntegrator::memory() const {
  PcltMemory m;
  m.cache = cache_.capacity() * sizeof(PixelCacheEntry);
  m.map = stochastic_ ? stochastic_->stats().bytes : grid_.stats().bytes;
  m.eye_output = staging_.capacity() * sizeof(PixelCacheEntry) + stored_.capacity();
  m.visibility = zbuffer_.capacity() * sizeof(float) + (plane_p_.capacity() + plane_n_.capacity()) * sizeof(Vec3);
  return m;
}

// Compacts this iteration's ES+D records into the cache (pixel order) and builds the search map.
void PcltIntegrator::build_cache(uint32_t pass, float r) {
  const size_t n = stored_.size();
  size_t candidates = 0;
  for (size_t i = 0; i < n; ++i) candidates += stored_[i];
  candidates_ = candidates;
  size_t count = 0;
  if (candidates <= capacity_) {
    for (size_t i = 0; i < n && count < capacity_; ++i)
      if (stored_[i]) cache_[count++] = staging_[i];
  } else if (s_.stochastic_store) {
    // A uniform subset of exactly capacity_ candidates: the capacity_ smallest hash priorities
    // (a pure function of seed, pass and pixel). Each candidate is kept with probability C/N, so
    // scaling the kept weights by N/C keeps the estimate unbiased.
    priorities_.clear();
    const uint64_t seed = hash_combine(seed_ ^ kStoreStream, pass);
    for (size_t i = 0; i < n; ++i)
      if (stored_[i]) priorities_.push_back((hash_combine(seed, i) & 0xffffffff00000000ull) | uint64_t(i));
    std::nth_element(priorities_.begin(), priorities_.begin() + std::ptrdiff_t(capacity_ - 1), priorities_.end());
    const uint64_t threshold = priorities_[capacity_ - 1];
    const float scale = float(double(candidates) / double(capacity_));
    for (size_t i = 0; i < n; ++i) {
      if (!stored_[i] || ((hash_combine(seed, i) & 0xffffffff00000000ull) | uint64_t(i)) > threshold) continue;
      cache_[count] = staging_[i];
      cache_[count++].weight *= scale;
    }
  } else {
    for (size_t i = 0; i < n && count < capacity_; ++i)
      if (stored_[i]) cache_[count++] = staging_[i];
  }
  record_count_ = count;
  dropped_total_ += candidates - count;
  auto position_of = [&](size_t i) { return cache_[i].p; };
  if (stochastic_) {
    stochastic_->build(count, r, hash_combine(seed_ ^ kStoreStream, ~uint64_t(pass)), position_of);
    grid_failures_ += stochastic_->stats().dropped;
  } else {
    grid_.build(count, r, position_of);
    const HashGridStats gs = grid_.stats();
    grid_failures_ += gs.probe_failures + gs.dropped;
  }
}

void PcltIntegrator::render_pass(uint32_t pass, Film& film, PathCounters& counters) {
  const size_t n = film.pixel_count();
  const float r = radius(pass);
  last_radius_ = r;
  splats_.clear();
  std::atomic<uint64_t> rays{0}, shadow_rays{0};

  // (a) Eye pass. In a scene that moves, the pass's eye and light paths share one time (pass_time):
  // the pixel cache and the visibility buffers hold that instant.
  const float time = pass_time(view_, seed_, pass);
  auto t = std::chrono::steady_clock::now();
  parallel_for(n, kPixelGrain, [&](size_t begin, size_t end) {
    PathCounters local;
    const SplatFilmView sv = splats_.worker_view();
    for (size_t pixel = begin; pixel < end; ++pixel) {
      const Sampler sampler(seed_, pixel, pass);
      PcltEyeResult eye;
      pclt_trace_eye(view_, accel_, sampler, sample_camera_ray(view_, sampler, uint32_t(pixel), time), uint32_t(pixel), s_,
                     max_segments_, &local, &eye);
      stored_[pixel] = eye.stored;
      if (eye.stored) staging_[pixel] = eye.entry;
      if (!is_black(eye.direct)) sv.add(uint32_t(pixel), eye.direct);
      if (!zbuffer_.empty()) zbuffer_[pixel] = eye.has_first_hit ? eye.first_depth : kInfinity;
      if (!plane_p_.empty()) {
        plane_p_[pixel] = eye.first_p;
        plane_n_[pixel] = eye.has_first_hit ? eye.first_n : Vec3();
      }
    }
    rays += local.rays;
  });
  eye_s_ += seconds_since(t);

  // (b) Cache and search structure.
  t = std::chrono::steady_clock::now();
  build_cache(pass, r);
  build_s_ += seconds_since(t);

  // (c) Light pass.
  t = std::chrono::steady_clock::now();
  PcltLightView lv;  // lv.film: each worker's own (below)
  lv.visibility = s_.visibility;
  lv.epsilon = s_.epsilon;
  lv.zbuffer = zbuffer_.data();
  lv.plane_p = plane_p_.data();
  lv.plane_n = plane_n_.data();
  lv.hash_map = s_.hash_map;
  if (stochastic_) lv.stochastic = stochastic_->view();
  else lv.grid = grid_.view();
  lv.entries = cache_.data();
  lv.entry_count = uint32_t(record_count_);
  lv.radius = r;
  lv.gather_scale = float(1.0 / (double(kPi) * double(r) * double(r) * double(light_paths_)));
  lv.inv_paths = float(1.0 / double(light_paths_));
  lv.max_segments = max_segments_;
  lv.time = time;
  const uint64_t light_seed = seed_ ^ kLightStream;
  std::atomic<uint64_t> queries{0}, gathered{0}, projections{0}, tests{0};
  parallel_for(size_t(light_paths_), kPathGrain, [&](size_t begin, size_t end) {
    PathCounters local;
    PcltLightCounters lc;
    PcltLightView worker_lv = lv;
    worker_lv.film = splats_.worker_view();
    for (size_t i = begin; i < end; ++i) pclt_trace_light(view_, accel_, Sampler(light_seed, i, pass), s_, worker_lv, &local, &lc);
    rays += local.rays;
    shadow_rays += local.shadow_rays;
    queries += lc.gather_queries;
    gathered += lc.gathered;
    projections += lc.projections;
    tests += lc.visibility_tests;
  });
  light_s_ += seconds_since(t);

  // (d) Resolve: every pixel's iteration estimate is one film sample.
  t = std::chrono::steady_clock::now();
  splats_.merge_workers();
  splats_.resolve_into(film);
  resolve_s_ += seconds_since(t);

  const uint64_t rejected = splats_.non_finite() + splats_.overflows();
  counters.rays += rays;
  counters.shadow_rays += shadow_rays;
  counters.paths += n + light_paths_;
  counters.dropped += rejected;
  ++passes_;
  eye_paths_ += n;
  light_path_total_ += light_paths_;
  records_total_ += record_count_;
  candidates_total_ += candidates_;
  max_records_ = std::max(max_records_, record_count_);
  gather_queries_ += queries;
  gathered_ += gathered;
  projections_ += projections;
  visibility_tests_ += tests;
  splat_rejects_ += rejected;
}

void PcltIntegrator::statistics(Statistics& out) const {
  const char* visibility[] = {"shadow-ray", "z-buffer", "plane"};
  const PcltMemory m = memory();
  const double passes = double(std::max<uint64_t>(1, passes_));
  const double total_s = eye_s_ + build_s_ + light_s_ + resolve_s_;
  out.counter("pclt.iterations", passes_);
  out.counter("pclt.eye_paths", eye_paths_);
  out.counter("pclt.light_paths", light_path_total_);
  out.counter("pclt.light_paths_per_iteration", light_paths_);
  out.value("pclt.initial_radius", radius_.initial(), "scene units");
  out.value("pclt.last_radius", last_radius_, "scene units");
  out.text("pclt.visibility", visibility[int(s_.visibility)]);
  out.text("pclt.hash_map", s_.hash_map == PcltHashMap::chained ? "chained" : "stochastic");
  out.ratio("pclt.cache_fill", eye_paths_ ? double(records_total_) / double(eye_paths_) : 0.0,
            "pixels with an ES+D record per iteration");
  out.counter("pclt.max_records", max_records_);
  out.counter("pclt.capacity", capacity_);
  out.counter("pclt.candidates_dropped", dropped_total_, s_.stochastic_store ? "stochastic store, reweighted" : "cache full");
  out.bytes("pclt.memory_bytes", m.total(), "fig. 7");
  out.bytes("pclt.memory_records_bytes", m.cache);
  out.bytes("pclt.memory_map_bytes", m.map);
  out.bytes("pclt.memory_eye_output_bytes", m.eye_output);
  out.bytes("pclt.memory_visibility_bytes", m.visibility);
  out.value("pclt.gather_queries_per_iteration", double(gather_queries_) / passes);
  out.value("pclt.gathered_per_iteration", double(gathered_) / passes);
  out.value("pclt.visibility_tests_per_iteration", double(visibility_tests_) / passes);
  out.value("pclt.projections_per_iteration", double(projections_) / passes);
  out.seconds("pclt.eye_s", eye_s_);
  out.seconds("pclt.build_s", build_s_);
  out.seconds("pclt.light_s", light_s_);
  out.seconds("pclt.resolve_s", resolve_s_);
  out.value("pclt.light_paths_per_s", total_s > 0 ? double(light_path_total_) / total_s : 0.0);
  out.counter("pclt.grid_failures", grid_failures_, "records not stored in the hash map");
  out.counter("pclt.splat_rejects", splat_rejects_, "overflow or non-finite");
}

// The radius recurrence and the totals; the cache and the maps are rebuilt every iteration.
void PcltIntegrator::save_state(StateWriter& out) const {
  radius_.save_state(out, "pclt");
  out.put("pclt.last_radius", last_radius_);
  const uint64_t counts[] = {passes_,          eye_paths_, light_path_total_, records_total_,    candidates_total_, dropped_total_,
                             gather_queries_,  gathered_,  projections_,      visibility_tests_, grid_failures_,    splat_rejects_,
                             uint64_t(max_records_)};
  const double times[] = {eye_s_, build_s_, light_s_, resolve_s_};
  out.put("pclt.counts", counts);
  out.put("pclt.times", times);
}

void PcltIntegrator::load_state(StateReader& in) {
  radius_.load_state(in, "pclt");
  in.get("pclt.last_radius", &last_radius_);
  uint64_t c[13];
  double t[4];
  in.get("pclt.counts", &c);
  in.get("pclt.times", &t);
  passes_ = c[0], eye_paths_ = c[1], light_path_total_ = c[2], records_total_ = c[3], candidates_total_ = c[4];
  dropped_total_ = c[5], gather_queries_ = c[6], gathered_ = c[7], projections_ = c[8], visibility_tests_ = c[9];
  grid_failures_ = c[10], splat_rejects_ = c[11], max_records_ = size_t(c[12]);
  eye_s_ = t[0], build_s_ = t[1], light_s_ = t[2], resolve_s_ = t[3];
}

}  // namespace pathspace
