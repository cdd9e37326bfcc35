#include "pathspace/gpu/cuda_pt_integrator.h"

#include <cuda_runtime.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pathspace/accel/bvh_build.h"
#include "pathspace/accel/bvh_tracer.h"
#include "pathspace/filters/filter_resolve.h"
#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/filters/vertex_buffer.h"
#include "pathspace/gpu/cuda_caustic_map.h"
#include "pathspace/gpu/cuda_event_timer.h"
#include "pathspace/filters/hashed/cuda_hashed_filter.h"
#include "pathspace/filters/cuda_vertex_buffer.h"
#include "pathspace/gpu/cuda_wavefront_pt.h"
#include "pathspace/gpu/device_bvh.h"
#include "pathspace/gpu/device_scene.h"
#include "pathspace/gpu/gpu_info.h"
#include "pathspace/integrators/common/camera_sample.h"
#include "pathspace/integrators/pt/caustic_photon_map.h"
#include "pathspace/integrators/pt/pt_kernel.h"
#include "pathspace/options/option_spec.h"
#include "pathspace/scene/scene.h"

namespace pathspace::gpu {

namespace {

constexpr int kThreadsPerBlock = 128;

using DeviceCounters = PathCountersDevice;

struct PassParams {
  SceneView scene;
  BvhTracer tracer;
  PtSettings settings;
  uint64_t seed;
  uint32_t pass;
  uint32_t pixels;
  bool has_caustics = false;
  CausticMapView caustics;  // the pass's caustic photon map in device memory (has_caustics)
};

// Plain path tracing: one path per pixel, its value into the pass image (non-finite values dropped,
// as the CPU's render_plain does).
__global__ void __launch_bounds__(kThreadsPerBlock) trace_plain(PassParams p, Rgb* image, DeviceCounters* counters) {
  const uint32_t pixel = blockIdx.x * blockDim.x + threadIdx.x;
  if (pixel >= p.pixels) return;
  PathCounters c;
  const Sampler sampler(p.seed, pixel, p.pass);
  Rgb value = pt_trace_path(p.scene, p.tracer, sampler, sample_camera_ray(p.scene, sampler, pixel, camera_path_time(p.scene, sampler)), p.settings, &c);
  uint32_t dropped = 0;
  if (!all_finite(value)) {
    dropped = 1;
    value = Rgb();
  }
  image[pixel] = value;
  add_counters(counters, uint32_t(c.rays), uint32_t(c.shadow_rays), 1u, dropped);
}

// Filtered path tracing, phase 1 (2021 paper, sec. 3): trace and record the selected vertices.
__global__ void __launch_bounds__(kThreadsPerBlock) trace_recording(PassParams p, VertexBufferView buffer, DeviceCounters* counters) {
  const uint32_t pixel = blockIdx.x * blockDim.x + threadIdx.x;
  if (pixel >= p.pixels) return;
  PathCounters c;
  PathSample sample;
  const Sampler sampler(p.seed, pixel, p.pass);
  pt_trace_path(p.scene, p.tracer, sampler, sample_camera_ray(p.scene, sampler, pixel, camera_path_time(p.scene, sampler)), p.settings, &c, &sample,
                {}, false, p.has_caustics ? &p.caustics : nullptr);
  buffer.store(pixel, pixel, sample);
  add_counters(counters, uint32_t(c.rays), uint32_t(c.shadow_rays), 1u, 0u);
}

// Phase 3: each path's value from its prefix and its filtered vertices (filters/filter_resolve.h,
// the CPU's resolve_filtered_pass).
__global__ void resolve_paths(VertexBufferView buffer, const Rgb* filtered, Rgb* image, DeviceCounters* counters) {
  const uint32_t path = blockIdx.x * blockDim.x + threadIdx.x;
  if (path >= buffer.paths) return;
  const ResolvedPath r = resolved_path_value(buffer, path, filtered);
  image[buffer.pixel[path]] = r.value;
  add_counters(counters, 0u, 0u, 0u, r.dropped ? 1u : 0u);
}

uint32_t blocks_for(size_t n) { return uint32_t((n + kThreadsPerBlock - 1) / kThreadsPerBlock); }

class CudaPtIntegrator final : public Integrator {
 public:
  CudaPtIntegrator(const IntegratorContext& ctx, const PtSettings& settings, CudaPtPipeline pipeline)
      : settings_(settings), pipeline_(pipeline), seed_(ctx.seed), pixels_(uint32_t(ctx.scene.camera.width) * uint32_t(ctx.scene.camera.height)),
        device_name_(gpu_info().name), scene_(ctx.scene), bvh_(ctx.scene) {
    if (ctx.filter.active()) {
      // check_device allows only the filters the device entry names (hashed).
      const HashedFilterSettings fs = settings_cast<HashedFilterSettings>(ctx.filter.settings, ctx.filter.name);
      // An animation's next frame takes the previous frame's filter over with its table (sec. 3.4).
      filter_ = std::dynamic_pointer_cast<CudaHashedFilter>(ctx.carried_filter);
      if (filter_) {
        filter_->begin_frame(ctx.scene.camera);
      } else {
        filter_ = std::make_shared<CudaHashedFilter>(fs, ctx.scene.camera, size_t(pixels_));
      }
      buffer_.resize(pixels_, records_per_path(settings_.selection));
      filtered_.resize(size_t(pixels_) * size_t(records_per_path(settings_.selection)));
      // Photon-mapped caustics beside the filter (2014 paper, sec. 2.3), as PtIntegrator.
      const SceneView host = ctx.scene.view();
      const CausticSettings caustics = caustics_for_scene(fs.caustics, host);
      if (caustics.enabled())
        caustics_.emplace(host, caustics, settings_.max_segments > 0 ? settings_.max_segments : host.max_path_segments,
                          settings_.selection);
    } else {
      settings_.selection.mode = VertexSelectionMode::none;  // nothing to split a path for (as on the CPU)
    }
    image_.resize(pixels_);
    counters_.resize(1);
    if (pipeline_ == CudaPtPipeline::wavefront) {
      // Its stages have no distance sampling in media (pt_trace_branch's loop is the megakernel's).
      if (ctx.scene.view().media.any())
        throw Error("the wavefront pipeline does not trace participating media (docs/media.md); use the megakernel");
      // Its paths are states in queues, one per pixel: branches of one path would need queues of their own.
      if (settings_.selection.mode != VertexSelectionMode::none && settings_.selection.camera_splits > 0)
        throw Error("the wavefront pipeline does not trace camera-side branches (--psf-camera-splits); use the megakernel");
      wavefront_.emplace(pixels_);
    }
    host_image_.resize(pixels_);
  }

