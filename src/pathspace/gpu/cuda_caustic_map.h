// The caustic photon map of the GPU path tracer (Keller, Dahm, Binder 2014, sec. 2.3; the CPU's is
// integrators/pt/caustic_photon_map.h). Per pass the photons are traced on the device with the
// CPU's sampler streams (trace_caustic_photon), copied to the host and indexed there by
// CausticPhotonMap::index, the CPU's own grid build, and the grid and the photons in cell order are
// uploaded for the gathers of the pass's camera paths. So the map is the one the CPU would build
// from the same photons, and its statistics and checkpoint state are the CPU's. The copies cost a
// few MB per pass; a grid built on the device would remove them.
#pragma once

#include <cstdint>

#include "pathspace/accel/bvh_tracer.h"
#include "pathspace/gpu/device_counters.h"
#include "pathspace/integrators/pt/caustic_photon_map.h"
#include "pathspace/parallel/device_buffer.h"

namespace pathspace::gpu {

class DeviceCausticMap {
 public:
  // host_scene: the scene as the CPU sees it (image size and bounds set the photon count and radius).
  DeviceCausticMap(const SceneView& host_scene, const CausticSettings& settings, int max_segments, const VertexSelection& selection);

  // Traces the pass's photons in the device scene, indexes them and uploads the map; the rays are
  // added to counters->rays.
  void build(const SceneView& scene, const BvhTracer& tracer, uint64_t seed, uint32_t pass, PathCountersDevice* counters);
  // The map of the last build, its pointers in device memory.
  const CausticMapView& view() const { return view_; }
  void statistics(Statistics& out) const { host_.statistics(out); }
  void save_state(StateWriter& out) const { host_.save_state(out); }
  void load_state(StateReader& in) { host_.load_state(in); }

 private:
  // One kind of photons in device memory (PhotonSetView).
  struct DeviceSet {
    DeviceBuffer<CausticPhoton> in_cells;
    DeviceBuffer<GridSlot> slots;
    DeviceBuffer<GridRecord> records;
    DeviceBuffer<uint64_t> occupancy;
    // Uploads the host's set (grid: its grid) and returns its view with device pointers.
    PhotonSetView upload(const PhotonSetView& host, const HashGrid& grid);
  };

  CausticPhotonMap host_;
  DeviceBuffer<CausticPhoton> traced_;
  DeviceSet caustic_, one_bounce_;
  CausticMapView view_;
};

}  // namespace pathspace::gpu
