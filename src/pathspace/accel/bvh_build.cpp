// Flat BVH build (accel/bvh_build.h): Embree 3's BVH builder API (rtcBuildBVH) makes a binary SAH
// tree with spatial splits (Stich, Friedrich, Dietrich 2009, "Spatial Splits in Bounding Volume
// Hierarchies"; RTC_BUILD_QUALITY_HIGH with a split callback), in nodes allocated from Embree's
// thread-local allocator; the tree is then copied depth-first into the Aila-Laine layout of
// accel/bvh_view.h, near children next to their parents.
#include "pathspace/accel/bvh_build.h"

#include <embree3/rtcore.h>
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <new>

#include "pathspace/base/error.h"
#include "pathspace/math/bbox.h"

namespace pathspace {

namespace {

constexpr unsigned kTriangleGeom = 0, kSphereGeom = 1;  // RTCBuildPrimitive::geomID
// Inner-node depth limit: the traversal pushes at most one entry per level (bvh_tracer.h).
constexpr unsigned kMaxDepth = kBvhStackSize - 8;

// The temporary tree Embree's callbacks build.
struct BuildNode {
  bool leaf = false;
};
struct BuildInner : BuildNode {
  BuildNode* child[2] = {nullptr, nullptr};
  Bounds3 bounds[2];
};
struct BuildLeaf : BuildNode {
  uint32_t count = 0;
  uint32_t* refs = nullptr;  // `count` bvh_prim_ref values
};

Bounds3 to_bounds(const RTCBounds& b) { return {Vec3(b.lower_x, b.lower_y, b.lower_z), Vec3(b.upper_x, b.upper_y, b.upper_z)}; }

void* create_node(RTCThreadLocalAllocator alloc, unsigned int child_count, void*) {
  if (child_count != 2) return nullptr;  // maxBranchingFactor is 2
  void* mem = rtcThreadLocalAlloc(alloc, sizeof(BuildInner), 16);
  return new (mem) BuildInner();
}

void set_children(void* node, void** children, unsigned int count, void*) {
  auto* inner = static_cast<BuildInner*>(node);
  for (unsigned i = 0; i < count && i < 2; ++i) inner->child[i] = static_cast<BuildNode*>(children[i]);
}

void set_bounds(void* node, const RTCBounds** bounds, unsigned int count, void*) {
  auto* inner = static_cast<BuildInner*>(node);
  for (unsigned i = 0; i < count && i < 2; ++i) inner->bounds[i] = to_bounds(*bounds[i]);
}

void* create_leaf(RTCThreadLocalAllocator alloc, const RTCBuildPrimitive* prims, size_t count, void*) {
  auto* leaf = new (rtcThreadLocalAlloc(alloc, sizeof(BuildLeaf), 16)) BuildLeaf();
  leaf->leaf = true;
  leaf->count = uint32_t(count);
  leaf->refs = static_cast<uint32_t*>(rtcThreadLocalAlloc(alloc, std::max<size_t>(count, 1) * sizeof(uint32_t), 4));
  for (size_t i = 0; i < count; ++i)
    leaf->refs[i] = bvh_prim_ref(prims[i].geomID == kTriangleGeom ? ShapeKind::triangle : ShapeKind::sphere, prims[i].primID);
  return leaf;
}

// Box of the part of a triangle on either side of the plane x[dim] = pos (Stich et al. 2009, sec.
// 4.2: clip the triangle, not its box), limited to the reference's current box (it may already be a
// split part). Clipped points are rounded, so the boxes are widened by a relative 2^-20: a box that
// is too large costs a little time, one too small would lose hits.
// Component-wise min / max as a compare and a select: fminf / fmaxf are libm calls in GCC without
// -ffinite-math-only, and the builder calls this for every candidate split (most of the build time).
Vec3 lower(const Vec3& a, const Vec3& b) { return {min_of(a.x, b.x), min_of(a.y, b.y), min_of(a.z, b.z)}; }
Vec3 upper(const Vec3& a, const Vec3& b) { return {max_of(a.x, b.x), max_of(a.y, b.y), max_of(a.z, b.z)}; }
void grow(Bounds3* b, const Vec3& p) {
  b->lo = lower(b->lo, p);
  b->hi = upper(b->hi, p);
}

void split_primitive(const RTCBuildPrimitive* prim, unsigned int dim, float pos, RTCBounds* left_out,
                     RTCBounds* right_out, void* user) {
  const auto& scene = *static_cast<const SceneView*>(user);
  const Bounds3 box{Vec3(prim->lower_x, prim->lower_y, prim->lower_z), Vec3(prim->upper_x, prim->upper_y, prim->upper_z)};
  Bounds3 left, right;
  if (prim->geomID == kTriangleGeom) {
    const Triangle& tri = scene.triangles[prim->primID];
    for (int i = 0; i < 3; ++i) {
      const Vec3 a = scene.positions[tri.v[i]], b = scene.positions[tri.v[(i + 1) % 3]];
      const float da = a[int(dim)], db = b[int(dim)];
      if (da <= pos) grow(&left, a);
      if (da >= pos) grow(&right, a);
      if ((da < pos && pos < db) || (db < pos && pos < da)) {
        Vec3 c = a + (b - a) * ((pos - da) / (db - da));
        c[int(dim)] = pos;
        grow(&left, c);
        grow(&right, c);
      }
    }
    for (Bounds3* b : {&left, &right}) {
      if (b->empty()) continue;
      const Vec3 m = upper(upper(b->lo, -b->lo), upper(b->hi, -b->hi));
      const float pad = 0x1p-20f * max_of(m.x, max_of(m.y, m.z));
      b->lo = b->lo - Vec3(pad);
      b->hi = b->hi + Vec3(pad);
    }
  } else {
    left = right = box;  // a sphere's part: its box cut at the plane
  }
  left.lo = upper(left.lo, box.lo);
  left.hi = lower(left.hi, box.hi);
  right.lo = upper(right.lo, box.lo);
  right.hi = lower(right.hi, box.hi);
  left.hi[int(dim)] = min_of(left.hi[int(dim)], pos);
  right.lo[int(dim)] = max_of(right.lo[int(dim)], pos);
  if (left.empty()) left = {Vec3(pos), Vec3(pos)};  // a point box on the plane: harmless
  if (right.empty()) right = {Vec3(pos), Vec3(pos)};
  *left_out = {left.lo.x, left.lo.y, left.lo.z, 0.f, left.hi.x, left.hi.y, left.hi.z, 0.f};
  *right_out = {right.lo.x, right.lo.y, right.lo.z, 0.f, right.hi.x, right.hi.y, right.hi.z, 0.f};
}

bool finite_box(const Bounds3& b) { return all_finite(b.lo) && all_finite(b.hi); }

RTCBuildPrimitive build_primitive(const Bounds3& b, unsigned geom, uint32_t prim) {
  RTCBuildPrimitive p;
  p.lower_x = b.lo.x, p.lower_y = b.lo.y, p.lower_z = b.lo.z, p.geomID = geom;
  p.upper_x = b.hi.x, p.upper_y = b.hi.y, p.upper_z = b.hi.z, p.primID = prim;
  return p;
}

void set_child_box(BvhNode& node, int c, const Bounds3& b) {
  node.xy[c][0] = b.lo.x, node.xy[c][1] = b.hi.x, node.xy[c][2] = b.lo.y, node.xy[c][3] = b.hi.y;
  node.z[2 * c] = b.lo.z, node.z[2 * c + 1] = b.hi.z;
}

// Depth-first copy into the flat arrays; returns the child reference of `n`.
int32_t flatten(const BuildNode* n, uint32_t depth, FlatBvh& out) {
  if (n->leaf) {
    const auto* leaf = static_cast<const BuildLeaf*>(n);
    const uint32_t first = uint32_t(out.prims.size());
    if (leaf->count >= (1u << kBvhLeafCountBits)) throw Error(fmt::format("BVH leaf of {} primitives", leaf->count));
    out.prims.insert(out.prims.end(), leaf->refs, leaf->refs + leaf->count);
    out.stats.leaves++;
    return bvh_leaf_child(first, leaf->count);
  }
  if (depth >= kMaxDepth) throw Error(fmt::format("BVH deeper than {} levels", kMaxDepth));
  out.stats.max_depth = std::max(out.stats.max_depth, depth);
  const auto* inner = static_cast<const BuildInner*>(n);
  const auto index = int32_t(out.nodes.size());
  out.nodes.emplace_back();
  for (int c = 0; c < 2; ++c) set_child_box(out.nodes[size_t(index)], c, inner->bounds[c]);
  for (int c = 0; c < 2; ++c) {
    const int32_t child = flatten(inner->child[c], depth + 1, out);
    out.nodes[size_t(index)].child[c] = child;  // not a reference held across the recursion (reallocation)
  }
  return index;
}

struct DeviceHandle {
  RTCDevice device = rtcNewDevice(nullptr);
  ~DeviceHandle() {
    if (device) rtcReleaseDevice(device);
  }
};
struct BvhHandle {
  RTCBVH bvh;
  ~BvhHandle() {
    if (bvh) rtcReleaseBVH(bvh);
  }
};

}  // namespace

BvhView FlatBvh::view() const {
  return {nodes.data(), uint32_t(nodes.size()), prims.data(), uint32_t(prims.size())};
}

FlatBvh build_bvh(const SceneView& scene) {
  const auto start = std::chrono::steady_clock::now();
  FlatBvh out;
  std::vector<RTCBuildPrimitive> prims;
  for (uint32_t i = 0; i < scene.num_triangles; ++i) {
    const Triangle& tri = scene.triangles[i];
    Bounds3 b;
    for (uint32_t v : tri.v) b.expand(scene.positions[v]);
    if (scene.positions_end)  // motion blur: the box holds the triangle at every time (linear motion)
      for (uint32_t v : tri.v) b.expand(scene.positions_end[v]);
    if (finite_box(b)) prims.push_back(build_primitive(b, kTriangleGeom, i));
  }
  for (uint32_t i = 0; i < scene.num_spheres; ++i) {
    const Sphere& s = scene.spheres[i];
    const Bounds3 b{s.center - Vec3(s.radius), s.center + Vec3(s.radius)};
    if (finite_box(b)) prims.push_back(build_primitive(b, kSphereGeom, i));
  }
  const size_t count = prims.size();
  // Leaf child references keep the first primitive in 28 bits; spatial splits at most double the refs.
  if (2 * count >= (size_t(1) << (31 - kBvhLeafCountBits))) throw Error(fmt::format("too many primitives for the BVH ({})", count));
  if (count > 0) {
    prims.resize(2 * count);  // room for the references spatial splits add
    DeviceHandle device;
    if (!device.device) throw Error("cannot create an Embree device for the BVH build");
    BvhHandle bvh{rtcNewBVH(device.device)};
    RTCBuildArguments args = rtcDefaultBuildArguments();
    // Spatial splits clip a triangle at a plane, which a moving one crosses at different places over
    // the shutter: scenes that move are built without them.
    args.buildQuality = scene.positions_end ? RTC_BUILD_QUALITY_MEDIUM : RTC_BUILD_QUALITY_HIGH;
    args.maxBranchingFactor = 2;
    args.maxDepth = kMaxDepth;
    args.minLeafSize = 1;
    args.maxLeafSize = kBvhMaxLeafSize;
    // One node visit (two box tests) costs about one primitive test: the SAH trades them one to one.
    args.traversalCost = 1.f;
    args.intersectionCost = 1.f;
    args.bvh = bvh.bvh;
    args.primitives = prims.data();
    args.primitiveCount = count;
    args.primitiveArrayCapacity = prims.size();
    args.createNode = create_node;
    args.setNodeChildren = set_children;
    args.setNodeBounds = set_bounds;
    args.createLeaf = create_leaf;
    args.splitPrimitive = scene.positions_end ? nullptr : split_primitive;
    args.userPtr = const_cast<SceneView*>(&scene);
    const auto* root = static_cast<const BuildNode*>(rtcBuildBVH(&args));
    const RTCError err = rtcGetDeviceError(device.device);
    if (!root || err != RTC_ERROR_NONE) throw Error(fmt::format("Embree failed to build the BVH (error {})", int(err)));
    if (root->leaf) {
      // A tree that is one leaf: a root whose second child is an empty leaf.
      const auto* leaf = static_cast<const BuildLeaf*>(root);
      BvhNode node{};
      Bounds3 b;
      for (uint32_t i = 0; i < count; ++i) b.expand(Bounds3{Vec3(prims[i].lower_x, prims[i].lower_y, prims[i].lower_z),
                                                            Vec3(prims[i].upper_x, prims[i].upper_y, prims[i].upper_z)});
      set_child_box(node, 0, b);
      set_child_box(node, 1, Bounds3{b.lo, b.lo});
      node.child[0] = bvh_leaf_child(0, leaf->count);
      node.child[1] = bvh_leaf_child(leaf->count, 0);
      out.nodes.push_back(node);
      out.prims.assign(leaf->refs, leaf->refs + leaf->count);
      out.stats.leaves = 1;
    } else {
      flatten(root, 0, out);
    }
  }
  out.stats.nodes = uint32_t(out.nodes.size());
  out.stats.prim_refs = uint32_t(out.prims.size());
  out.stats.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace pathspace
