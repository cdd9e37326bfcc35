// Path tracing against the limit of its ray caster (issue 19). One pass of path tracing records
// every ray it casts, nearest-hit and shadow, in order, per chunk of 256 pixels; the same rays are
// then replayed on the same threads, chunk by chunk, through Embree alone (Accel::hit_distance and
// Accel::occluded: the query, nothing filled in) and through Accel::intersect (Embree plus the
// SurfaceHit an integrator needs). That is the real limit for this scene and this ray mix, not a
// synthetic one. Runs of a PT pass (a RenderSession pass, as the CLI renders) and of both replays
// alternate; the table holds medians and PT's ray rate as a share of Embree's, taken run by run.
//
//   ray_replay_bench [--runs N (default 7)] [--threads 1,2] [--size 512]
// Scenes: cornell-box, cornell-glossy-large-mirror (glm_c) and, when ../shared/scenes holds it,
// Bitterli's living room (docs/testing.md).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/common/camera_sample.h"
#include "pathspace/integrators/pt/pt_kernel.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/session/render_session.h"

#ifndef PATHSPACE_SHARED_SCENES_DIR
#define PATHSPACE_SHARED_SCENES_DIR ""
#endif

namespace pathspace {
namespace {

constexpr size_t kChunkPixels = 256;  // PtIntegrator's grain

struct RecordedRay {
  Ray ray;
  bool shadow = false;
};

// The Tracer concept (accel/accel.h) over an Accel, appending each query to `rays`.
struct RecordingTracer {
  const Accel& accel;
  std::vector<RecordedRay>* rays;
  bool intersect(const Ray& r, SurfaceHit* hit) const {
    rays->push_back({r, false});
    return accel.intersect(r, hit);
  }
  bool occluded(const Ray& r) const {
    rays->push_back({r, true});
    return accel.occluded(r);
  }
};

// Pass 0 of a PT render (seed 0, the scene's path length), its rays per chunk of pixels.
std::vector<std::vector<RecordedRay>> record_pass(const Scene& scene, const Accel& accel) {
  const SceneView view = scene.view();
  const size_t pixels = size_t(scene.camera.width) * size_t(scene.camera.height);
  std::vector<std::vector<RecordedRay>> chunks((pixels + kChunkPixels - 1) / kChunkPixels);
  PtSettings settings;
  settings.selection.mode = VertexSelectionMode::none;  // as PtIntegrator traces without a filter
  parallel_for(chunks.size(), 1, [&](size_t c0, size_t c1) {
    for (size_t c = c0; c < c1; ++c) {
      const RecordingTracer tracer{accel, &chunks[c]};
      PathCounters counters;
      for (size_t pixel = c * kChunkPixels; pixel < std::min(pixels, (c + 1) * kChunkPixels); ++pixel) {
        const Sampler sampler(0, pixel, 0);
        pt_trace_path(view, tracer, sampler, sample_camera_ray(view.camera, sampler, uint32_t(pixel), camera_path_time(view, sampler)), settings, &counters);
      }
    }
  });
  return chunks;
}

double seconds(const std::chrono::steady_clock::time_point& t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Replays the chunks on the worker threads; `with_hits`: through Accel::intersect, else Embree alone.
double replay(const Accel& accel, const std::vector<std::vector<RecordedRay>>& chunks, bool with_hits) {
  std::atomic<uint64_t> sink{0};
  const auto t = std::chrono::steady_clock::now();
  parallel_for(chunks.size(), 1, [&](size_t c0, size_t c1) {
    uint64_t found = 0;
    for (size_t c = c0; c < c1; ++c)
      for (const RecordedRay& r : chunks[c]) {
        if (r.shadow) {
          found += accel.occluded(r.ray);
        } else if (with_hits) {
          SurfaceHit hit;
          found += accel.intersect(r.ray, &hit);
        } else {
          found += accel.hit_distance(r.ray) < kInfinity;
        }
      }
    sink += found;
  });
  const double s = seconds(t);
  if (sink.load() == ~uint64_t(0)) std::puts("");  // keeps the queries
  return s;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void run_scene(const std::string& name, std::shared_ptr<const Scene> scene, const std::vector<int>& threads, int runs) {
  const auto accel = std::make_shared<const Accel>(*scene);
  for (const int t : threads) {
    const ThreadLimit limit(t);
    const auto chunks = record_pass(*scene, *accel);
    uint64_t recorded = 0, shadow = 0;
    for (const auto& c : chunks)
      for (const RecordedRay& r : c) ++recorded, shadow += r.shadow;
    RenderConfig config = make_render_config("pt", PtSettings{}, 0);
    config.threads = t;
    RenderSession session(scene, accel, config);
    session.run(RunLimit::for_passes(1));  // warm-up
    replay(*accel, chunks, false);
    std::vector<double> pt_s, embree_s, accel_s, share, share_hits;
    for (int i = 0; i < runs; ++i) {
      const uint64_t rays_before = session.stats().rays;
      const auto t0 = std::chrono::steady_clock::now();
      session.run(RunLimit::for_passes(1));
      const double pass = seconds(t0);
      const double pt_rate = double(session.stats().rays - rays_before) / pass;
      const double e = replay(*accel, chunks, false);
      const double a = replay(*accel, chunks, true);
      pt_s.push_back(pass);
      embree_s.push_back(e);
      accel_s.push_back(a);
      share.push_back(pt_rate / (double(recorded) / e));
      share_hits.push_back(pt_rate / (double(recorded) / a));
    }
    std::printf("%-28s %7d %8.2f %10.1f %12.1f %12.1f %10.2f %10.2f %9.1f%% %9.1f%%\n", name.c_str(), t,
                double(recorded) * 1e-6, 100.0 * double(shadow) / double(recorded), 1e3 * median(pt_s), 1e3 * median(embree_s),
                double(recorded) * 1e-6 / median(embree_s), double(recorded) * 1e-6 / median(accel_s), 100.0 * median(share),
                100.0 * median(share_hits));
    std::fflush(stdout);
  }
}

std::vector<int> parse_threads(const char* s) {
  std::vector<int> out;
  for (const char* p = s; *p;) {
    char* end = nullptr;
    const long v = std::strtol(p, &end, 10);
    if (end == p || v < 1 || v > 4096) {
      std::fprintf(stderr, "ray_replay_bench: --threads takes a comma-separated list of counts, not '%s'\n", s);
      std::exit(2);
    }
    out.push_back(int(v));
    p = *end == ',' ? end + 1 : end;
  }
  return out;
}

}  // namespace
}  // namespace pathspace

int main(int argc, char** argv) {
  using namespace pathspace;
  int runs = 7, size = 512;
  std::vector<int> threads = {1, 2};
  for (int i = 1; i < argc; ++i) {
    const bool has_value = i + 1 < argc;
    if (!std::strcmp(argv[i], "--runs") && has_value) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else if (!std::strcmp(argv[i], "--threads") && has_value) {
      threads = parse_threads(argv[++i]);
    } else if (!std::strcmp(argv[i], "--size") && has_value) {
      size = std::clamp(std::atoi(argv[++i]), 16, 4096);
    } else {
      std::fprintf(stderr, "usage: %s [--runs N] [--threads 1,2] [--size 512]\n", argv[0]);
      return 2;
    }
  }
  std::printf("%-28s %7s %8s %10s %12s %12s %10s %10s %10s %10s\n", "scene", "threads", "Mrays", "shadow %", "PT pass ms",
              "Embree ms", "Embree Mr/s", "+hits Mr/s", "PT/Embree", "PT/+hits");
  for (const char* name : {"cornell-box", "cornell-glossy-large-mirror"})
    run_scene(name, std::make_shared<const Scene>(make_builtin_scene(name, size, size)), threads, runs);
  const std::string room = std::string(PATHSPACE_SHARED_SCENES_DIR) + "/bitterli/living-room/scene-v4.pbrt";
  try {
    SceneLoadOptions options;
    options.width = options.height = size;
    options.substitute_missing_textures = true;  // three files are missing from the source
    run_scene("living-room", std::make_shared<const Scene>(load_scene(room, options, nullptr)), threads, runs);
  } catch (const std::exception& e) {
    std::printf("living-room: skipped (%s)\n", e.what());
  }
  return 0;
}
