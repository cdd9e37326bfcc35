// BvhTracer: the device-safe Tracer (intersect / occluded, as accel/accel.h's Accel) over a flat BVH
// (accel/bvh_view.h, built by accel/bvh_build.h), for GPUs without ray-tracing cores.
// Traversal: Aila & Laine 2009 ("Understanding the Efficiency of Ray Traversal on GPUs", HPG), the
// while-while loop with a local stack, the nearer child first. Boxes: slab test with the far
// distance scaled up as in Ize 2013 ("Robust BVH Ray Traversal", JCGT 2(2)), so rounding never
// culls a box the ray touches. Triangles: Woop, Benthin, Wald 2013 ("Watertight Ray/Triangle
// Intersection", JCGT 2(1)): no ray slips between triangles that share an edge (t itself comes
// from the plane equation, see intersect_triangle). Spheres:
// geometry/shapes.h's intersect_sphere, as the Embree backend. Hits are filled by
// accel/surface_hit_fill.h, like the Embree backend's, with Embree's interval (tmin, tmax).
// Cutouts (scene/surface_opacity.h) are skipped in the triangle test. Moving triangles (motion blur,
// scene/motion.h) are tested where they are at the ray's time, inside boxes that hold their motion.
#pragma once

#include <cstdint>

#include "pathspace/accel/bvh_view.h"
#include "pathspace/accel/surface_hit_fill.h"
#include "pathspace/geometry/ray.h"
#include "pathspace/math/scalar.h"
#include "pathspace/scene/motion.h"
#include "pathspace/scene/scene_view.h"
#include "pathspace/scene/surface_opacity.h"

