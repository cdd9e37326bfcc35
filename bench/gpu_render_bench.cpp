// Path tracing and hashed filtering on the GPU (--device cuda) at 1920x1080, 1 sample per pixel per
// frame, with both pipelines (megakernel and wavefront, gpu/cuda_pt_integrator.h): per-frame device
// time (camera rays to the filtered image in device memory) as the median over frames after
// warm-up, its stages (trace, filter, resolve), rays per second, and the 2-thread CPU figure of the
// same build for the same scene. The megakernel also runs with the filter's table kept from frame
// to frame (--temporal integrate, sec. 3.4): the temporal steps' share of the filter's time. Needs a CUDA device (prints why not and exits 0
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

#include "median.h"
#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/accel/accel.h"
#include "pathspace/film/film.h"
#include "pathspace/gpu/cuda_pt_integrator.h"
#include "pathspace/gpu/gpu_info.h"
#include "pathspace/gpu/wavefront_stages.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/session/render_session.h"

namespace pathspace {
namespace {

constexpr int kWidth = 1920, kHeight = 1080;

// A statistic's total over `passes` passes (the integrator reports per-pass means).
double total(const Statistics& s, const char* name, uint32_t passes) {
  const Statistic* st = s.find(name);
  return st ? st->number * double(passes) : 0.0;
}

enum class BenchFilter { none, hashed, temporal };
const char* filter_name(BenchFilter f) { return f == BenchFilter::none ? "none" : f == BenchFilter::hashed ? "hashed" : "temporal"; }

struct GpuRun {
  double frame_ms = 0, trace_ms = 0, filter_ms = 0, resolve_ms = 0, download_ms = 0, mrays_per_s = 0, rays_per_path = 0;
  double temporal_ms = 0;  // --temporal: level transfer, folding and eviction (part of filter_ms)
  double extend_ms = 0, shade_ms = 0, shadow_ms = 0;  // wavefront stages
};

GpuRun run_gpu(const Scene& scene, BenchFilter bench_filter, gpu::CudaPtPipeline pipeline, int frames) {
  const Accel accel(scene);  // the context's; the GPU builds its own BVH
  FilterChoice filter;
  if (bench_filter != BenchFilter::none) {
    HashedFilterSettings settings;
    if (bench_filter == BenchFilter::temporal) settings.temporal.mode = TemporalMode::integrate;
    filter = FilterChoice{"hashed", settings};
  }
  const IntegratorContext context{scene, accel, 1, filter};
  // Both pipelines without camera-side branches, which the wavefront does not trace: the rows compare.
  auto integrator = gpu::make_cuda_pt_integrator(context, without_camera_branches(PtSettings{}), pipeline);
  Film film(scene.camera.width, scene.camera.height);
  PathCounters counters;
  uint32_t passes = 0;
  for (; passes < 3; ++passes) integrator->render_pass(passes, film, counters);  // warm-up
  std::vector<double> frame, trace, filter_ms, resolve, download, mrays, extend, shade, shadow, temporal;
  Statistics before;
  integrator->statistics(before);
  uint64_t rays_before = counters.rays;
  for (int f = 0; f < frames; ++f) {
    integrator->render_pass(passes, film, counters);
    Statistics now;
    integrator->statistics(now);
    auto delta = [&](const char* n) { return (total(now, n, passes + 1) - total(before, n, passes)) * 1e3; };  // ms
    frame.push_back(delta("cuda.frame_s_per_pass"));
    trace.push_back(delta("cuda.trace_s_per_pass"));
    filter_ms.push_back(delta("cuda.filter_s_per_pass"));
    resolve.push_back(delta("cuda.resolve_s_per_pass"));
    download.push_back(delta("cuda.download_s_per_pass"));
    extend.push_back(delta("cuda.extend_s_per_pass"));
    shade.push_back(delta("cuda.shade_s_per_pass"));
    shadow.push_back(delta("cuda.shadow_s_per_pass"));
    temporal.push_back(delta("hashed.temporal.s_per_step"));
    mrays.push_back(double(counters.rays - rays_before) / (trace.back() * 1e3));
    rays_before = counters.rays;
    before = std::move(now);
    ++passes;
  }
  GpuRun r{median(frame), median(trace), median(filter_ms), median(resolve), median(download), median(mrays),
           double(counters.rays) / double(std::max<uint64_t>(1, counters.paths))};
  r.extend_ms = median(extend);
  r.shade_ms = median(shade);
  r.shadow_ms = median(shadow);
  r.temporal_ms = median(temporal);
  return r;
}

double cpu_mrays_per_s(const std::shared_ptr<const Scene>& scene, int threads) {  // one pass
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
  std::printf("\n%-12s %-8s %-10s %9s %7s %9s %9s %9s %9s %9s %9s %9s %10s %9s %10s %9s\n", "scene", "filter", "pipeline", "frame ms",
              "fps", "trace ms", "extend ms", "shade ms", "shadow ms", "filter ms", "temporal", "resolve ms", "Mrays/s", "rays/path",
              "CPU2 Mr/s", "GPU/CPU2");
  for (const auto& [name, scene] : scenes) {
    const double cpu = cpu_mrays_per_s(scene, 2);
    for (BenchFilter f : {BenchFilter::none, BenchFilter::hashed, BenchFilter::temporal})
      for (gpu::CudaPtPipeline pipeline : {gpu::CudaPtPipeline::megakernel, gpu::CudaPtPipeline::wavefront}) {
        const bool wave = pipeline == gpu::CudaPtPipeline::wavefront;
        if (wave && f == BenchFilter::temporal) continue;  // the same filter calls as the megakernel's
        const GpuRun r = run_gpu(*scene, f, pipeline, frames);
        std::printf("%-12s %-8s %-10s %9.3f %7.1f %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f %10.1f %9.2f %10.2f %9.1f\n", name.c_str(),
                    filter_name(f), wave ? "wavefront" : "megakernel", r.frame_ms, 1e3 / r.frame_ms, r.trace_ms, r.extend_ms, r.shade_ms,
                    r.shadow_ms, r.filter_ms, r.temporal_ms, r.resolve_ms, r.mrays_per_s, r.rays_per_path, cpu, r.mrays_per_s / cpu);
        out["runs"].push_back({{"scene", name}, {"filter", filter_name(f)}, {"pipeline", wave ? "wavefront" : "megakernel"},
                               {"frame_ms", r.frame_ms}, {"fps", 1e3 / r.frame_ms}, {"trace_ms", r.trace_ms}, {"extend_ms", r.extend_ms},
                               {"shade_ms", r.shade_ms}, {"shadow_ms", r.shadow_ms}, {"filter_ms", r.filter_ms},
                               {"temporal_ms", r.temporal_ms}, {"resolve_ms", r.resolve_ms}, {"download_ms", r.download_ms},
                               {"mrays_per_s", r.mrays_per_s}, {"rays_per_path", r.rays_per_path}, {"cpu_2_threads_mrays_per_s", cpu}});
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
