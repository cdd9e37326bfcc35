// A SurfaceHit from what a traversal reports (kind, primitive, t and the barycentrics of vertices 1
// and 2): the one place that computes hit points, normals, uvs and shading normals, shared by the
// Embree backend (embree_accel.cpp) and the device-safe BVH tracer (bvh_tracer.h), so both fill
// hits identically. Reads only the geometry of the SceneView (positions, uvs, normals, triangles,
// spheres) and num_textures (uvs are computed only in textured scenes: atan2/acos on spheres).
#pragma once

#include <cstdint>

#include "pathspace/geometry/interaction.h"
#include "pathspace/geometry/ray.h"
#include "pathspace/geometry/surface_attributes.h"
#include "pathspace/scene/motion.h"
#include "pathspace/scene/scene_view.h"

namespace pathspace {

// Triangle `prim` hit at barycentrics (u, v) of vertices 1 and 2 (Embree's convention), at `time`
// (scene/motion.h: the vertices and normals of a moving scene at that instant).
PS_INLINE void fill_triangle_hit(const SceneView& scene, uint32_t prim, float t, float u, float v, float time,
                                 SurfaceHit* hit) {
  const Triangle& tri = scene.triangles[prim];
  const TriangleVertices tv = triangle_at(scene, tri, time);
  const Vec3 &p0 = tv.p0, &p1 = tv.p1, &p2 = tv.p2;
  hit->t = t;
  hit->prim = prim;
  hit->p = p0 * (1.f - u - v) + p1 * u + p2 * v;  // barycentric: more precise than o + t d
  hit->ng = triangle_normal(p0, p1, p2);
  hit->u = u;
  hit->v = v;
  hit->uv = scene.num_textures > 0 ? triangle_uv(tri, scene.uvs, u, v) : Point2{};
  hit->ns = triangle_shading_normal(tri, scene.normals, u, v, hit->ng);
  if (scene.normals_end && time > 0.f) {
    const Vec3 ns_end = triangle_shading_normal(tri, scene.normals_end, u, v, hit->ng);
    const Vec3 n = hit->ns * (1.f - time) + ns_end * time;
    if (length_squared(n) > 1e-12f) hit->ns = normalize(n);
  }
  hit->kind = ShapeKind::triangle;
  hit->material = tri.material;
  hit->light = tri.light;
  hit->time = time;
}

// Sphere `prim` hit by `ray` at t.
PS_INLINE void fill_sphere_hit(const SceneView& scene, uint32_t prim, float t, const Ray& ray, SurfaceHit* hit) {
  const Sphere& s = scene.spheres[prim];
  const Vec3 radial = normalize(ray.at(t) - s.center);
  hit->t = t;
  hit->prim = prim;
  hit->p = s.center + radial * s.radius;  // re-project onto the surface
  hit->ng = s.inward_normals ? -radial : radial;
  hit->u = hit->v = 0.f;
  hit->uv = scene.num_textures > 0 ? sphere_uv(s, hit->p) : Point2{};
  hit->ns = hit->ng;
  hit->kind = ShapeKind::sphere;
  hit->material = s.material;
  hit->light = s.light;
  hit->time = ray.time;
}

PS_INLINE void fill_surface_hit(const SceneView& scene, ShapeKind kind, uint32_t prim, float t, float u, float v,
                                const Ray& ray, SurfaceHit* hit) {
  if (kind == ShapeKind::triangle)
    fill_triangle_hit(scene, prim, t, u, v, ray.time, hit);
  else
    fill_sphere_hit(scene, prim, t, ray, hit);
}

}  // namespace pathspace
