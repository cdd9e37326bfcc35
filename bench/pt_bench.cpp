// Path tracing throughput on the default scene (cornell-box, 512x512): one pass = one sample per
// pixel. Counters: samples/s (= paths/s), Mrays/s; 1 and 2 threads for the scaling ratio. One
// benchmark iteration = one pass of a RenderSession made outside the timed loop (as the CLI renders).
// BM_OnePathPerPixel: the same pass with the hashed filter, with and without caustic photons
// (docs/hashed-filter.md), beside plain PT in the same run, for the ratio of their times.
#include <benchmark/benchmark.h>

#include "pathspace/accel/accel.h"
#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/session/render_session.h"

namespace pathspace {
namespace {

void BM_PtCornellBox(benchmark::State& state) {
  static const Scene scene = make_builtin_scene("cornell-box", 512, 512);
  static const Accel accel(scene);
  RenderConfig config = make_render_config("pt", PtSettings{}, 0);
  config.threads = int(state.range(0));
  // Non-owning handles: scene and accel are static.
  RenderSession session(std::shared_ptr<const Scene>(std::shared_ptr<void>(), &scene),
                        std::shared_ptr<const Accel>(std::shared_ptr<void>(), &accel), config);
  for (auto _ : state) session.run(RunLimit::for_passes(1));
  const RenderStats st = session.stats();
  const uint64_t rays = st.rays, paths = st.paths;
  state.counters["paths_per_s"] = benchmark::Counter(double(paths), benchmark::Counter::kIsRate);
  state.counters["Mrays_per_s"] = benchmark::Counter(double(rays) * 1e-6, benchmark::Counter::kIsRate);
  state.counters["rays_per_path"] = double(rays) / double(paths);
}

// Arg: 0 plain PT, 1 PT + hashed filter, 2 and more: PT + hashed filter + (arg - 1) / 4 caustic
// photons per pixel and pass. All threads.
void BM_OnePathPerPixel(benchmark::State& state) {
  static const Scene scene = make_builtin_scene("cornell-box", 512, 512);
  static const Accel accel(scene);
  RenderConfig config = make_render_config("pt", PtSettings{}, 0);
  if (state.range(0) > 0) {
    HashedFilterSettings filter;
    filter.caustics.photons_per_pixel = double(state.range(0) - 1) / 4.0;
    config = with_filter(config, "hashed", filter);
  }
  RenderSession session(std::shared_ptr<const Scene>(std::shared_ptr<void>(), &scene),
                        std::shared_ptr<const Accel>(std::shared_ptr<void>(), &accel), config);
  session.run(RunLimit::for_passes(1));  // the first pass allocates the table and buffers
  for (auto _ : state) session.run(RunLimit::for_passes(1));
  state.SetLabel(state.range(0) == 0 ? "PT" : state.range(0) == 1 ? "PT + hashed" : "PT + hashed + photons");
  state.counters["photons_per_pixel"] = state.range(0) > 1 ? double(state.range(0) - 1) / 4.0 : 0.0;
}

BENCHMARK(BM_OnePathPerPixel)->DenseRange(0, 2)->Arg(3)->Arg(5)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0)->Repetitions(3)->ReportAggregatesOnly(true);

BENCHMARK(BM_PtCornellBox)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

}  // namespace
}  // namespace pathspace

BENCHMARK_MAIN();
