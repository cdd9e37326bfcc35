// The two primitive kinds: triangles (indexed into a shared vertex array) and exact analytic spheres.
// Both are intersected through Embree (accel/); these records are the device-safe scene data.
#pragma once

#include <cstdint>

#include "pathspace/math/vec3.h"

namespace pathspace {

inline constexpr int32_t kNoLight = -1;

enum class ShapeKind : uint8_t { triangle = 0, sphere = 1 };

struct Triangle {
  uint32_t v[3];
  uint32_t material;
  int32_t light = kNoLight;  // index into the light array when this triangle emits
};

struct Sphere {
  Vec3 center;
  float radius;
  uint32_t material;
  int32_t light = kNoLight;
  // Normals point inwards (for closed "inside of a sphere" scenes with one-sided materials).
  bool inward_normals = false;
};

PS_INLINE Vec3 triangle_normal(const Vec3& p0, const Vec3& p1, const Vec3& p2) { return normalize(cross(p1 - p0, p2 - p0)); }
PS_INLINE float triangle_area(const Vec3& p0, const Vec3& p1, const Vec3& p2) { return 0.5f * length(cross(p1 - p0, p2 - p0)); }

PS_INLINE Vec3 sphere_normal(const Sphere& s, const Vec3& p) {
  const Vec3 n = (p - s.center) / s.radius;
  return s.inward_normals ? -n : n;
}

// Robust ray-sphere intersection (Haines et al., Ray Tracing Gems ch. 7): the discriminant is
// computed from the distance of the centre to the ray line, which keeps precision for small spheres
// far away. Returns the nearest t in (tmin, tmax), or false.
PS_INLINE bool intersect_sphere(const Sphere& s, const Vec3& o, const Vec3& d, float tmin, float tmax, float* t_hit) {
  const Vec3 f = o - s.center;
  const float a = dot(d, d);
  const float b = -dot(f, d);
  const Vec3 l = f + d * (b / a);
  const float disc = a * (s.radius * s.radius - dot(l, l));
  if (disc < 0.f) return false;
  const float sq = sqrtf(disc);
  const float c = dot(f, f) - s.radius * s.radius;
  const float q = b + copysignf(sq, b);
  float t0 = c / q, t1 = q / a;
  if (q == 0.f) t0 = t1 = b / a;
  if (t0 > t1) {
    const float tmp = t0;
    t0 = t1;
    t1 = tmp;
  }
  if (t0 > tmin && t0 < tmax) {
    *t_hit = t0;
    return true;
  }
  if (t1 > tmin && t1 < tmax) {
    *t_hit = t1;
    return true;
  }
  return false;
}

}  // namespace pathspace
