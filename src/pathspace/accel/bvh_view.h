// The flattened BVH a device traverses (accel/bvh_tracer.h), built on the host by accel/bvh_build.h:
// a binary tree in the layout of Aila & Laine 2009 ("Understanding the Efficiency of Ray Traversal
// on GPUs", HPG): a node holds the boxes of both children and their references, so one node fetch
// (four 16-byte loads) tests both children. Leaves are not nodes: a child reference < 0 encodes a
// range [first, first + count) of the primitive reference array. Plain arrays: a CUDA backend
// uploads nodes and prims with one copy each.
#pragma once

#include <cstdint>

#include "pathspace/geometry/shapes.h"
#include "pathspace/math/vec3.h"

namespace pathspace {

inline constexpr uint32_t kBvhMaxLeafSize = 4;   // primitives per leaf the builder is asked for
inline constexpr uint32_t kBvhLeafCountBits = 3;  // counts 0..7 fit a child reference
inline constexpr int kBvhStackSize = 64;          // traversal stack; the builder limits the depth to fit

struct alignas(16) BvhNode {
  // Child c's box: x and y in xy[c] as (lo.x, hi.x, lo.y, hi.y), z in z[2c], z[2c+1] (Aila-Laine's
  // grouping: the x/y slabs of both children come from two loads, the z slabs from one).
  float xy[2][4];
  float z[4];
  int32_t child[2];  // >= 0: inner node index; < 0: leaf (bvh_leaf_first / bvh_leaf_count)
  uint32_t unused[2] = {0, 0};

  PS_HD Vec3 lo(int c) const { return {xy[c][0], xy[c][2], z[2 * c]}; }
  PS_HD Vec3 hi(int c) const { return {xy[c][1], xy[c][3], z[2 * c + 1]}; }
};
static_assert(sizeof(BvhNode) == 64, "one node is four 16-byte loads");

PS_INLINE int32_t bvh_leaf_child(uint32_t first, uint32_t count) {
  return ~int32_t((first << kBvhLeafCountBits) | count);
}
PS_INLINE uint32_t bvh_leaf_first(int32_t child) { return uint32_t(~child) >> kBvhLeafCountBits; }
PS_INLINE uint32_t bvh_leaf_count(int32_t child) { return uint32_t(~child) & ((1u << kBvhLeafCountBits) - 1u); }

// A primitive reference: the kind in the top bit, the index into the scene's triangles or spheres.
PS_INLINE uint32_t bvh_prim_ref(ShapeKind kind, uint32_t index) { return (uint32_t(kind) << 31) | index; }
PS_INLINE ShapeKind bvh_ref_kind(uint32_t ref) { return (ref >> 31) ? ShapeKind::sphere : ShapeKind::triangle; }
PS_INLINE uint32_t bvh_ref_index(uint32_t ref) { return ref & 0x7fffffffu; }

// The device-safe view of a FlatBvh: no nodes for a scene without primitives; node 0 is the root.
struct BvhView {
  const BvhNode* nodes = nullptr;
  uint32_t num_nodes = 0;
  const uint32_t* prims = nullptr;  // primitive references, leaves' ranges index this
  uint32_t num_prims = 0;
};

}  // namespace pathspace