  const char* name() const override { return "pt"; }
  std::shared_ptr<PathSpaceFilter> carried_filter() const override { return filter_; }
  uint32_t frame_warm_up() const override { return filter_ ? filter_->frame_warm_up() : 0; }
  std::string distribution_limit() const override { return filter_ ? filter_->distribution_limit() : std::string(); }
  // What the next pass needs (--temporal: the filter's keys and histories), as PtIntegrator.
  void save_state(StateWriter& out) const override {
    if (filter_) filter_->save_state(out);
    if (caustics_) caustics_->save_state(out);
  }
  void load_state(StateReader& in) override {
    if (filter_) filter_->load_state(in);
    if (caustics_) caustics_->load_state(in);
  }

  void render_pass(uint32_t pass, Film& film, PathCounters& counters) override {
    PassParams p{scene_.view(), BvhTracer{scene_.view(), bvh_.view()}, settings_, seed_, pass, pixels_};
    counters_.fill_bytes(0);
    timer_.start();
    if (caustics_) {
      caustics_->build(p.scene, p.tracer, seed_, pass, counters_.data());
      p.has_caustics = true;
      p.caustics = caustics_->view();
      timer_.lap(&caustics_ms_);
    }
    if (wavefront_) {
      const VertexBufferView view = filter_ ? buffer_.view() : VertexBufferView{};
      wavefront_->trace(p.scene, p.tracer, settings_, seed_, pass, filter_ ? &view : nullptr, image_.data(), counters_.data(), &stages_,
                        p.has_caustics ? &p.caustics : nullptr);
      timer_.start();  // the wavefront timed its own stages; the trace time is their sum
      trace_ms_ = stages_.camera_ms + stages_.extend_ms + stages_.shade_ms + stages_.shadow_ms;
    } else if (filter_) {
      trace_recording<<<blocks_for(pixels_), kThreadsPerBlock>>>(p, buffer_.view(), counters_.data());
      PS_CUDA_CHECK_LAUNCH("trace_recording");
      timer_.lap(&trace_ms_);
    } else {
      trace_plain<<<blocks_for(pixels_), kThreadsPerBlock>>>(p, image_.data(), counters_.data());
      PS_CUDA_CHECK_LAUNCH("trace_plain");
      timer_.lap(&trace_ms_);
    }
    if (filter_) {
      filter_->filter(buffer_.view(), seed_, pass, filtered_.data());
      timer_.lap(&filter_ms_);
      resolve_paths<<<blocks_for(pixels_), kThreadsPerBlock>>>(buffer_.view(), filtered_.data(), image_.data(), counters_.data());
      PS_CUDA_CHECK_LAUNCH("resolve_paths");
      timer_.lap(&resolve_ms_);
    }
    image_.download(host_image_.data(), pixels_);
    DeviceCounters c{};
    counters_.download(&c, 1);
    timer_.lap(&download_ms_);
    for (uint32_t i = 0; i < pixels_; ++i) film.add_sample(i, host_image_[i]);
    counters.rays += c.rays;
    counters.shadow_rays += c.shadow_rays;
    counters.paths += c.paths;
    counters.dropped += c.dropped;
    rays_ += c.rays;
    ++passes_;
  }

