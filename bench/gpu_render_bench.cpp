// Path tracing and hashed filtering on the GPU (--device cuda) at 1920x1080, 1 sample per pixel per
// frame: per-frame device time (camera rays to the filtered image in device memory) as the median
// over frames after warm-up, its stages (trace, filter, resolve), rays per second, and the 2-thread
// CPU figure of the same build for the same scene. Needs a CUDA device (prints why not and exits 0
// without one, so that CI can run it). Used by scripts/gpu-check; docs/benchmarks.md.
//
//   gpu_render_bench [--scenes DIR] [--frames N] [--json FILE]
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathspace/filters/hashed_filter_settings.h"
#include "pathspace/gpu/gpu_info.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/session/render_session.h"

namespace pathspace {
namespace {

constexpr int kWidth = 1920, kHeight = 1080;

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// A statistic's total over the passes so far (the integrator reports per-pass means).
double total(const RenderStats& s, const char* name) {
  const Statistic* st = s.details.find(name);
  return st ? st->number * double(s.spp) : 0.0;
}

struct GpuRun {
  double frame_ms = 0, trace_ms = 0, filter_ms = 0, resolve_ms = 0, download_ms = 0, mrays_per_s = 0, rays_per_path = 0;
};

GpuRun run_gpu(const std::shared_ptr<const Scene>& scene, bool filtered, int frames) {
  RenderConfig config = make_render_config("pt", PtSettings{}, 1);
  config.device = "cuda";
  if (filtered) config = with_filter(config, "hashed", HashedFilterSettings{});
  RenderSession session(scene, nullptr, config);
  session.run(RunLimit::for_passes(3));  // warm-up: module load, first-touch of the buffers
  std::vector<double> frame, trace, filter, resolve, download, mrays;
  RenderStats before = session.stats();
  for (int f = 0; f < frames; ++f) {
    session.run(RunLimit::for_passes(1));
    const RenderStats now = session.stats();
    auto delta = [&](const char* n) { return (total(now, n) - total(before, n)) * 1e3; };  // ms
    frame.push_back(delta("cuda.frame_s_per_pass"));
    trace.push_back(delta("cuda.trace_s_per_pass"));
    filter.push_back(delta("cuda.filter_s_per_pass"));
    resolve.push_back(delta("cuda.resolve_s_per_pass"));
    download.push_back(delta("cuda.download_s_per_pass"));
    mrays.push_back(double(now.rays - before.rays) / (trace.back() * 1e3));
    before = now;
  }
  const RenderStats s = session.stats();
  return {median(frame), median(trace), median(filter), median(resolve), median(download), median(mrays),
          double(s.rays) / double(std::max<uint64_t>(1, s.paths))};
}

double cpu_mrays_per_s(const std::shared_ptr<const Scene>& scene, int threads) {
  RenderConfig config = make_render_config("pt", PtSettings{}, 1);
  config.threads = threads;
  RenderSession session(scene, nullptr, config);
  session.run(RunLimit::for_passes(1));
  return session.stats().mrays_per_s();
}

int run(int argc, char** argv) {
  std::string scenes_dir = PATHSPACE_SHARED_SCENES_DIR, json_path;
  int frames = 30;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--scenes" && i + 1 < argc) scenes_dir = argv[++i];
    else if (a == "--frames" && i + 1 < argc) frames = std::max(1, std::atoi(argv[++i]));
    else if (a == "--json" && i + 1 < argc) json_path = argv[++i];
    else {
      std::fprintf(stderr, "usage: gpu_render_bench [--scenes DIR] [--frames N] [--json FILE]\n");
      return 2;
    }
  }
  const gpu::GpuInfo& g = gpu::gpu_info();
  if (!g.available) {
    std::printf("gpu_render_bench: skipped: %s\n", g.reason.c_str());
    return 0;
  }
  std::printf("GPU: %s\n", g.describe().c_str());
  std::vector<std::pair<std::string, std::shared_ptr<const Scene>>> scenes;
  scenes.emplace_back("cornell-box", std::make_shared<const Scene>(make_builtin_scene("cornell-box", kWidth, kHeight)));
  const std::string living = scenes_dir + "/bitterli/living-room/scene-v4.pbrt";
  if (std::ifstream(living).good()) {
    SceneLoadOptions o;
    o.substitute_missing_textures = true;
    o.width = kWidth, o.height = kHeight;
    std::vector<std::string> warnings;
    scenes.emplace_back("living-room", std::make_shared<const Scene>(load_scene(living, o, &warnings)));
  } else {
    std::printf("living-room not found at %s: skipped\n", living.c_str());
  }
  nlohmann::ordered_json out;
  out["gpu"] = g.describe();
  out["width"] = kWidth;
  out["height"] = kHeight;
  out["frames"] = frames;
  std::printf("\n%-12s %-7s %9s %7s %9s %9s %9s %10s %9s %10s %9s\n", "scene", "filter", "frame ms", "fps", "trace ms", "filter ms",
              "resolve ms", "Mrays/s", "rays/path", "CPU2 Mr/s", "GPU/CPU2");
  for (const auto& [name, scene] : scenes) {
    const double cpu = cpu_mrays_per_s(scene, 2);
    for (bool filtered : {false, true}) {
      const GpuRun r = run_gpu(scene, filtered, frames);
      std::printf("%-12s %-7s %9.3f %7.1f %9.3f %9.3f %9.3f %10.1f %9.2f %10.2f %9.1f\n", name.c_str(), filtered ? "hashed" : "none",
                  r.frame_ms, 1e3 / r.frame_ms, r.trace_ms, r.filter_ms, r.resolve_ms, r.mrays_per_s, r.rays_per_path, cpu,
                  r.mrays_per_s / cpu);
      out["runs"].push_back({{"scene", name}, {"filter", filtered ? "hashed" : "none"}, {"frame_ms", r.frame_ms},
                             {"fps", 1e3 / r.frame_ms}, {"trace_ms", r.trace_ms}, {"filter_ms", r.filter_ms},
                             {"resolve_ms", r.resolve_ms}, {"download_ms", r.download_ms}, {"mrays_per_s", r.mrays_per_s},
                             {"rays_per_path", r.rays_per_path}, {"cpu_2_threads_mrays_per_s", cpu}});
    }
  }
  if (!json_path.empty()) std::ofstream(json_path) << out.dump(2) << "\n";
  return 0;
}

}  // namespace
}  // namespace pathspace

int main(int argc, char** argv) {
  try {
    return pathspace::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gpu_render_bench: %s\n", e.what());
    return 1;
  }
}
