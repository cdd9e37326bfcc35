// The device BVH tracer (accel/bvh_tracer.h) run on the CPU against Embree (Accel), single-ray
// nearest hits on one thread: incoherent rays (random points in the scene's bounds, uniform
// directions) and camera rays, on the Cornell box and on Bitterli's living room (outside the
// repository, docs/testing.md; skipped when missing). Rays/s is the "items_per_second" counter.
// The BVH tracer is written for GPUs (no SIMD); on the CPU this shows its cost relative to Embree.
// The wide tracer (accel/wide_bvh.h) over the same tree collapsed to 8-wide nodes runs beside it.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "pathspace/accel/accel.h"
#include "pathspace/accel/bvh_build.h"
#include "pathspace/accel/bvh_tracer.h"
#include "pathspace/accel/wide_bvh_build.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/sampling/rng.h"
#include "pathspace/sampling/warps.h"
#include "pathspace/scene/builtin_scenes.h"

#ifndef PATHSPACE_SHARED_SCENES_DIR
#define PATHSPACE_SHARED_SCENES_DIR ""
#endif

namespace pathspace {
namespace {

constexpr size_t kRays = 1 << 18;

struct Setup {
  Scene scene;
  SceneView view;
  std::unique_ptr<Accel> accel;
  FlatBvh bvh;
  WideBvh wide;
  std::vector<Ray> incoherent, camera;
};

std::unique_ptr<Setup> make_setup(Scene scene) {
  auto s = std::make_unique<Setup>();
  s->scene = std::move(scene);
  s->view = s->scene.view();
  s->accel = std::make_unique<Accel>(s->scene);
  s->bvh = build_bvh(s->view);
  s->wide = build_wide_bvh(s->bvh);
  Pcg32 rng(1, 2);
  const Bounds3 b = s->scene.geometry_bounds();
  const Vec3 e = b.diagonal();
  const PerspectiveCamera& c = s->scene.camera;
  for (size_t i = 0; i < kRays; ++i) {
    const Vec3 o = b.lo + Vec3(e.x * rng.next_float(), e.y * rng.next_float(), e.z * rng.next_float());
    s->incoherent.push_back(Ray{o, square_to_uniform_sphere({rng.next_float(), rng.next_float()}), 0.f, kInfinity});
    s->camera.push_back(c.generate_ray(float(c.width) * rng.next_float(), float(c.height) * rng.next_float()));
  }
  return s;
}

const Setup* cornell() {
  static const auto s = make_setup(make_builtin_scene("cornell-box", 512, 512));
  return s.get();
}

const Setup* living_room() {
  static const auto s = [] {
    const std::string path = std::string(PATHSPACE_SHARED_SCENES_DIR) + "/bitterli/living-room/scene-v4.pbrt";
    std::unique_ptr<Setup> r;
    try {
      SceneLoadOptions options;
      options.width = options.height = 512;
      options.substitute_missing_textures = true;  // three files are missing from the source
      r = make_setup(load_scene(path, options, nullptr));
    } catch (const std::exception&) {
    }
    return r;
  }();
  return s.get();
}

template <typename Tracer>
void trace(benchmark::State& state, const Setup* s, const Tracer& tracer, bool camera) {
  const std::vector<Ray>& rays = camera ? s->camera : s->incoherent;
  for (auto _ : state) {
    size_t hits = 0;
    SurfaceHit hit;
    for (const Ray& r : rays) hits += tracer.intersect(r, &hit);
    benchmark::DoNotOptimize(hits);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(rays.size()));
  state.counters["bvh_nodes"] = double(s->bvh.stats.nodes);
  state.counters["bvh_build_ms"] = 1e3 * s->bvh.stats.build_seconds;
}

enum class Tracer { embree, bvh, wide };

void run(benchmark::State& state, const Setup* (*setup)(), Tracer which, bool camera) {
  const Setup* s = setup();
  if (!s)
    state.SkipWithError("scene missing (docs/testing.md, 'Test data outside the repository')");
  else if (which == Tracer::bvh)
    trace(state, s, BvhTracer{s->view, s->bvh.view()}, camera);
  else if (which == Tracer::wide)
    trace(state, s, WideBvhTracer{s->view, s->wide.view()}, camera);
  else
    trace(state, s, *s->accel, camera);
}

void BM_CornellIncoherentEmbree(benchmark::State& s) { run(s, cornell, Tracer::embree, false); }
void BM_CornellIncoherentBvh(benchmark::State& s) { run(s, cornell, Tracer::bvh, false); }
void BM_CornellIncoherentWide(benchmark::State& s) { run(s, cornell, Tracer::wide, false); }
void BM_CornellCameraEmbree(benchmark::State& s) { run(s, cornell, Tracer::embree, true); }
void BM_CornellCameraBvh(benchmark::State& s) { run(s, cornell, Tracer::bvh, true); }
void BM_CornellCameraWide(benchmark::State& s) { run(s, cornell, Tracer::wide, true); }
void BM_LivingRoomIncoherentEmbree(benchmark::State& s) { run(s, living_room, Tracer::embree, false); }
void BM_LivingRoomIncoherentBvh(benchmark::State& s) { run(s, living_room, Tracer::bvh, false); }
void BM_LivingRoomIncoherentWide(benchmark::State& s) { run(s, living_room, Tracer::wide, false); }
void BM_LivingRoomCameraEmbree(benchmark::State& s) { run(s, living_room, Tracer::embree, true); }
void BM_LivingRoomCameraBvh(benchmark::State& s) { run(s, living_room, Tracer::bvh, true); }
void BM_LivingRoomCameraWide(benchmark::State& s) { run(s, living_room, Tracer::wide, true); }
BENCHMARK(BM_CornellIncoherentEmbree)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CornellIncoherentBvh)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CornellIncoherentWide)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CornellCameraEmbree)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CornellCameraBvh)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CornellCameraWide)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LivingRoomIncoherentEmbree)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LivingRoomIncoherentBvh)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LivingRoomIncoherentWide)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LivingRoomCameraEmbree)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LivingRoomCameraBvh)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LivingRoomCameraWide)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace pathspace

BENCHMARK_MAIN();
