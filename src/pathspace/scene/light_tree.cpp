#include "pathspace/scene/light_tree.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace pathspace {

namespace {

// v rotated by `angle` about the unit axis k (Rodrigues' formula).
Vec3 rotate(const Vec3& v, const Vec3& k, float angle) {
  const float c = std::cos(angle), s = std::sin(angle);
  return v * c + cross(k, v) * s + k * (dot(k, v) * (1.f - c));
}

struct Cone {
  Vec3 w;
  float cos_theta;
};

// The smallest cone holding cones a and b (both half-angles in [0, π]).
Cone merge_cones(const Cone& a, const Cone& b) {
  const float theta_a = safe_acos(a.cos_theta), theta_b = safe_acos(b.cos_theta);
  const float theta_d = safe_acos(dot(a.w, b.w));
  if (std::min(theta_d + theta_b, kPi) <= theta_a) return a;
  if (std::min(theta_d + theta_a, kPi) <= theta_b) return b;
  const float theta_o = 0.5f * (theta_a + theta_d + theta_b);
  if (theta_o >= kPi) return {a.w, -1.f};
  const Vec3 axis = cross(a.w, b.w);
  if (!(length_squared(axis) > 0.f)) return {a.w, -1.f};  // opposite axes
  return {normalize(rotate(a.w, normalize(axis), theta_o - theta_a)), std::cos(theta_o)};
}

float surface_area(const Bounds3& b) {
  const Vec3 d = max_vec(b.diagonal(), Vec3(0.f));
  return 2.f * (d.x * d.y + d.y * d.z + d.z * d.x);
}

struct Item {
  uint32_t light;
  LightBounds bounds;
};

struct Builder {
  std::vector<Item>& items;  // reordered into leaf order as the tree is built
  std::vector<LightTreeNode>& nodes;
  std::vector<uint32_t>& leaf_position;
  int depth = 0;

  // The split of items [begin, end) with the lowest cost, as a partition point; the middle by
  // count when their centres do not separate.
  size_t split(size_t begin, size_t end, const LightBounds& all);
  void build();
};

size_t Builder::split(size_t begin, size_t end, const LightBounds& all) {
  constexpr int kBuckets = 12;
  Bounds3 centres;
  for (size_t i = begin; i < end; ++i) centres.expand(items[i].bounds.box.center());
  const Vec3 extent = all.box.diagonal();
  const float longest = max_component(extent);
  auto bucket_of = [&](const Item& item, int axis) {
    const float lo = centres.lo[axis], hi = centres.hi[axis];
    const int k = int(float(kBuckets) * (item.bounds.box.center()[axis] - lo) / (hi - lo));
    return std::clamp(k, 0, kBuckets - 1);
  };
  auto cost = [](const LightBounds& b) { return b.phi * orientation_measure(b) * surface_area(b.box); };
  float best_cost = INFINITY;
  int best_axis = -1, best_bucket = -1;
  for (int axis = 0; axis < 3; ++axis) {
    if (!(centres.hi[axis] > centres.lo[axis])) continue;
    std::array<LightBounds, kBuckets> bucket{};  // phi 0: empty (merge_light_bounds skips it)
    for (size_t i = begin; i < end; ++i) {
      LightBounds& b = bucket[size_t(bucket_of(items[i], axis))];
      b = merge_light_bounds(b, items[i].bounds);
    }
    // Splits across a short axis of an elongated box cost more (pbrt-v4's K_r).
    const float aspect = extent[axis] > 0.f ? longest / extent[axis] : 1.f;
    std::array<LightBounds, kBuckets> above{};  // above[s]: buckets s + 1 and up
    for (int s = kBuckets - 2; s >= 0; --s) above[size_t(s)] = merge_light_bounds(above[size_t(s) + 1], bucket[size_t(s) + 1]);
    LightBounds below;
    for (int s = 0; s + 1 < kBuckets; ++s) {
      below = merge_light_bounds(below, bucket[size_t(s)]);
      if (!(below.phi > 0.f) || !(above[size_t(s)].phi > 0.f)) continue;
      const float c = aspect * (cost(below) + cost(above[size_t(s)]));
      if (c < best_cost) best_cost = c, best_axis = axis, best_bucket = s;
    }
  }
  if (best_axis < 0) return begin + (end - begin) / 2;
  const auto mid = std::partition(items.begin() + std::ptrdiff_t(begin), items.begin() + std::ptrdiff_t(end),
                                  [&](const Item& item) { return bucket_of(item, best_axis) <= best_bucket; });
  return size_t(mid - items.begin());
}

void Builder::build() {
  // Depth first with an explicit stack (a degenerate tree may be as deep as it has lights): each
  // node's first child follows it, and its second child patches the parent when it is reached.
  struct Task {
    size_t begin, end;
    uint32_t parent;  // whose second child this is, or kNone for a first child (or the root)
    int depth;
  };
  std::vector<Task> stack{{0, items.size(), LightTreeView::kNone, 0}};
  uint32_t leaves = 0;
  while (!stack.empty()) {
    const Task t = stack.back();
    stack.pop_back();
    const uint32_t index = uint32_t(nodes.size());
    if (t.parent != LightTreeView::kNone) {
      nodes[t.parent].index = index;
      nodes[t.parent].split = leaves;
    }
    depth = std::max(depth, t.depth);
    LightTreeNode node;
    if (t.end - t.begin == 1) {
      node.bounds = importance_bounds(items[t.begin].bounds);
      node.leaf = true;
      node.index = items[t.begin].light;
      leaf_position[node.index] = leaves++;
      nodes.push_back(node);
      continue;
    }
    LightBounds all;
    for (size_t i = t.begin; i < t.end; ++i) all = merge_light_bounds(all, items[i].bounds);
    node.bounds = importance_bounds(all);
    const size_t mid = split(t.begin, t.end, all);
    nodes.push_back(node);
    stack.push_back({mid, t.end, index, t.depth + 1});
    stack.push_back({t.begin, mid, LightTreeView::kNone, t.depth + 1});
  }
}

}  // namespace

