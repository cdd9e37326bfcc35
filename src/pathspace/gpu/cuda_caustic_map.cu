#include "pathspace/gpu/cuda_caustic_map.h"

#include <chrono>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/parallel/cuda_check.h"

namespace pathspace::gpu {

namespace {

constexpr int kThreads = 128;

// Photon path i of the pass, from the stream the CPU's CausticPhotonMap::build uses for it, into
// out[caustic_photons_per_path(one_bounce) * i] on.
__global__ void trace_photons_kernel(SceneView scene, BvhTracer tracer, uint64_t photon_seed, uint32_t pass, int max_segments,
                                     VertexSelection receivers, bool one_bounce, uint32_t n, CausticPhoton* out,
                                     PathCountersDevice* counters) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  PathCounters c;
  CausticPhoton* slots = &out[caustic_photons_per_path(one_bounce) * size_t(i)];
  trace_caustic_photon(scene, tracer, Sampler(photon_seed, i, pass), max_segments, receivers, one_bounce, &c, slots);
  add_counters(counters, uint32_t(c.rays), 0u, 0u, 0u);
}

}  // namespace

DeviceCausticMap::DeviceCausticMap(const SceneView& host_scene, const CausticSettings& settings, int max_segments,
                                   const VertexSelection& selection)
    : host_(host_scene, settings, max_segments, selection) {
  if (host_.photons_per_pass() > UINT32_MAX)
    throw Error("the GPU path tracer traces at most 2^32 - 1 caustic photons per pass: lower --psf-caustic-photons");
}

void DeviceCausticMap::build(const SceneView& scene, const BvhTracer& tracer, uint64_t seed, uint32_t pass,
                             PathCountersDevice* counters) {
  const auto start = std::chrono::steady_clock::now();
  const uint32_t n = uint32_t(host_.photons_per_pass());
  traced_.resize(host_.photons_per_path() * size_t(n));
  if (n > 0) {
    trace_photons_kernel<<<(n + kThreads - 1) / kThreads, kThreads>>>(scene, tracer, caustic_photon_seed(seed), pass,
                                                                     host_.max_segments(), host_.receivers(), host_.one_bounce(), n,
                                                                     traced_.data(), counters);
    PS_CUDA_CHECK_LAUNCH("trace_photons_kernel");
  }
  std::vector<CausticPhoton>& traced = host_.traced_photons();
  traced_.download(traced.data(), traced.size());  // waits for the kernel
  host_.index(pass, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  view_ = host_.view();
  view_.caustic = caustic_.upload(view_.caustic, host_.caustic_grid());
  // Without one-bounce photons their grid is never built: nothing to upload.
  if (host_.one_bounce()) view_.one_bounce = one_bounce_.upload(view_.one_bounce, host_.one_bounce_grid());
}

PhotonSetView DeviceCausticMap::DeviceSet::upload(const PhotonSetView& host, const HashGrid& grid) {
  slots.upload(host.grid.slots, size_t(host.grid.slot_mask) + 1);
  records.upload(host.grid.records, host.grid.record_capacity);
  in_cells.upload(host.photons, grid.compacted_records());
  PhotonSetView device = host;
  device.grid.slots = slots.data();
  device.grid.records = records.data();
  device.grid.counters = nullptr;  // gathers only read
  if (host.grid.occupancy.words) {
    occupancy.upload(host.grid.occupancy.words, host.grid.occupancy.word_count());
    device.grid.occupancy.words = occupancy.data();
  }
  device.photons = in_cells.data();
  return device;
}

}  // namespace pathspace::gpu
