// DeviceBvh: a scene's flat BVH (accel/bvh_build.h: Embree's SAH builder, flattened in the Aila-Laine
// layout) built on the host and uploaded once; view() is the BvhView with device pointers that
// kernels pair with the DeviceScene's SceneView in a BvhTracer. CUDA builds only.
#pragma once

#include <cstdint>

#include "pathspace/accel/bvh_build.h"
#include "pathspace/parallel/device_buffer.h"
#include "pathspace/scene/scene.h"

namespace pathspace::gpu {

class DeviceBvh {
 public:
  explicit DeviceBvh(const Scene& scene);
  BvhView view() const { return view_; }
  size_t bytes() const { return nodes_.bytes() + prims_.bytes(); }
  uint64_t nodes() const { return stats_.nodes; }
  double build_seconds() const { return stats_.build_seconds; }
  const BvhBuildStats& stats() const { return stats_; }

 private:
  DeviceBuffer<BvhNode> nodes_;
  DeviceBuffer<uint32_t> prims_;
  BvhView view_;
  BvhBuildStats stats_;
};

}  // namespace pathspace::gpu
