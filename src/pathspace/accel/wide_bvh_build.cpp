// The greedy collapse of a binary BVH into the wide one, and the conservative quantisation of the
// children's boxes (accel/wide_bvh_build.h).
#include "pathspace/accel/wide_bvh_build.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "pathspace/base/error.h"
#include "pathspace/math/bbox.h"

namespace pathspace {

namespace {

struct Child {
  int32_t ref;  // as BvhNode::child
  Bounds3 box;
};

float surface_area(const Bounds3& b) {
  const Vec3 d = b.hi - b.lo;
  return 2.f * (d.x * d.y + d.y * d.z + d.z * d.x);
}

// The smallest exponent whose grid of 255 steps from `lo` reaches `hi` (an axis may be flat).
int grid_exponent(float lo, float hi) {
  int e = -126;
  const float extent = hi - lo;
  if (extent > 0.f) e = std::max(e, int(std::ceil(std::log2(double(extent) / 255.0))));
  while (e < 126 && lo + 255.f * wide_bvh_detail::exp2_int(e) < hi) ++e;
  return e;
}

class Collapse {
 public:
  explicit Collapse(const FlatBvh& binary) : binary_(binary) {}

  // Builds the wide node for binary inner node `index`; returns its index.
  int32_t node(int32_t index, uint32_t depth) {
    const uint32_t wide_depth_limit = kWideBvhStackSize / (kWideBvhWidth - 1) - 2;
    if (depth > wide_depth_limit)
      throw Error(fmt::format("the wide BVH is deeper than its traversal stack allows ({} levels)", wide_depth_limit));
    stats_.max_depth = std::max(stats_.max_depth, depth);
    Child children[kWideBvhWidth];
    int count = 0;
    add_children(index, children, &count);
    while (count < kWideBvhWidth) {
      int widest = -1;
      for (int c = 0; c < count; ++c) {
        const bool wider = widest < 0 || surface_area(children[c].box) > surface_area(children[widest].box);
        if (children[c].ref >= 0 && wider) widest = c;
      }
      if (widest < 0) break;
      const int32_t opened = children[widest].ref;
      children[widest] = children[--count];
      add_children(opened, children, &count);
    }
    const int32_t self = int32_t(nodes_.size());
    nodes_.push_back(quantise(children, count));
    for (int c = 0; c < count; ++c)
      if (children[c].ref >= 0) nodes_[size_t(self)].child[c] = node(children[c].ref, depth + 1);
    return self;
  }

  std::vector<WideBvhNode> take_nodes() { return std::move(nodes_); }
  WideBvhStats stats() const { return stats_; }

 private:
  void add_children(int32_t index, Child* children, int* count) const {
    const BvhNode& n = binary_.nodes[size_t(index)];
    for (int c = 0; c < 2; ++c) children[(*count)++] = Child{n.child[c], Bounds3{n.lo(c), n.hi(c)}};
  }

  // Children's boxes on the node's grid, rounded outwards until the decoded box holds the exact one.
  static WideBvhNode quantise(const Child* children, int count) {
    WideBvhNode n{};
    n.count = uint8_t(count);
    Bounds3 all;
    for (int c = 0; c < count; ++c) all.expand(children[c].box);
    for (int a = 0; a < 3; ++a) {
      n.origin[a] = all.lo[a];
      n.exponent[a] = int8_t(grid_exponent(all.lo[a], all.hi[a]));
    }
    for (int c = 0; c < count; ++c) {
      n.child[c] = children[c].ref;
      for (int a = 0; a < 3; ++a) {
        const float step = wide_bvh_detail::exp2_int(n.exponent[a]);
        const float lo = children[c].box.lo[a], hi = children[c].box.hi[a];
        int qlo = std::clamp(int(std::floor((lo - n.origin[a]) / step)), 0, 255);
        int qhi = std::clamp(int(std::ceil((hi - n.origin[a]) / step)), 0, 255);
        while (qlo > 0 && n.origin[a] + float(qlo) * step > lo) --qlo;
        while (qhi < 255 && n.origin[a] + float(qhi) * step < hi) ++qhi;
        n.qlo[a][c] = uint8_t(qlo);
        n.qhi[a][c] = uint8_t(qhi);
      }
    }
    for (int c = 0; c < count; ++c) {  // the decoding the traversal does must hold the exact box
      const Vec3 lo = wide_bvh_detail::child_lo(n, c), hi = wide_bvh_detail::child_hi(n, c);
      for (int a = 0; a < 3; ++a)
        if (lo[a] > children[c].box.lo[a] || hi[a] < children[c].box.hi[a])
          throw Error("wide BVH: a quantised child box does not hold its child (a bug in the builder)");
    }
    return n;
  }

  const FlatBvh& binary_;
  std::vector<WideBvhNode> nodes_;
  WideBvhStats stats_;
};

}  // namespace

WideBvhView WideBvh::view() const {
  return {nodes.empty() ? nullptr : nodes.data(), uint32_t(nodes.size()), prims.empty() ? nullptr : prims.data(), uint32_t(prims.size())};
}

WideBvh build_wide_bvh(const FlatBvh& binary) {
  WideBvh wide;
  wide.prims = binary.prims;
  if (binary.nodes.empty()) return wide;
  Collapse collapse(binary);
  collapse.node(0, 0);
  wide.nodes = collapse.take_nodes();
  wide.stats = collapse.stats();
  wide.stats.nodes = uint32_t(wide.nodes.size());
  double children = 0.0;
  for (const WideBvhNode& n : wide.nodes) children += n.count;
  wide.stats.mean_children = children / double(wide.nodes.size());
  return wide;
}

}  // namespace pathspace
