// The GPU hashed filter across frames (--temporal integrate and ema, 2021 paper sec. 3.4) against the
// CPU's HashedFilter: a camera flies towards the Cornell box over eight frames, so voxels change
// their level of detail (3.4.2) and, with small tables, probe windows overflow and cells are
// evicted (3.4.3). Every frame's filtered values must be the same bits, and the temporal counters
// (blend weights, transfers, evictions, occupancy) the same numbers. A GPU filter restored from a
// checkpoint must continue as the one that was saved, and a CUDA path tracer must hand its filter
// to the next frame's. Label cuda; skips where no GPU is present.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/filters/hashed/hashed_filter.h"
#include "pathspace/filters/hashed/cuda_hashed_filter.h"
#include "pathspace/gpu/cuda_pt_integrator.h"
#include "pathspace/stats/statistics.h"
#include "gpu_comparison.h"
#include "support/filter_pass_buffers.h"

namespace pathspace {
namespace {

constexpr int kWidth = 160, kHeight = 120, kFrames = 8;

struct Frame {
  std::unique_ptr<Scene> scene;
  VertexBuffer buffer;
};

// Frame f of the flight: the camera moves from the built-in view halfway to the box and turns a
// little, so voxels of the same surface shrink from frame to frame. nth > 0: the nth diffuse vertex.
const std::vector<Frame>& flight(int nth) {
  static std::vector<Frame> frames[3];
  std::vector<Frame>& out = frames[nth];
  if (!out.empty()) return out;
  for (int f = 0; f < kFrames; ++f) {
    Frame frame;
    frame.scene = std::make_unique<Scene>(make_builtin_scene("cornell-box", kWidth, kHeight));
    const PerspectiveCamera& c = frame.scene->camera;
    const float t = float(f) / float(kFrames - 1);
    frame.scene->camera = make_perspective_camera(c.position + c.forward * (2.f * t) + c.right * (0.3f * t),
                                                  c.forward - c.right * (0.1f * t), c.up, 40.f, kWidth, kHeight);
    frame.scene->finalize();
    const Accel accel(*frame.scene);
    PtSettings s;
    if (nth > 0) {
      s.selection.mode = VertexSelectionMode::nth;
      s.selection.n = nth;
    }
    PtIntegrator pt(*frame.scene, accel, s, 100 + uint64_t(f), FilterChoice{"passthrough", {}});
    Film film(kWidth, kHeight);
    PathCounters counters;
    pt.render_pass(0, film, counters);
    frame.buffer = pt.vertex_buffer();
    out.push_back(std::move(frame));
  }
  return out;
}

struct TemporalCase {
  std::string name;
  int nth = 0;
  HashedFilterSettings settings;
};

void PrintTo(const TemporalCase& c, std::ostream* os) { *os << c.name; }

std::vector<TemporalCase> temporal_cases() {
  std::vector<TemporalCase> cases;
  TemporalCase integrate{"integrate_priority", 0, {}};
  integrate.settings.temporal.mode = TemporalMode::integrate;
  cases.push_back(integrate);
  TemporalCase second = integrate;
  second.name = "integrate_second_bounce_capped";
  second.nth = 2;
  second.settings.temporal.max_frames = 3;
  cases.push_back(second);
  TemporalCase ema{"ema_lru_small_table", 0, {}};
  ema.settings.temporal.mode = TemporalMode::ema;
  ema.settings.temporal.alpha = 0.7f;
  ema.settings.temporal.eviction = EvictionPolicy::lru;
  ema.settings.table_factor = 0.05f;
  cases.push_back(ema);
  TemporalCase stale{"integrate_stale_no_transfer", 2, {}};
  stale.settings.temporal.mode = TemporalMode::integrate;
  stale.settings.temporal.eviction = EvictionPolicy::stale;
  stale.settings.temporal.stale_frames = 2;
  stale.settings.temporal.level_transfer = false;
  cases.push_back(stale);
  TemporalCase tiny{"integrate_overflowing_table", 2, {}};
  tiny.settings.temporal.mode = TemporalMode::integrate;
  tiny.settings.temporal.occupancy = 0.5f;
  tiny.settings.table_factor = 0.002f;
  cases.push_back(tiny);
  return cases;
}

class CudaTemporalFilterTest : public ::testing::TestWithParam<TemporalCase> {};

TEST_P(CudaTemporalFilterTest, EqualsTheCpuFilterFrameByFrame) {
  PATHSPACE_REQUIRE_GPU();
  const TemporalCase& c = GetParam();
  const std::vector<Frame>& frames = flight(c.nth);
  const size_t pixels = size_t(kWidth) * size_t(kHeight);
  HashedFilter cpu(c.settings, frames[0].scene->camera, pixels);
  gpu::CudaHashedFilter gpu_filter(c.settings, frames[0].scene->camera, pixels);
  for (int f = 0; f < kFrames; ++f) {
    const Frame& frame = frames[size_t(f)];
    if (f > 0) {
      cpu.begin_frame(frame.scene->camera);
      gpu_filter.begin_frame(frame.scene->camera);
    }
    SlotValues expected, got;
    cpu.filter(frame.buffer, 100 + uint64_t(f), 0, &expected);
    gpu_filter.filter(frame.buffer, 100 + uint64_t(f), 0, &got);
    size_t differing = 0;
    EXPECT_TRUE(testing::same_filtered_bits(frame.buffer, expected, got, &differing))
        << c.name << " frame " << f << ": " << differing << " of " << frame.buffer.total_records() << " vertices differ";
    const HashedFilterStats& a = cpu.stats();
    const HashedFilterStats& b = gpu_filter.stats();
    EXPECT_EQ(b.steps, a.steps) << c.name << " frame " << f;
    EXPECT_EQ(b.blended, a.blended) << c.name << " frame " << f;
    EXPECT_EQ(b.mean_alpha_last, a.mean_alpha_last) << c.name << " frame " << f;
    EXPECT_EQ(b.from_finer, a.from_finer) << c.name << " frame " << f;
    EXPECT_EQ(b.from_coarser, a.from_coarser) << c.name << " frame " << f;
    EXPECT_EQ(b.evicted, a.evicted) << c.name << " frame " << f;
    EXPECT_EQ(b.occupied_cells_last, a.occupied_cells_last) << c.name << " frame " << f;
    EXPECT_EQ(b.probe_failures, a.probe_failures) << c.name << " frame " << f;
  }
  const HashedFilterStats& a = cpu.stats();
  std::printf("%s: mean alpha %.3f (last frame), %llu from finer, %llu from coarser, %llu evicted, temporal steps %.3f ms "
              "on the GPU (last frame)\n",
              c.name.c_str(), a.mean_alpha_last, (unsigned long long)a.from_finer, (unsigned long long)a.from_coarser,
              (unsigned long long)a.evicted, gpu_filter.stats().temporal_ms_last);
}

// Runs everywhere (no GPU needed): each case exercises what it is named for on the CPU filter, so the
// GPU comparison above compares those steps.
TEST_P(CudaTemporalFilterTest, CaseExercisesItsSteps) {
  const TemporalCase& c = GetParam();
  const std::vector<Frame>& frames = flight(c.nth);
  HashedFilter cpu(c.settings, frames[0].scene->camera, size_t(kWidth) * size_t(kHeight));
  uint64_t settled = 0;
  for (int f = 0; f < kFrames; ++f) {
    if (f > 0) cpu.begin_frame(frames[size_t(f)].scene->camera);
    SlotValues values;
    cpu.filter(frames[size_t(f)].buffer, 100 + uint64_t(f), 0, &values);
    settled = cpu.stats().settled_passes;
  }
  const HashedFilterStats& a = cpu.stats();
  EXPECT_GT(a.mean_alpha_last, 0.0) << c.name;
  if (c.settings.temporal.level_transfer) {
    EXPECT_GT(a.from_finer + a.from_coarser, 0u) << c.name;
  }
  if (c.settings.table_factor < 1.f || c.settings.temporal.eviction == EvictionPolicy::stale) {
    EXPECT_GT(a.evicted, 0u) << c.name;
  }
  if (c.settings.table_factor < 0.01f) {
    EXPECT_GT(settled, 0u) << c.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, CudaTemporalFilterTest, ::testing::ValuesIn(temporal_cases()),
                         [](const ::testing::TestParamInfo<TemporalCase>& i) { return i.param.name; });

// save_state after frame 3, load_state into a new filter: frames 4..7 as if nothing happened.
TEST(CudaTemporalFilter, RestoredFilterContinuesBitForBit) {
  PATHSPACE_REQUIRE_GPU();
  const std::vector<Frame>& frames = flight(0);
  const size_t pixels = size_t(kWidth) * size_t(kHeight);
  HashedFilterSettings settings;
  settings.temporal.mode = TemporalMode::integrate;
  settings.table_factor = 0.05f;
  gpu::CudaHashedFilter original(settings, frames[0].scene->camera, pixels);
  SlotValues values;
  for (int f = 0; f < 4; ++f) {
    if (f > 0) original.begin_frame(frames[size_t(f)].scene->camera);
    original.filter(frames[size_t(f)].buffer, 100 + uint64_t(f), 0, &values);
  }
  StateWriter writer;
  original.save_state(writer);
  gpu::CudaHashedFilter restored(settings, frames[3].scene->camera, pixels);
  StateReader reader(writer.bytes());
  restored.load_state(reader);
  for (int f = 4; f < kFrames; ++f) {
    original.begin_frame(frames[size_t(f)].scene->camera);
    restored.begin_frame(frames[size_t(f)].scene->camera);
    SlotValues expected, got;
    original.filter(frames[size_t(f)].buffer, 100 + uint64_t(f), 0, &expected);
    restored.filter(frames[size_t(f)].buffer, 100 + uint64_t(f), 0, &got);
    size_t differing = 0;
    EXPECT_TRUE(testing::same_filtered_bits(frames[size_t(f)].buffer, expected, got, &differing)) << "frame " << f << ": " << differing;
  }
  EXPECT_EQ(restored.stats().steps, original.stats().steps);
  EXPECT_GT(restored.stats().mean_alpha_last, 0.0);
}

// The CUDA path tracer hands its filter, table and histories, to the next frame's integrator
// (RenderSession::begin_frame does this for `--device cuda --frames`).
TEST(CudaTemporalFilter, PathTracerCarriesTheTableToTheNextFrame) {
  PATHSPACE_REQUIRE_GPU();
  const std::vector<Frame>& frames = flight(0);
  HashedFilterSettings settings;
  settings.temporal.mode = TemporalMode::integrate;
  const FilterChoice filter{"hashed", settings};
  std::shared_ptr<PathSpaceFilter> carried;
  const Scene& scene = *frames[0].scene;  // a still camera: integration weights N_old / (N_old + N_new) grow to 2/3
  const Accel accel(scene);
  for (int f = 0; f < 3; ++f) {
    const IntegratorContext context{scene, accel, 100 + uint64_t(f), filter, carried};
    auto pt = gpu::make_cuda_pt_integrator(context, PtSettings{});
    Film film(kWidth, kHeight);
    PathCounters counters;
    pt->render_pass(0, film, counters);
    carried = pt->carried_filter();
    ASSERT_NE(carried, nullptr);
    EXPECT_EQ(pt->frame_warm_up(), kTemporalWarmUpFrames);
    EXPECT_FALSE(pt->distribution_limit().empty());
  }
  const auto* gpu_filter = dynamic_cast<const gpu::CudaHashedFilter*>(carried.get());
  ASSERT_NE(gpu_filter, nullptr);
  EXPECT_EQ(gpu_filter->stats().steps, 3u);
  EXPECT_GT(gpu_filter->stats().mean_alpha_last, 0.5);
  Statistics stats;
  gpu_filter->statistics(stats);
  EXPECT_TRUE(stats.find("hashed.temporal.mean_alpha_last") != nullptr);
}

}  // namespace
}  // namespace pathspace