float orientation_measure(const LightBounds& b) {
  const float theta_o = safe_acos(b.cos_theta_o), theta_e = safe_acos(b.cos_theta_e);
  const float theta_w = std::min(theta_o + theta_e, kPi);
  const float sin_o = std::sqrt(std::max(0.f, 1.f - b.cos_theta_o * b.cos_theta_o));
  // ∫ over the cone of normals (weight 1) plus ∫ from θo to θw of cos(θ − θo) over the sphere.
  return kTwoPi * (1.f - b.cos_theta_o) +
         0.5f * kPi * (b.cos_theta_o - std::cos(2.f * theta_w - theta_o) + 2.f * (theta_w - theta_o) * sin_o);
}

LightBounds merge_light_bounds(const LightBounds& a, const LightBounds& b) {
  if (!(a.phi > 0.f)) return b;
  if (!(b.phi > 0.f)) return a;
  LightBounds m;
  m.box = a.box;
  m.box.expand(b.box);
  const Cone c = merge_cones({a.w, a.cos_theta_o}, {b.w, b.cos_theta_o});
  m.w = c.w;
  m.cos_theta_o = c.cos_theta;
  m.cos_theta_e = std::min(a.cos_theta_e, b.cos_theta_e);
  m.phi = a.phi + b.phi;
  m.two_sided = a.two_sided || b.two_sided;
  return m;
}

LightTree::LightTree(const std::vector<std::optional<LightBounds>>& bounds) {
  leaf_position_.assign(bounds.size(), LightTreeView::kNone);
  std::vector<Item> items;
  for (size_t i = 0; i < bounds.size(); ++i) {
    if (!bounds[i]) infinite_.push_back(uint32_t(i));
    else if (bounds[i]->phi > 0.f) items.push_back({uint32_t(i), *bounds[i]});
  }
  if (items.empty()) return;
  Builder builder{items, nodes_, leaf_position_};
  builder.build();
  depth_ = builder.depth;
}

namespace {
bool same_bounds(const LightImportanceBounds& a, const LightImportanceBounds& b) {
  return a.center == b.center && a.radius2 == b.radius2 && a.w == b.w && a.phi == b.phi &&
         a.cos_theta_o == b.cos_theta_o && a.cos_theta_e == b.cos_theta_e && a.two_sided == b.two_sided;
}
}  // namespace

bool LightTree::can_differ_from_power() const {
  if (nodes_.empty()) return false;
  if (!infinite_.empty()) return true;
  const LightTreeNode* first = nullptr;
  for (const LightTreeNode& n : nodes_) {
    if (!n.leaf) continue;
    if (!first) first = &n;
    else if (!same_bounds(first->bounds, n.bounds)) return true;
  }
  return false;
}

LightTreeView LightTree::view() const {
  LightTreeView v;
  v.nodes = nodes_.empty() ? nullptr : nodes_.data();
  v.num_nodes = uint32_t(nodes_.size());
  v.leaf_position = leaf_position_.data();
  v.infinite = infinite_.empty() ? nullptr : infinite_.data();
  v.num_infinite = uint32_t(infinite_.size());
  v.active = true;
  return v;
}

}  // namespace pathspace
