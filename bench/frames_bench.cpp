// Frames of an animation at 640x360, one sample per pixel each, on 2 threads: what issue 16's "10
// frames per second" measures (docs/results/frames-per-second.md). One session
// renders the still cornell-box frame after frame as `pathspace render --frames` does
// (session/frame_sequence.h: a new scene and its acceleration structure per frame, then one pass),
// without writing files. One benchmark iteration = one frame; the first frames of the sequence,
// before the timed loop, let tables and buffers reach their running state. Variants: plain path
// tracing (the baseline, in the same process, for ratios) and the hashed filter with --temporal
// off and integrate. Counter: frames_per_s.
#include <benchmark/benchmark.h>

#include <memory>

#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/session/render_config.h"
#include "pathspace/session/render_session.h"

namespace pathspace {
namespace {

constexpr int kWidth = 640, kHeight = 360, kThreads = 2, kWarmUpFrames = 5;

enum class FrameFilter { none, hashed_off, hashed_integrate };

RenderConfig frame_config(FrameFilter filter) {
  RenderConfig config = make_render_config("pt", PtSettings{}, 0);
  if (filter != FrameFilter::none) {
    HashedFilterSettings hashed;
    hashed.temporal.mode = filter == FrameFilter::hashed_integrate ? TemporalMode::integrate : TemporalMode::off;
    config = with_filter(config, "hashed", hashed);
  }
  config.threads = kThreads;
  return config;
}

void BM_Frames640x360(benchmark::State& state, FrameFilter filter) {
  const Scene scene = make_builtin_scene("cornell-box", kWidth, kHeight);
  RenderSession session(std::make_shared<const Scene>(scene), nullptr, frame_config(filter));
  uint64_t frame = 0;
  const auto render_next_frame = [&] {
    session.begin_frame(std::make_shared<const Scene>(scene), nullptr, frame++);
    session.run(RunLimit::for_passes(1));
  };
  for (int i = 0; i < kWarmUpFrames; ++i) render_next_frame();
  for (auto _ : state) render_next_frame();
  state.counters["frames_per_s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

BENCHMARK_CAPTURE(BM_Frames640x360, pt, FrameFilter::none)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);
BENCHMARK_CAPTURE(BM_Frames640x360, hashed_off, FrameFilter::hashed_off)
    ->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);
BENCHMARK_CAPTURE(BM_Frames640x360, hashed_integrate, FrameFilter::hashed_integrate)
    ->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

}  // namespace
}  // namespace pathspace

BENCHMARK_MAIN();
