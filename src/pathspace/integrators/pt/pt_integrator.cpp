#include "pathspace/integrators/pt/pt_integrator.h"

#include <atomic>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/common/camera_sample.h"
#include "pathspace/integrators/pt/pt_kernel.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/scene/scene.h"

namespace pathspace {

namespace {

constexpr size_t kPixelGrain = 256;

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

}  // namespace

PtIntegrator::PtIntegrator(const Scene& scene, const Accel& accel, const PtSettings& settings, uint64_t seed,
                           const FilterChoice& filter)
    : view_(scene.view()), accel_(accel), settings_(settings), seed_(seed) {
  const size_t pixels = size_t(scene.camera.width) * size_t(scene.camera.height);
  filter_ = make_filter(filter, FilterContext{scene.camera, pixels});
}

PtIntegrator::~PtIntegrator() = default;

void PtIntegrator::render_pass(uint32_t pass, Film& film, PathCounters& counters) {
  if (filter_) {
    render_filtered(pass, film, counters);
  } else {
    render_plain(pass, film, counters);
  }
}

void PtIntegrator::render_plain(uint32_t pass, Film& film, PathCounters& counters) {
  const size_t n = film.pixel_count();
  SharedCounters shared;
  parallel_for(n, kPixelGrain, [&](size_t begin, size_t end) {
    PathCounters local;
    for (size_t pixel = begin; pixel < end; ++pixel) {
      const Sampler sampler(seed_, pixel, pass);
      Rgb value = pt_trace_path(view_, accel_, sampler, sample_camera_ray(view_.camera, sampler, uint32_t(pixel)), settings_, &local);
      if (!all_finite(value)) {
        ++local.dropped;
        value = Rgb();
      }
      film.add_sample(uint32_t(pixel), value);
    }
    shared.add(local);
  });
  shared.flush(counters, n);
}

void PtIntegrator::render_filtered(uint32_t pass, Film& film, PathCounters& counters) {
  const size_t n = film.pixel_count();
  const int per_path = records_per_path(settings_.selection);
  if (buffer_.paths() != n || buffer_.records_per_path() != per_path) buffer_.resize(n, per_path);
  SharedCounters shared;
  parallel_for(n, kPixelGrain, [&](size_t begin, size_t end) {
    PathCounters local;
    PathSample sample;
    for (size_t pixel = begin; pixel < end; ++pixel) {
      const Sampler sampler(seed_, pixel, pass);
      pt_trace_path(view_, accel_, sampler, sample_camera_ray(view_.camera, sampler, uint32_t(pixel)), settings_, &local, &sample);
      buffer_.store(pixel, uint32_t(pixel), sample);
    }
    shared.add(local);
  });
  shared.flush(counters, n);
  filter_->filter(buffer_, seed_, pass, &filtered_);
  resolve_filtered_pass(buffer_, filtered_, film, &counters);
}

void PtIntegrator::statistics(Statistics& out) const {
  if (filter_) filter_->statistics(out);
}

std::vector<NamedImage> PtIntegrator::aovs() const { return filter_ ? filter_->aovs() : std::vector<NamedImage>{}; }

// Passes of plain PT are independent; a filter may carry statistics from pass to pass.
void PtIntegrator::save_state(StateWriter& out) const {
  if (filter_) filter_->save_state(out);
}
void PtIntegrator::load_state(StateReader& in) {
  if (filter_) filter_->load_state(in);
}

}  // namespace pathspace
