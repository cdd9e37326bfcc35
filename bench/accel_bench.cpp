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

}  // namespace
}  // namespace pathspace

BENCHMARK_MAIN();