  void statistics(Statistics& out) const override {
    const double passes = double(passes_ ? passes_ : 1);
    out.text("cuda.device", device_name_);
    out.text("cuda.pipeline", wavefront_ ? "wavefront" : "megakernel", "how paths are traced (docs/gpu.md)");
    if (wavefront_) {
      out.seconds("cuda.camera_s_per_pass", stages_.camera_ms * 1e-3 / passes, "wavefront: camera rays into path states");
      out.seconds("cuda.extend_s_per_pass", stages_.extend_ms * 1e-3 / passes, "wavefront: extension rays, closest hit");
      out.seconds("cuda.shade_s_per_pass", stages_.shade_ms * 1e-3 / passes, "wavefront: emission, selection, NEE, BSDF sampling");
      out.seconds("cuda.shadow_s_per_pass", stages_.shadow_ms * 1e-3 / passes, "wavefront: shadow rays, any hit");
      out.value("cuda.bounces_per_pass", double(stages_.bounces) / passes, "wavefront: extension rounds");
      out.bytes("cuda.path_state_bytes", wavefront_->bytes(), "wavefront: path states, hits and queues");
    }
    out.bytes("cuda.scene_bytes", scene_.bytes(), "the scene's arrays in device memory");
    out.bytes("cuda.bvh_bytes", bvh_.bytes(), "BVH nodes and primitive references in device memory");
    out.counter("cuda.bvh_nodes", bvh_.nodes());
    out.seconds("cuda.bvh_build_s", bvh_.build_seconds(), "on the host, Embree's SAH builder, then flattened");
    if (caustics_)
      out.seconds("cuda.caustics_s_per_pass", caustics_ms_ * 1e-3 / passes, "caustic photons: traced, indexed on the host, uploaded");
    out.seconds("cuda.trace_s_per_pass", trace_ms_ * 1e-3 / passes, "camera rays to the paths' values or vertices (device time)");
    out.seconds("cuda.filter_s_per_pass", filter_ms_ * 1e-3 / passes, "the hashed filter: clear, accumulate, lookup (device time)");
    out.seconds("cuda.resolve_s_per_pass", resolve_ms_ * 1e-3 / passes, "filtered vertices into pixels (device time)");
    out.seconds("cuda.download_s_per_pass", download_ms_ * 1e-3 / passes, "the pass image to the host film");
    out.seconds("cuda.frame_s_per_pass", (trace_ms_ + filter_ms_ + resolve_ms_) * 1e-3 / passes,
                "camera rays to the filtered image in device memory");
    out.value("cuda.mrays_per_s", trace_ms_ > 0.0 ? double(rays_) / (trace_ms_ * 1e3) : 0.0, "rays over the tracing time");
    if (filter_) filter_->statistics(out);
    if (caustics_) caustics_->statistics(out);
  }

 private:
  PtSettings settings_;
  CudaPtPipeline pipeline_;
  uint64_t seed_;
  uint32_t pixels_;
  std::string device_name_;
  DeviceScene scene_;
  DeviceBvh bvh_;
  std::shared_ptr<CudaHashedFilter> filter_;
  std::optional<DeviceCausticMap> caustics_;  // --psf-caustic-photons
  std::optional<WavefrontPathTracer> wavefront_;
  WavefrontStageTimes stages_;
  DeviceVertexBuffer buffer_;
  DeviceBuffer<Rgb> filtered_, image_;
  DeviceBuffer<DeviceCounters> counters_;
  std::vector<Rgb> host_image_;
  CudaEventTimer timer_;
  double caustics_ms_ = 0, trace_ms_ = 0, filter_ms_ = 0, resolve_ms_ = 0, download_ms_ = 0;
  uint64_t rays_ = 0, passes_ = 0;
};

}  // namespace

std::unique_ptr<Integrator> make_cuda_pt_integrator(const IntegratorContext& context, const PtSettings& settings,
                                                    CudaPtPipeline pipeline) {
  require_gpu();
  return std::make_unique<CudaPtIntegrator>(context, settings, pipeline);
}

}  // namespace pathspace::gpu
