// Throughput of every registered integrator (integrator_registry()) with its default settings on the
// default scene (cornell-box, 512x512), 1 and 2 threads: one benchmark iteration = one pass of a
// RenderSession made once outside the timed loop (so SPPM/PCLT setup is excluded; their radius keeps
// shrinking across passes).
// Counters: pixel_paths_per_s (film pixels per pass / time), light_paths_per_s (lt: light paths;
// sppm: photons; pclt: light paths; bpt: light subpaths, one per pixel), Mrays_per_s.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/session/render_session.h"

namespace pathspace {
namespace {

constexpr int kSize = 512;

const std::shared_ptr<const Scene>& cornell_box() {
  static const std::shared_ptr<const Scene> scene = std::make_shared<const Scene>(make_builtin_scene("cornell-box", kSize, kSize));
  return scene;
}

const std::shared_ptr<const Accel>& cornell_accel() {
  static const std::shared_ptr<const Accel> accel = std::make_shared<const Accel>(*cornell_box());
  return accel;
}

void BM_Integrator(benchmark::State& state, const std::string& name) {
  RenderConfig config;  // the integrator's default settings
  config.integrator = name;
  config.seed = 1;
  config.threads = int(state.range(0));
  RenderSession session(cornell_box(), cornell_accel(), config);
  for (auto _ : state) session.run(RunLimit::for_passes(1));
  const RenderStats counters = session.stats();
  const double pixel_paths = double(counters.spp) * double(kSize) * double(kSize);
  // What counters.paths counts differs (integrator.h implementations): pixels (pt, bpt), light
  // paths (lt), pixels + photons or light paths (sppm, pclt).
  double light_paths = 0;
  if (name == "lt") light_paths = double(counters.paths);
  if (name == "sppm" || name == "pclt") light_paths = double(counters.paths) - pixel_paths;
  if (name == "bpt") light_paths = pixel_paths;
  state.counters["pixel_paths_per_s"] = benchmark::Counter(pixel_paths, benchmark::Counter::kIsRate);
  if (light_paths > 0) state.counters["light_paths_per_s"] = benchmark::Counter(light_paths, benchmark::Counter::kIsRate);
  state.counters["Mrays_per_s"] = benchmark::Counter(double(counters.rays) * 1e-6, benchmark::Counter::kIsRate);
}

}  // namespace
}  // namespace pathspace

int main(int argc, char** argv) {
  for (const std::string& name : pathspace::integrator_registry().names())
    benchmark::RegisterBenchmark(("BM_Integrator/" + name).c_str(), pathspace::BM_Integrator, name)
        ->Arg(1)
        ->Arg(2)
        ->ArgName("threads")
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->MinTime(2.0);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
