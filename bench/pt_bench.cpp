// Path tracing throughput on the default scene (cornell-box, 512x512): one pass = one sample per
// pixel. Counters: samples/s (= paths/s), Mrays/s; 1 and 2 threads for the scaling ratio.
#include <benchmark/benchmark.h>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/render.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace {
namespace {

void BM_PtCornellBox(benchmark::State& state) {
  static const Scene scene = make_builtin_scene("cornell-box", 512, 512);
  static const Accel accel(scene);
  Film film(512, 512);
  RenderRequest req;
  req.spp = 1;
  req.threads = int(state.range(0));
  uint64_t rays = 0, paths = 0;
  uint64_t seed = 0;
  for (auto _ : state) {
    req.settings.seed = seed++;
    const RenderStats st = render(scene, accel, req, film);
    rays += st.rays;
    paths += st.paths;
  }
  state.counters["paths_per_s"] = benchmark::Counter(double(paths), benchmark::Counter::kIsRate);
  state.counters["Mrays_per_s"] = benchmark::Counter(double(rays) * 1e-6, benchmark::Counter::kIsRate);
  state.counters["rays_per_path"] = double(rays) / double(paths);
}

BENCHMARK(BM_PtCornellBox)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

}  // namespace
}  // namespace pathspace

BENCHMARK_MAIN();
