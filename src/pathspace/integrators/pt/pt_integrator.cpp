#include "pathspace/integrators/pt/pt_integrator.h"

#include <algorithm>
#include <atomic>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/common/camera_sample.h"
#include "pathspace/integrators/pt/pt_kernel.h"
#include "pathspace/parallel/cancellable_work.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/sampling/hash.h"
#include "pathspace/scene/scene.h"

namespace pathspace {

namespace {

constexpr size_t kPixelGrain = 256;
// Seeds the samplers of the query-only paths apart from the pass's own paths.
constexpr uint64_t kQueryStreamSalt = 0x5175657279506174ull;

// Sums per-chunk counters into the pass totals (one atomic add per chunk).
struct SharedCounters {
  std::atomic<uint64_t> rays{0}, shadow_rays{0}, dropped{0};
  void add(const PathCounters& c) {
    rays += c.rays;
    shadow_rays += c.shadow_rays;
    dropped += c.dropped;
  }
  void flush(PathCounters& into, size_t paths) const {
    into.rays += rays;
    into.shadow_rays += shadow_rays;
    into.dropped += dropped;
    into.paths += paths;
  }
};

// The camera rays of a chunk of paths are traced together, kCameraBatch at a time, as one coherent
// Embree stream: they start at one point in nearly one direction, and the stream's packets trace
// them in about half the time of one ray after another, with the same hits (docs/benchmarks.md).
// Each path then continues alone (pt_continue_path). ray_of(path) gives a path's camera ray,
// go_on(path, ray, found, hit) continues it.
constexpr size_t kCameraBatch = 64;
template <typename RayOf, typename GoOn>
void trace_from_camera_batches(const Accel& accel, size_t begin, size_t end, const RayOf& ray_of, const GoOn& go_on) {
  Ray rays[kCameraBatch];
  SurfaceHit hits[kCameraBatch];
  bool found[kCameraBatch];
  for (size_t first = begin; first < end; first += kCameraBatch) {
    const uint32_t n = uint32_t(std::min(kCameraBatch, end - first));
    for (uint32_t k = 0; k < n; ++k) rays[k] = ray_of(first + k);
    accel.intersect_batch(rays, hits, found, n, /*coherent=*/true);
    for (uint32_t k = 0; k < n; ++k) go_on(first + k, rays[k], found[k], hits[k]);
  }
}

}  // namespace

PtIntegrator::PtIntegrator(const Scene& scene, const Accel& accel, const PtSettings& settings, uint64_t seed,
                           const FilterChoice& filter, std::shared_ptr<PathSpaceFilter> carried)
    : view_(scene.view()), accel_(accel), settings_(settings), seed_(seed) {
  const size_t pixels = size_t(scene.camera.width) * size_t(scene.camera.height);
  if (carried && filter.active() && filter.name == carried->name()) {
    filter_ = std::move(carried);
    filter_->begin_frame(scene.camera);
  } else {
    filter_ = make_filter(filter, FilterContext{scene.camera, pixels});
  }
  if (filter_) {
    needs_ = filter_->needs();
  } else {
    settings_.selection.mode = VertexSelectionMode::none;  // nothing to split a path for
  }
  if (needs_.visibility) {
    // The visibility weight's probes (2014 paper, sec. 2.1): the first 32 delta lights, and the
    // hemisphere ray when any light is extended.
    for (uint32_t i = 0; i < view_.num_lights; ++i) {
      if (is_delta_light(view_.lights[i])) {
        if (probe_lights_.size() < size_t(kMaxVisibilityLights)) probe_lights_.push_back(i);
      } else {
        probes_.open_ray = true;
      }
    }
    probes_.delta_lights = probe_lights_.data();
    probes_.delta_count = int(probe_lights_.size());
  }
  needs_.caustics = caustics_for_scene(needs_.caustics, view_);
  if (needs_.caustics.enabled())
    caustics_ = std::make_unique<CausticPhotonMap>(view_, needs_.caustics,
                                                   settings_.max_segments > 0 ? settings_.max_segments : view_.max_path_segments,
                                                   settings_.selection);
}

PtIntegrator::~PtIntegrator() = default;

void PtIntegrator::render_pass(uint32_t pass, Film& film, PathCounters& counters) {
  if (filter_) {
    render_filtered(pass, film, counters);
  } else {
    render_plain(pass, film, counters);
  }
}

// One camera path per pixel goes through the filter in every pass.
void PtIntegrator::skip_pass(uint32_t, size_t pixels) {
  if (filter_) filter_->skip_pass(pixels);
}

const VertexBuffer& PtIntegrator::vertex_buffer() const {
  static const VertexBuffer kNone;
  return filter_ ? filter_->workspace().paths : kNone;
}

std::string PtIntegrator::distribution_limit() const { return filter_ ? filter_->distribution_limit() : std::string(); }

void PtIntegrator::render_plain(uint32_t pass, Film& film, PathCounters& counters) {
  const size_t n = film.pixel_count();
  SharedCounters shared;
  parallel_for(n, kPixelGrain, [&](size_t begin, size_t end) {
    PathCounters local;
    PathSample sample;
    const auto ray_of = [&](size_t pixel) {
      const Sampler sampler(seed_, pixel, pass);
      return sample_camera_ray(view_, sampler, uint32_t(pixel), camera_path_time(view_, sampler));
    };
    trace_from_camera_batches(accel_, begin, end, ray_of, [&](size_t pixel, const Ray& ray, bool found, const SurfaceHit& hit) {
      pt_continue_path(view_, accel_, Sampler(seed_, pixel, pass), ray, found, hit, settings_, &local, &sample);
      Rgb value = sample.value();
      if (!all_finite(value)) {
        ++local.dropped;
        value = Rgb();
      }
      film.add_sample(uint32_t(pixel), value);
    });
    shared.add(local);
  });
  shared.flush(counters, n);
}

void PtIntegrator::render_filtered(uint32_t pass, Film& film, PathCounters& counters) {
  const size_t n = film.pixel_count();
  const int per_path = records_per_path(settings_.selection);
  const size_t batch = filter_->batch_paths(per_path);
  const size_t step = batch == 0 ? n : std::min(n, batch);
  if (caustics_) caustics_->build(accel_, seed_, pass, counters);  // 2014 paper, sec. 2.3
  FilterWorkspace& w = filter_->workspace();
  filter_reached_ = false;
  if (const ProbeRequest* request = filter_->probe_request(pass)) {  // 2021 paper, sec. 3.4.1 (hybrid)
    trace_probes(*request, &w.probes, counters);
    filter_reached_ = true;
    filter_->temporal_probes(w.probes);
  }
  for (size_t first = 0; first < n; first += step) {
    const size_t paths = std::min(step, n - first);
    trace_batch(pass, first, paths, 0, &w.paths, counters);
    // An aborted pass (RenderSession::abort) that has not touched the filter yet leaves it as the
    // last whole pass did, so that a viewer's flight keeps the table (2021 paper, sec. 3.4).
    if (!filter_reached_ && work_cancelled()) return;
    filter_reached_ = true;
    filter_->filter(w.paths, seed_, pass, &w.filtered);
    resolve_filtered_pass(w.paths, w.filtered, film, &counters);
    // 2014 paper, sec. 3 (fig. 7): extra camera paths per pixel that only query the batch's
    // vertices, so anti-aliasing costs a primary ray, not a path.
    for (int k = 1; k <= needs_.query_paths; ++k) {
      trace_batch(pass, first, paths, k, &w.queries, counters);  // their rays count, they are not paths
      filter_->query(w.queries, &w.queried, &w.found);
      resolve_filtered_pass(w.queries, w.queried, film, &counters, &w.found);
    }
  }
  filter_->end_pass();
}

// Traces the paths of pixels [first, first + paths) into `buffer`. Stream 0 is the pass's paths;
// stream k > 0 the k-th query-only path of each pixel, with a sampler of its own.
void PtIntegrator::trace_batch(uint32_t pass, size_t first, size_t paths, int stream, VertexBuffer* buffer,
                               PathCounters& counters) {
  const int per_path = records_per_path(settings_.selection);
  if (buffer->paths() != paths || buffer->records_per_path() != per_path) buffer->resize(paths, per_path);
  const uint64_t seed = stream == 0 ? seed_ : hash_combine(seed_ ^ kQueryStreamSalt, uint64_t(stream));
  SharedCounters shared;
  const VertexBufferView out = buffer->view();  // once: VertexBuffer::store would build it per path
  parallel_for(paths, kPixelGrain, [&](size_t begin, size_t end) {
    PathCounters local;
    PathSample sample;
    const auto ray_of = [&](size_t path) {
      const Sampler sampler(seed, first + path, pass);
      return sample_camera_ray(view_, sampler, uint32_t(first + path), camera_path_time(view_, sampler));
    };
    trace_from_camera_batches(accel_, begin, end, ray_of, [&](size_t path, const Ray& ray, bool found, const SurfaceHit& hit) {
      const size_t pixel = first + path;
      pt_continue_path(view_, accel_, Sampler(seed, pixel, pass), ray, found, hit, settings_, &local, &sample, probes_, stream != 0,
                       caustics_ ? &caustics_->view() : nullptr);
      out.store(path, uint32_t(pixel), sample);
    });
    shared.add(local);
  });
  shared.flush(counters, stream == 0 ? paths : 0);
}

// The previous frame's paths of request.pixels, with its seed, pass and camera, in this frame's scene:
// where nothing changed they are the same paths. (A camera that moves within a frame is taken at its
// shutter-open pose here, so its re-traced paths differ and count as change.) Their rays count; they
// are not paths of the pass.
void PtIntegrator::trace_probes(const ProbeRequest& request, VertexBuffer* buffer, PathCounters& counters) {
  const int per_path = records_per_path(settings_.selection);
  const size_t paths = request.pixels.size();
  if (buffer->paths() != paths || buffer->records_per_path() != per_path) buffer->resize(paths, per_path);
  SharedCounters shared;
  const VertexBufferView out = buffer->view();
  parallel_for(paths, kPixelGrain, [&](size_t begin, size_t end) {
    PathCounters local;
    PathSample sample;
    const auto ray_of = [&](size_t k) {
      const Sampler sampler(request.seed, request.pixels[k], request.pass);
      return sample_camera_ray(request.camera, sampler, request.pixels[k], camera_path_time(view_, sampler));
    };
    trace_from_camera_batches(accel_, begin, end, ray_of, [&](size_t k, const Ray& ray, bool found, const SurfaceHit& hit) {
      const uint32_t pixel = request.pixels[k];
      pt_continue_path(view_, accel_, Sampler(request.seed, pixel, request.pass), ray, found, hit, settings_, &local, &sample, probes_,
                       false, caustics_ ? &caustics_->view() : nullptr);
      out.store(k, pixel, sample);
    });
    shared.add(local);
  });
  shared.flush(counters, 0);
}

void PtIntegrator::statistics(Statistics& out) const {
  if (filter_) filter_->statistics(out);
  if (caustics_) caustics_->statistics(out);
}

std::vector<NamedImage> PtIntegrator::aovs() const { return filter_ ? filter_->aovs() : std::vector<NamedImage>{}; }

// Passes of plain PT are independent; a filter and the caustic photons carry statistics from pass to pass.
void PtIntegrator::save_state(StateWriter& out) const {
  if (filter_) filter_->save_state(out);
  if (caustics_) caustics_->save_state(out);
}
void PtIntegrator::load_state(StateReader& in) {
  if (filter_) filter_->load_state(in);
  if (caustics_) caustics_->load_state(in);
}

}  // namespace pathspace
