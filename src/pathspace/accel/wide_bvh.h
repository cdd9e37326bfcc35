// An 8-wide BVH with quantised child boxes (after Ylitie, Karras, Laine 2017, "Efficient
// Incoherent Ray Traversal on GPUs Through Compressed Wide BVHs", HPG), built by collapsing the
// binary tree of accel/bvh_build.h (accel/wide_bvh_build.h), and its device-safe tracer. A node
// holds up to eight children: each child's box as 8-bit offsets from the node's origin on a grid of
// power-of-two steps per axis, rounded outwards, so a box never shrinks; and a child reference as
// in BvhNode (>= 0 an inner node, < 0 a leaf's primitive range in the binary tree's array). One node
// is 96 bytes (six 16-byte loads) for eight boxes, against 64 bytes for two. Unlike the paper's 80
// bytes, children keep explicit references instead of a base index and a mask, and the traversal
// orders the children it hits by entry distance with a stack instead of the paper's octant order and
// hit masks. The primitive tests are the binary tracer's (accel/bvh_tracer.h), so both find the
// same nearest t for every ray and the same answer for every shadow ray.
#pragma once

#include <cstdint>
#include <cstring>

#include "pathspace/accel/bvh_tracer.h"

namespace pathspace {

inline constexpr int kWideBvhWidth = 8;
inline constexpr int kWideBvhStackSize = 256;  // the builder limits depth so that 7 per level fit

struct alignas(16) WideBvhNode {
  float origin[3];          // the grid's corner: the low corner of the union of the children's boxes
  int8_t exponent[3];       // the grid step per axis is 2^exponent
  uint8_t count;            // children in use, the first `count`
  int32_t child[kWideBvhWidth];
  uint8_t qlo[3][kWideBvhWidth], qhi[3][kWideBvhWidth];  // per axis, per child, in grid steps
};
static_assert(sizeof(WideBvhNode) == 96, "a wide node is six 16-byte loads");

// The device-safe view: node 0 is the root; prims are the binary tree's references.
struct WideBvhView {
  const WideBvhNode* nodes = nullptr;
  uint32_t num_nodes = 0;
  const uint32_t* prims = nullptr;
  uint32_t num_prims = 0;
};

namespace wide_bvh_detail {

// 2^e as a float, exactly, for the exponents a node stores (|e| < 127).
PS_INLINE float exp2_int(int e) {
  const uint32_t bits = uint32_t(e + 127) << 23;
  float f;
  memcpy(&f, &bits, sizeof f);
  return f;
}

// Child c's box as the traversal decodes it (and the builder checks it): origin + q * step.
PS_INLINE Vec3 child_lo(const WideBvhNode& n, int c) {
  return {n.origin[0] + float(n.qlo[0][c]) * exp2_int(n.exponent[0]), n.origin[1] + float(n.qlo[1][c]) * exp2_int(n.exponent[1]),
          n.origin[2] + float(n.qlo[2][c]) * exp2_int(n.exponent[2])};
}
PS_INLINE Vec3 child_hi(const WideBvhNode& n, int c) {
  return {n.origin[0] + float(n.qhi[0][c]) * exp2_int(n.exponent[0]), n.origin[1] + float(n.qhi[1][c]) * exp2_int(n.exponent[1]),
          n.origin[2] + float(n.qhi[2][c]) * exp2_int(n.exponent[2])};
}

// Nearest hit (or any hit: shadow rays) as bvh_detail::traverse, over the wide tree: a node's hit
// children go on the stack farthest first, so the nearest is taken next.
template <bool AnyHit, bool Moving>
PS_HD bool traverse(const SceneView& scene, const WideBvhView& bvh, const Ray& ray, float* t_out, uint32_t* ref_out,
                    float* u_out, float* v_out) {
  if (bvh.num_nodes == 0) return false;
  const bvh_detail::RayPrep r = bvh_detail::prepare(ray);
  const float tmin = ray.tmin;
  float tmax = ray.tmax;
  bool found = false;
  int32_t stack[kWideBvhStackSize];
  int sp = 0;
  stack[sp++] = 0;  // the root, an inner node
  while (sp > 0) {
    const int32_t item = stack[--sp];
    if (item < 0) {
      const uint32_t first = bvh_leaf_first(item), end = first + bvh_leaf_count(item);
      for (uint32_t i = first; i < end; ++i) {
        float t, u, v;
        if (!bvh_detail::intersect_prim<Moving>(scene, r, bvh.prims[i], tmin, tmax, &t, &u, &v)) continue;
        found = true;
        tmax = t;  // later primitives must be nearer
        *t_out = t;
        *ref_out = bvh.prims[i];
        *u_out = u;
        *v_out = v;
        if (AnyHit) return true;
      }
      continue;
    }
    const WideBvhNode& node = bvh.nodes[item];
    int32_t hit_child[kWideBvhWidth];
    float hit_entry[kWideBvhWidth];
    int hits = 0;
    for (int c = 0; c < node.count; ++c) {
      float entry;
      if (!bvh_detail::hit_box(r, child_lo(node, c), child_hi(node, c), tmin, tmax, &entry)) continue;
      // Insertion by entry distance, farthest first.
      int k = hits++;
      while (k > 0 && hit_entry[k - 1] < entry) {
        hit_entry[k] = hit_entry[k - 1];
        hit_child[k] = hit_child[k - 1];
        --k;
      }
      hit_entry[k] = entry;
      hit_child[k] = node.child[c];
    }
    for (int k = 0; k < hits; ++k) stack[sp++] = hit_child[k];
  }
  return found;
}

}  // namespace wide_bvh_detail

template <>
struct TreeTraversal<WideBvhView> {
  template <bool AnyHit, bool Moving>
  PS_HD static bool run(const SceneView& scene, const WideBvhView& bvh, const Ray& ray, float* t, uint32_t* ref, float* u,
                        float* v) {
    return wide_bvh_detail::traverse<AnyHit, Moving>(scene, bvh, ray, t, ref, u, v);
  }
};

// The Tracer interface (intersect / occluded) over a wide BVH, as BvhTracer over the binary one.
using WideBvhTracer = TreeTracer<WideBvhView>;

}  // namespace pathspace
