#include "pathspace/gpu/cuda_caustic_map.h"

#include <chrono>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/parallel/cuda_check.h"

namespace pathspace::gpu {

namespace {

constexpr int kThreads = 128;

// Photon i of the pass, from the stream the CPU's CausticPhotonMap::build uses for it.
__global__ void trace_photons_kernel(SceneView scene, BvhTracer tracer, uint64_t photon_seed, uint32_t pass, int max_segments,
                                     VertexSelection receivers, uint32_t n, CausticPhoton* out, PathCountersDevice* counters) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  PathCounters c;
  trace_caustic_photon(scene, tracer, Sampler(photon_seed, i, pass), max_segments, receivers, &c, &out[i]);
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
  traced_.resize(n);
  if (n > 0) {
    trace_photons_kernel<<<(n + kThreads - 1) / kThreads, kThreads>>>(scene, tracer, caustic_photon_seed(seed), pass,
                                                                     host_.max_segments(), host_.receivers(), n,
                                                                     traced_.data(), counters);
    PS_CUDA_CHECK_LAUNCH("trace_photons_kernel");
  }
  std::vector<CausticPhoton>& traced = host_.traced_photons();
  traced_.download(traced.data(), n);  // waits for the kernel
  host_.index(pass, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  const CausticMapView& map = host_.view();
  slots_.upload(map.grid.slots, size_t(map.grid.slot_mask) + 1);
  records_.upload(map.grid.records, map.grid.record_capacity);
  in_cells_.upload(map.photons, host_.grid().compacted_records());
  view_ = map;
  view_.grid.slots = slots_.data();
  view_.grid.records = records_.data();
  view_.grid.counters = nullptr;  // gathers only read
  if (map.grid.occupancy.words) {
    occupancy_.upload(map.grid.occupancy.words, map.grid.occupancy.word_count());
    view_.grid.occupancy.words = occupancy_.data();
  }
  view_.photons = in_cells_.data();
}

}  // namespace pathspace::gpu
