// Texture coordinates and shading normals at a hit: barycentric interpolation of per-vertex uvs and
// normals on triangles (Embree reports the barycentrics), the spherical (u, v) of pbrt on spheres.
// Raw pointers so that a device tracer can fill hits the same way the Embree backend does.
#pragma once

#include "pathspace/geometry/shapes.h"
#include "pathspace/math/scalar.h"
#include "pathspace/sampling/warps.h"

namespace pathspace {

// uv at barycentrics (b1, b2) of vertices 1 and 2. Without vertex uvs: pbrt's default
// parameterisation (0,0), (1,0), (1,1).
PS_INLINE Point2 triangle_uv(const Triangle& tri, const Point2* uvs, float b1, float b2) {
  if (!uvs) return {b1 + b2, b2};
  const float b0 = 1.f - b1 - b2;
  const Point2 &a = uvs[tri.v[0]], &b = uvs[tri.v[1]], &c = uvs[tri.v[2]];
  return {a.x * b0 + b.x * b1 + c.x * b2, a.y * b0 + b.y * b1 + c.y * b2};
}

// Interpolated vertex normal turned to the side of ng (ng decides which side is the front of a
// one-sided material; loaders already orient faces by their normals). Zero normals (meshes without
// normals, padded by Scene::finalize) give ng.
PS_INLINE Vec3 triangle_shading_normal(const Triangle& tri, const Vec3* normals, float b1, float b2, const Vec3& ng) {
  if (!normals) return ng;
  const float b0 = 1.f - b1 - b2;
  const Vec3 n = normals[tri.v[0]] * b0 + normals[tri.v[1]] * b1 + normals[tri.v[2]] * b2;
  const float len2 = dot(n, n);
  if (!(len2 > 1e-12f) || !(len2 < kInfinity)) return ng;
  const Vec3 ns = n * (1.f / sqrtf(len2));
  return dot(ns, ng) < 0.f ? -ns : ns;
}

// pbrt's sphere parameterisation about the world z axis: u = phi / 2 pi, v = 0 at the -z pole and
// 1 at the +z pole.
PS_INLINE Point2 sphere_uv(const Sphere& s, const Vec3& p) {
  const Vec3 d = (p - s.center) / s.radius;
  float phi = atan2f(d.y, d.x);
  if (phi < 0.f) phi += kTwoPi;
  const float theta = acosf(clamp_to(d.z, -1.f, 1.f));
  return {phi * (1.f / kTwoPi), 1.f - theta * kInvPi};
}

}  // namespace pathspace
