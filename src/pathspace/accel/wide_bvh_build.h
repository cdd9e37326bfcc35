// Host-side build of the wide BVH (accel/wide_bvh.h) by collapsing the binary tree of
// accel/bvh_build.h: a wide node starts from a binary node's two children and opens the inner child
// with the largest box surface area until it has eight children or only leaves (the greedy
// collapse; Ylitie et al. 2017 choose by an SAH cost instead). Leaves stay the binary tree's
// primitive ranges, so the wide tree shares its primitive array.
#pragma once

#include <cstdint>
#include <vector>

#include "pathspace/accel/bvh_build.h"
#include "pathspace/accel/wide_bvh.h"

namespace pathspace {

struct WideBvhStats {
  uint32_t nodes = 0;           // wide inner nodes
  uint32_t max_depth = 0;       // of wide inner nodes, root = 0
  double mean_children = 0.0;   // per wide node
};

struct WideBvh {
  std::vector<WideBvhNode> nodes;
  std::vector<uint32_t> prims;  // a copy of the binary tree's
  WideBvhStats stats;

  // Valid while this WideBvh lives and is not modified.
  WideBvhView view() const;
};

// Throws pathspace::Error when the tree is deeper than the traversal's stack allows.
WideBvh build_wide_bvh(const FlatBvh& binary);

}  // namespace pathspace