namespace pathspace {

namespace bvh_detail {

// Per-ray constants of the slab test and of the watertight triangle test.
struct RayPrep {
  Vec3 o, d;
  float time;      // the ray's (scene/motion.h)
  Vec3 inv_d;      // 1/d, exact zeros replaced by a tiny value of the same sign (no 0 * inf = NaN)
  int kx, ky, kz;  // Woop et al. sec. 3: kz the dominant axis of d, kx/ky the others, winding kept
  float sx, sy;
};

PS_INLINE float nonzero(float x) { return x != 0.f ? x : copysignf(1e-30f, x); }

PS_INLINE RayPrep prepare(const Ray& ray) {
  RayPrep r;
  r.o = ray.o;
  r.d = ray.d;
  r.time = ray.time;
  r.inv_d = Vec3(1.f / nonzero(ray.d.x), 1.f / nonzero(ray.d.y), 1.f / nonzero(ray.d.z));
  const float ax = fabsf(ray.d.x), ay = fabsf(ray.d.y), az = fabsf(ray.d.z);
  r.kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
  r.kx = r.kz == 2 ? 0 : r.kz + 1;
  r.ky = r.kx == 2 ? 0 : r.kx + 1;
  if (ray.d[r.kz] < 0.f) {  // swapping keeps the winding, so U, V, W keep their signs' meaning
    const int tmp = r.kx;
    r.kx = r.ky;
    r.ky = tmp;
  }
  r.sx = ray.d[r.kx] / ray.d[r.kz];
  r.sy = ray.d[r.ky] / ray.d[r.kz];
  return r;
}

// Entry distance of the box [lo, hi] when the ray's (tmin, tmax) interval overlaps it.
// Ize 2013: the far distance times 1 + 2 gamma(3) covers the rounding of the three slab products.
PS_INLINE bool hit_box(const RayPrep& r, const Vec3& lo, const Vec3& hi, float tmin, float tmax, float* entry) {
  const float x0 = (lo.x - r.o.x) * r.inv_d.x, x1 = (hi.x - r.o.x) * r.inv_d.x;
  const float y0 = (lo.y - r.o.y) * r.inv_d.y, y1 = (hi.y - r.o.y) * r.inv_d.y;
  const float z0 = (lo.z - r.o.z) * r.inv_d.z, z1 = (hi.z - r.o.z) * r.inv_d.z;
  // min_of / max_of (a compare and a select), not fminf / fmaxf: no NaN reaches here, and GCC calls
  // libm for fminf without -ffinite-math-only (half of the CPU time).
  const float t_near = max_of(max_of(min_of(x0, x1), min_of(y0, y1)), max_of(min_of(z0, z1), tmin));
  const float t_far = min_of(min_of(max_of(x0, x1), max_of(y0, y1)), min_of(max_of(z0, z1), tmax)) * 1.0000004f;
  *entry = t_near;
  return t_near <= t_far;
}

// hit_box for child c of a binary node.
PS_INLINE bool hit_child_box(const RayPrep& r, const BvhNode& node, int c, float tmin, float tmax, float* entry) {
  return hit_box(r, node.lo(c), node.hi(c), tmin, tmax, entry);
}

// Woop, Benthin, Wald 2013, fig. 6 (without backface culling) for the hit decision. On a hit in (tmin, tmax): t, and u, v
// the barycentrics of vertices 1 and 2 (Embree's convention for surface_hit_fill.h).
PS_INLINE bool intersect_triangle(const RayPrep& r, const Vec3& p0, const Vec3& p1, const Vec3& p2, float tmin,
                                  float tmax, float* t, float* u, float* v) {
  const Vec3 a = p0 - r.o, b = p1 - r.o, c = p2 - r.o;
  // Shear the vertices so that the ray is the +z axis from the origin (the scale of z only serves t).
  const float ax = a[r.kx] - r.sx * a[r.kz], ay = a[r.ky] - r.sy * a[r.kz];
  const float bx = b[r.kx] - r.sx * b[r.kz], by = b[r.ky] - r.sy * b[r.kz];
  const float cx = c[r.kx] - r.sx * c[r.kz], cy = c[r.ky] - r.sy * c[r.kz];
  // Scaled barycentrics: 2D edge functions of the edges opposite vertices 0, 1, 2.
  float e0 = cx * by - cy * bx, e1 = ax * cy - ay * cx, e2 = bx * ay - by * ax;
  if (e0 == 0.f || e1 == 0.f || e2 == 0.f) {
    // Exactly on an edge in float: decide in double, so that both triangles sharing the edge agree
    // (sec. 4: the fallback that makes the test watertight).
    e0 = float(double(cx) * double(by) - double(cy) * double(bx));
    e1 = float(double(ax) * double(cy) - double(ay) * double(cx));
    e2 = float(double(bx) * double(ay) - double(by) * double(ax));
  }
  if ((e0 < 0.f || e1 < 0.f || e2 < 0.f) && (e0 > 0.f || e1 > 0.f || e2 > 0.f)) return false;
  const float det = e0 + e1 + e2;
  if (det == 0.f) return false;  // seen edge-on
  // t from the triangle's plane, as Embree computes it, not Woop et al.'s interpolation of the
  // vertices' sheared distances, which cancels for a long sliver hit near the ray's origin (1e-3
  // relative error in Bitterli's living room). The edge test above keeps the test watertight.
  const Vec3 n = cross(p1 - p0, p2 - p0);
  const float t_hit = dot(n, a) / dot(n, r.d);  // a ray in the plane: inf or NaN, rejected below
  if (!(t_hit > tmin && t_hit < tmax)) return false;
  const float inv_det = 1.f / det;
  *t = t_hit;
  *u = e1 * inv_det;
  *v = e2 * inv_det;
  return true;
}

// The primitive `ref` against the ray in (tmin, tmax). Moving: the scene moves (motion blur), so a
// triangle's vertices are those at the ray's time; a template parameter, so that still scenes keep
// the loop they had (the test in the loop cost the GPU 5-7% per frame).
template <bool Moving>
PS_INLINE bool intersect_prim(const SceneView& scene, const RayPrep& r, uint32_t ref, float tmin, float tmax, float* t,
                              float* u, float* v) {
  const uint32_t index = bvh_ref_index(ref);
  if (bvh_ref_kind(ref) == ShapeKind::triangle) {
    const Triangle& tri = scene.triangles[index];
    if constexpr (Moving) {
      const TriangleVertices p = triangle_at(scene, tri, r.time);
      if (!intersect_triangle(r, p.p0, p.p1, p.p2, tmin, tmax, t, u, v)) return false;
    } else {
      if (!intersect_triangle(r, scene.positions[tri.v[0]], scene.positions[tri.v[1]], scene.positions[tri.v[2]], tmin,
                              tmax, t, u, v))
        return false;
    }
    // A cutout the ray passes through is no hit (scene/surface_opacity.h; Embree's filter does the same).
    return !(scene.has_cutouts &&
             ray_passes_cutout(scene.triangles, scene.materials, scene.uvs, scene.textures, index, *u, *v, r.o, r.d));
  }
  *u = *v = 0.f;
  return intersect_sphere(scene.spheres[index], r.o, r.d, tmin, tmax, t);
}

// Aila-Laine's while-while traversal. AnyHit: stop at the first primitive in (tmin, tmax) (shadow
// rays); else the nearest: *t, *ref, *u, *v of the closest hit.
template <bool AnyHit, bool Moving>
PS_HD bool traverse(const SceneView& scene, const BvhView& bvh, const Ray& ray, float* t_out, uint32_t* ref_out,
                    float* u_out, float* v_out) {
  if (bvh.num_nodes == 0) return false;
  const RayPrep r = prepare(ray);
  const float tmin = ray.tmin;
  float tmax = ray.tmax;
  bool found = false;
  constexpr int32_t kDone = 0x7fffffff;  // below the stack's first entry
  int32_t stack[kBvhStackSize];
  int sp = 0;
  stack[sp++] = kDone;
  int32_t next = 0;  // the root, an inner node
  while (next != kDone) {
    // Inner nodes until the next item is a leaf (or nothing is left).
    while (next >= 0 && next != kDone) {
      const BvhNode& node = bvh.nodes[next];
      float e0, e1;
      const bool h0 = hit_child_box(r, node, 0, tmin, tmax, &e0);
      const bool h1 = hit_child_box(r, node, 1, tmin, tmax, &e1);
      if (h0 && h1) {
        const bool swap = e1 < e0;  // the nearer child first, the other waits on the stack
        next = node.child[swap ? 1 : 0];
        stack[sp++] = node.child[swap ? 0 : 1];
      } else if (h0 || h1) {
        next = node.child[h0 ? 0 : 1];
      } else {
        next = stack[--sp];
      }
    }
    // Leaves until the next item is an inner node.
    while (next < 0) {
      const uint32_t first = bvh_leaf_first(next), end = first + bvh_leaf_count(next);
      for (uint32_t i = first; i < end; ++i) {
        float t, u, v;
        if (!intersect_prim<Moving>(scene, r, bvh.prims[i], tmin, tmax, &t, &u, &v)) continue;
        found = true;
        tmax = t;  // later primitives must be nearer
        *t_out = t;
        *ref_out = bvh.prims[i];
        *u_out = u;
        *v_out = v;
        if (AnyHit) return true;
      }
      next = stack[--sp];
    }
  }
  return found;
}

}  // namespace bvh_detail

// How a tree of view type View is traversed: run<AnyHit, Moving>(scene, view, ray, &t, &ref, &u, &v)
// as bvh_detail::traverse. Specialised per tree (accel/wide_bvh.h has the wide one's).
template <typename View>
struct TreeTraversal;

template <>
struct TreeTraversal<BvhView> {
  template <bool AnyHit, bool Moving>
  PS_HD static bool run(const SceneView& scene, const BvhView& bvh, const Ray& ray, float* t, uint32_t* ref, float* u, float* v) {
    return bvh_detail::traverse<AnyHit, Moving>(scene, bvh, ray, t, ref, u, v);
  }
};

// The Tracer interface (intersect / occluded, as accel/accel.h's Accel) over a tree and the scene
// it indexes.
template <typename View>
struct TreeTracer {
  SceneView scene;
  View bvh;

  // Nearest hit in (ray.tmin, ray.tmax); fills every field of *hit as Accel::intersect does.
  PS_HD bool intersect(const Ray& ray, SurfaceHit* hit) const {
    float t = 0.f, u = 0.f, v = 0.f;
    uint32_t ref = 0;
    using T = TreeTraversal<View>;
    const bool found = scene.positions_end ? T::template run<false, true>(scene, bvh, ray, &t, &ref, &u, &v)
                                           : T::template run<false, false>(scene, bvh, ray, &t, &ref, &u, &v);
    if (!found) return false;
    fill_surface_hit(scene, bvh_ref_kind(ref), bvh_ref_index(ref), t, u, v, ray, hit);
    return true;
  }

  // True when anything blocks (ray.tmin, ray.tmax).
  PS_HD bool occluded(const Ray& ray) const {
    float t = 0.f, u = 0.f, v = 0.f;
    uint32_t ref = 0;
    using T = TreeTraversal<View>;
    return scene.positions_end ? T::template run<true, true>(scene, bvh, ray, &t, &ref, &u, &v)
                               : T::template run<true, false>(scene, bvh, ray, &t, &ref, &u, &v);
  }
};

using BvhTracer = TreeTracer<BvhView>;

}  // namespace pathspace
