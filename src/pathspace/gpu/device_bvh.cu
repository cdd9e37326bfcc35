#include "pathspace/gpu/device_bvh.h"

namespace pathspace::gpu {

DeviceBvh::DeviceBvh(const Scene& scene) {
  const FlatBvh bvh = build_bvh(scene.view());
  stats_ = bvh.stats;
  nodes_.upload(bvh.nodes);
  prims_.upload(bvh.prims);
  view_.nodes = nodes_.data();
  view_.num_nodes = uint32_t(bvh.nodes.size());
  view_.prims = prims_.data();
  view_.num_prims = uint32_t(bvh.prims.size());
}

}  // namespace pathspace::gpu
