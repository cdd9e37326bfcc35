// Host-side build of the flat BVH (accel/bvh_view.h) over a scene's triangles and spheres, for the
// device tracer (accel/bvh_tracer.h). The tree comes from Embree's BVH builder (SAH with spatial
// splits, Stich et al. 2009), flattened depth-first into BvhNodes.
#pragma once

#include <cstdint>
#include <vector>

#include "pathspace/accel/bvh_view.h"
#include "pathspace/scene/scene_view.h"

namespace pathspace {

struct BvhBuildStats {
  double build_seconds = 0.0;  // Embree's build and the flattening
  uint32_t nodes = 0;          // inner nodes (BvhNode)
  uint32_t leaves = 0;
  uint32_t prim_refs = 0;      // references in leaves (spatial splits reference a primitive more than once)
  uint32_t max_depth = 0;      // of inner nodes, root = 0
};

struct FlatBvh {
  std::vector<BvhNode> nodes;
  std::vector<uint32_t> prims;  // bvh_prim_ref values
  BvhBuildStats stats;

  // Valid while this FlatBvh lives and is not modified.
  BvhView view() const;
};

// Reads the scene's positions, triangles and spheres. The result keeps indices into them, not
// geometry: a BvhTracer pairs it with a view of the same scene. Primitives with non-finite bounds are left out, as Embree leaves them out.
// Throws pathspace::Error when Embree fails or the tree exceeds the traversal's limits. A scene that
// moves (motion blur, scene/motion.h) gets boxes around each triangle's whole motion.
FlatBvh build_bvh(const SceneView& scene);

}  // namespace pathspace
