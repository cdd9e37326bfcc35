#include "pathspace/integrators/pt/pt_integrator.h"

#include <atomic>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/pt/pt_kernel.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/scene/scene.h"

namespace pathspace {

PtIntegrator::PtIntegrator(const Scene& scene, const Accel& accel, const IntegratorSettings& settings)
    : view_(scene.view()), accel_(accel), settings_(settings) {}

void PtIntegrator::render_pass(uint32_t pass, Film& film, PathCounters& counters) {
  const int width = film.width();
  const size_t n = film.pixel_count();
  std::atomic<uint64_t> rays{0}, shadow_rays{0}, dropped{0};
  parallel_for(n, 256, [&](size_t begin, size_t end) {
    PathCounters local;
    for (size_t pixel = begin; pixel < end; ++pixel) {
      const Sampler sampler(settings_.seed, pixel, pass);
      const float rx = float(pixel % size_t(width)) + sampler.at(dims::kPixelX);
      const float ry = float(pixel / size_t(width)) + sampler.at(dims::kPixelY);
      Rgb value = pt_trace_path(view_, accel_, sampler, view_.camera.generate_ray(rx, ry), settings_.pt, &local);
      if (!all_finite(value)) {
        ++local.dropped;
        value = Rgb();
      }
      film.add_sample(uint32_t(pixel), value);
    }
    rays += local.rays;
    shadow_rays += local.shadow_rays;
    dropped += local.dropped;
  });
  counters.rays += rays;
  counters.shadow_rays += shadow_rays;
  counters.dropped += dropped;
  counters.paths += n;
}

}  // namespace pathspace
