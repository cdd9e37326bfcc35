// The light tree's device-safe view: picks one light for next event estimation at a shading point,
// with probability proportional to the importance (lights/light_bounds.h) of each subtree, walking
// from the root and choosing one child at each node (pbrt-v4's BVHLightSampler is the model).
// Infinite lights (environment, directional) have no bounds: one of them is picked with
// probability n_inf / (n_inf + 1), uniformly among them, the tree with the rest.
//
// A tree of one light always picks it (an unreachable light then contributes nothing).
// The probability of a light at a point (for MIS, when a BSDF-sampled ray finds an emitter) walks
// the same nodes from the root with the same arithmetic, steered by the light's leaf position, so
// sample() and probability() agree to the bit.
// The host builds the tree (scene/light_tree.h).
#pragma once

#include <cstdint>

#include "pathspace/lights/light_bounds.h"

namespace pathspace {

struct LightTreeNode {
  LightImportanceBounds bounds;
  // Interior: the second child's node index (the first child is the next node). Leaf: the light.
  uint32_t index = 0;
  // Interior: the leaf position of the second child's first leaf (leaves are numbered in tree order).
  uint32_t split = 0;
  bool leaf = false;
};

struct LightTreeView {
  static constexpr uint32_t kNone = 0xffffffffu;
  const LightTreeNode* nodes = nullptr;  // depth-first order, root first
  uint32_t num_nodes = 0;
  const uint32_t* leaf_position = nullptr;  // per light: its leaf's position, or kNone (infinite or unused)
  const uint32_t* infinite = nullptr;       // indices of the infinite lights
  uint32_t num_infinite = 0;
  bool active = false;  // false: lights are picked by the scene's discrete distribution instead

  PS_HD float infinite_probability() const {
    return num_infinite == 0 ? 0.f : float(num_infinite) / float(num_infinite + (num_nodes > 0 ? 1u : 0u));
  }

  // A light for the point p with normal n (zero: none), or kNone when no light can reach p; writes
  // its probability (0 with kNone).
  PS_HD uint32_t sample(const Vec3& p, const Vec3& n, float u, float* prob) const {
    *prob = 0.f;
    const float p_inf = infinite_probability();
    if (u < p_inf) {
      const uint32_t i = uint32_t(u / p_inf * float(num_infinite));
      const uint32_t last = num_infinite - 1;
      *prob = p_inf / float(num_infinite);
      return infinite[i < last ? i : last];
    }
    if (num_nodes == 0) return kNone;
    u = below_one((u - p_inf) / (1.f - p_inf));
    float pmf = 1.f - p_inf;
    uint32_t node = 0;
    while (!nodes[node].leaf) {
      float p_first;
      if (!first_child_probability(node, p, n, &p_first)) return kNone;
      if (u < p_first) {
        u = below_one(u / p_first);
        pmf *= p_first;
        node = node + 1;
      } else {
        u = below_one((u - p_first) / (1.f - p_first));
        pmf *= 1.f - p_first;
        node = nodes[node].index;
      }
    }
    *prob = pmf;
    return nodes[node].index;
  }

  // The probability that sample() picks `light` at (p, n).
  PS_HD float probability(const Vec3& p, const Vec3& n, uint32_t light) const {
    const uint32_t position = leaf_position[light];
    if (position == kNone) {
      for (uint32_t i = 0; i < num_infinite; ++i)
        if (infinite[i] == light) return infinite_probability() / float(num_infinite);
      return 0.f;
    }
    float pmf = 1.f - infinite_probability();
    uint32_t node = 0;
    while (!nodes[node].leaf) {
      float p_first;
      if (!first_child_probability(node, p, n, &p_first)) return 0.f;
      if (position < nodes[node].split) {
        pmf *= p_first;
        node = node + 1;
      } else {
        pmf *= 1.f - p_first;
        node = nodes[node].index;
      }
    }
    return pmf;
  }

 private:
  // The rescaled random number kept in [0, 1) (a compare and select, cheaper than fminf).
  PS_HD static float below_one(float u) { return u < kOneMinusEpsilon ? u : kOneMinusEpsilon; }
  // The probability of an interior node's first child; false when neither child can reach p.
  PS_HD bool first_child_probability(uint32_t node, const Vec3& p, const Vec3& n, float* p_first) const {
    const float a = light_bounds_importance(nodes[node + 1].bounds, p, n);
    const float b = light_bounds_importance(nodes[nodes[node].index].bounds, p, n);
    if (!(a > 0.f) && !(b > 0.f)) return false;
    // a / (a + b), written so that one or both infinite (a point light at distance ~0) stays exact.
    if (a == b) *p_first = 0.5f;
    else if (a > b) *p_first = 1.f / (1.f + b / a);
    else *p_first = (a / b) / (1.f + a / b);
    return true;
  }
};

}  // namespace pathspace
