// The light tree (host side): built from each light's bounds by Scene::finalize() when lights are
// selected by `--light-selection bvh`; kernels see it as a LightTreeView (lights/light_tree_view.h).
//
// Construction follows Conty Estevez and Kulla 2018 (sec. 4.3) as pbrt-v4 builds its light BVH:
// top down, one light per leaf; each split is the best of 12 buckets per axis by the surface area
// orientation heuristic, cost = power × orientation measure M_Ω × box area, with the box's aspect
// ratio penalising splits across its short axes.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "pathspace/lights/light_tree_view.h"

namespace pathspace {

class LightTree {
 public:
  LightTree() = default;
  // bounds[i]: light i's bounds, or nullopt for an infinite light (environment, directional).
  // Lights of zero power are left out of the tree and never picked.
  explicit LightTree(const std::vector<std::optional<LightBounds>>& bounds);

  LightTreeView view() const;
  const std::vector<LightTreeNode>& nodes() const { return nodes_; }
  // The tree's depth (a single leaf: 0).
  int depth() const { return depth_; }
  // False when the tree would pick exactly as power-proportional selection does, only slower: no
  // infinite lights and every finite light with the same bounds (so the same importance
  // everywhere and the same power; a Cornell box's emitter quad as two triangles), or no finite
  // light at all (the tree would pick the infinite ones uniformly; power is the better choice).
  bool can_differ_from_power() const;

 private:
  std::vector<LightTreeNode> nodes_;
  std::vector<uint32_t> leaf_position_, infinite_;
  int depth_ = 0;
};

// The union of two sets' bounds (the normals' cones merged into the smallest cone holding both).
LightBounds merge_light_bounds(const LightBounds& a, const LightBounds& b);

// The orientation measure M_Ω of a set's bounds (Conty Estevez and Kulla 2018, eq. 1): the cone of
// normals widened by the emission spread, integrated with cosine weights.
float orientation_measure(const LightBounds& b);

}  // namespace pathspace
