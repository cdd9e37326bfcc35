// What a checkpoint costs at 1920x1080 (docs/results/io-and-overheads.md, "Checkpoints and periodic outputs"): save_state() (the copy
// taken on the render thread between passes: the only part a periodic checkpoint stalls the render
// for), encode_checkpoint() (header, CRC-32) and write_checkpoint() (encode, write, fsync, rename),
// for pt + hashed filter and for sppm, after one pass. Counter `MiB`: the file's size.
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <memory>
#include <string>

#include "pathspace/accel/accel.h"
#include "pathspace/checkpoint/checkpoint_file.h"
#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/integrators/sppm/sppm_settings.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/session/render_session.h"

namespace pathspace {
namespace {

// Session 0: pt + hashed filter, 1: sppm; each rendered for one pass, made once.
RenderSession& session(int which) {
  static std::unique_ptr<RenderSession> made[2];
  if (!made[which]) {
    const auto scene = std::make_shared<const Scene>(make_builtin_scene("cornell-box", 1920, 1080));
    SppmSettings sppm;
    sppm.photons = 100000;  // the state's size does not depend on it; the pass's time does
    const RenderConfig config = which == 0 ? with_filter(make_render_config("pt", PtSettings{}), "hashed", HashedFilterSettings{})
                                           : make_render_config("sppm", sppm);
    made[which] = std::make_unique<RenderSession>(scene, nullptr, config);
    made[which]->run(RunLimit::for_passes(1));
  }
  return *made[which];
}

CheckpointInfo info_of(const RenderSession& s) {
  CheckpointInfo info;
  info.scene = "cornell-box";
  info.scene_hash = "builtin:cornell-box";
  info.integrator = s.config().integrator;
  info.filter = s.config().filter.name;
  info.width = 1920;
  info.height = 1080;
  info.passes = s.passes_done();
  return info;
}

void BM_SaveState(benchmark::State& state) {
  RenderSession& s = session(int(state.range(0)));
  size_t bytes = 0;
  for (auto _ : state) bytes = s.save_state().bytes.size();
  state.counters["MiB"] = double(bytes) / 1048576.0;
}

void BM_EncodeCheckpoint(benchmark::State& state) {
  RenderSession& s = session(int(state.range(0)));
  const SessionState saved = s.save_state();
  size_t bytes = 0;
  for (auto _ : state) bytes = encode_checkpoint(info_of(s), saved).size();
  state.counters["MiB"] = double(bytes) / 1048576.0;
}

void BM_WriteCheckpoint(benchmark::State& state) {
  RenderSession& s = session(int(state.range(0)));
  const SessionState saved = s.save_state();
  const std::string path = "/tmp/pathspace-checkpoint-bench-" + std::to_string(::getpid()) + ".ckpt";
  for (auto _ : state) write_checkpoint(path, info_of(s), saved);
  ::unlink(path.c_str());
}

BENCHMARK(BM_SaveState)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(5);
BENCHMARK(BM_EncodeCheckpoint)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(5);
BENCHMARK(BM_WriteCheckpoint)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(5);

}  // namespace
}  // namespace pathspace

BENCHMARK_MAIN();
