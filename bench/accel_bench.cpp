// Embree throughput on incoherent rays (random origins inside the Cornell box, uniform directions)
// and on coherent camera rays, with 1 and 2 threads; single-ray calls versus the stream API.
// Reports rays/s as the "items_per_second" counter. See docs/benchmarks.md.
#include <benchmark/benchmark.h>

#include <vector>

#include "pathspace/accel/accel.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/sampling/rng.h"
#include "pathspace/sampling/warps.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace {
namespace {

constexpr size_t kRays = 1 << 20;

const Scene& scene() {
  static const Scene s = make_builtin_scene("cornell-box", 512, 512);
  return s;
}
const Accel& accel() {
  static const Accel a(scene());
  return a;
}

std::vector<Ray> incoherent_rays() {
  std::vector<Ray> rays(kRays);
  Pcg32 rng(1, 2);
  for (Ray& r : rays) {
    const Vec3 o(-1.2f + 2.4f * rng.next_float(), -1.2f + 2.4f * rng.next_float(), -1.2f + 2.4f * rng.next_float());
    r = Ray{o, square_to_uniform_sphere({rng.next_float(), rng.next_float()}), 0.f, kInfinity};
  }
  return rays;
}

std::vector<Ray> camera_rays() {
  std::vector<Ray> rays(kRays);
  const PerspectiveCamera& c = scene().camera;
  for (size_t i = 0; i < kRays; ++i) {
    const size_t p = i % (512 * 512);
    rays[i] = c.generate_ray(float(p % 512) + 0.5f, float(p / 512) + 0.5f);
  }
  return rays;
}

void run_single(benchmark::State& state, const std::vector<Ray>& rays, bool shadow) {
  ThreadLimit limit(int(state.range(0)));
  for (auto _ : state) {
    std::atomic<size_t> hits{0};
    parallel_for(rays.size(), 4096, [&](size_t b, size_t e) {
      size_t local = 0;
      SurfaceHit hit;
      for (size_t i = b; i < e; ++i) local += shadow ? accel().occluded(rays[i]) : accel().intersect(rays[i], &hit);
      hits += local;
    });
    benchmark::DoNotOptimize(hits.load());
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(rays.size()));
}

void run_stream(benchmark::State& state, const std::vector<Ray>& rays, bool coherent) {
  ThreadLimit limit(int(state.range(0)));
  for (auto _ : state) {
    parallel_for(rays.size() / 256, 16, [&](size_t b, size_t e) {
      SurfaceHit hits[256];
      bool found[256];
      for (size_t k = b; k < e; ++k) accel().intersect_batch(&rays[k * 256], hits, found, 256, coherent);
    });
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(rays.size()));
}

void BM_IncoherentIntersect1(benchmark::State& s) {
  static const auto rays = incoherent_rays();
  run_single(s, rays, false);
}
void BM_IncoherentOccluded1(benchmark::State& s) {
  static const auto rays = incoherent_rays();
  run_single(s, rays, true);
}
void BM_IncoherentStream(benchmark::State& s) {
  static const auto rays = incoherent_rays();
  run_stream(s, rays, false);
}
void BM_CameraIntersect1(benchmark::State& s) {
  static const auto rays = camera_rays();
  run_single(s, rays, false);
}
void BM_CameraStreamCoherent(benchmark::State& s) {
  static const auto rays = camera_rays();
  run_stream(s, rays, true);
}

BENCHMARK(BM_IncoherentIntersect1)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_IncoherentOccluded1)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_IncoherentStream)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CameraIntersect1)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CameraStreamCoherent)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// An animation frame (docs/animation.md): the moving-sphere Cornell box with a static floor grid of
// 2^arg triangles. Full: every frame builds everything; Reuse: the frame's Accel takes the previous
// frame's static part and builds only the moving sphere and the two-instance top level.
Scene animated_frame(int log2_triangles, double seconds) {
  Scene s = make_builtin_scene_at("cornell-moving-sphere", 64, 64, seconds);
  const int side = 1 << (log2_triangles / 2);
  const uint32_t material = s.triangles.front().material;
  Scene grid = s;  // the grid's triangles go before the box's (all static); the sphere stays the moving part
  grid.triangles.clear();
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side / 2; ++i) {
      const float x0 = -1.2f + 2.4f * float(2 * i) / float(side), x1 = -1.2f + 2.4f * float(2 * i + 2) / float(side);
      const float y0 = -1.2f + 2.4f * float(j) / float(side), y1 = -1.2f + 2.4f * float(j + 1) / float(side);
      grid.add_quad(Vec3(x0, y0, -1.27f), Vec3(x1, y0, -1.27f), Vec3(x1, y1, -1.27f), Vec3(x0, y1, -1.27f), material);
    }
  for (const Triangle& t : s.triangles) grid.triangles.push_back(t);
  grid.finalize();
  return grid;
}

void BM_AnimatedFrameFullRebuild(benchmark::State& state) {
  const Scene a = animated_frame(int(state.range(0)), 0.0), b = animated_frame(int(state.range(0)), 0.5);
  int frame = 0;
  for (auto _ : state) {
    Scene flat = (++frame & 1) ? a : b;
    flat.first_moving_sphere = Scene::kNothingMoves;
    state.PauseTiming();
    state.ResumeTiming();
    const Accel accel(flat);
    benchmark::DoNotOptimize(&accel);
  }
}

void BM_AnimatedFrameReuse(benchmark::State& state) {
  const Scene a = animated_frame(int(state.range(0)), 0.0), b = animated_frame(int(state.range(0)), 0.5);
  auto previous = std::make_unique<Accel>(a);
  int frame = 0;
  for (auto _ : state) {
    auto next = std::make_unique<Accel>((++frame & 1) ? b : a, previous.get());
    if (!next->reused_static_part()) state.SkipWithError("the static part was rebuilt");
    previous = std::move(next);
  }
}

BENCHMARK(BM_AnimatedFrameFullRebuild)->Arg(16)->Arg(20)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_AnimatedFrameReuse)->Arg(16)->Arg(20)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace pathspace

BENCHMARK_MAIN();
