// Ray with a parametric interval [tmin, tmax]. Directions are unit length unless stated.
#pragma once

#include "pathspace/math/vec3.h"

namespace pathspace {

struct Ray {
  Vec3 o;
  Vec3 d;
  float tmin = 0.f;
  float tmax = kInfinity;

  PS_HD Vec3 at(float t) const { return o + d * t; }
};

// Rays leaving a surface start at the point pushed off the surface along the geometric normal, to
// the side the ray travels to (for refraction: the far side). Offsetting along the normal rather than
// along the ray (SmallVCM's tmin = 1e-3, cornell-variants.md §6) keeps origins near an edge inside
// a closed room: an along-ray offset can jump over the adjacent wall and leak light.
PS_INLINE Vec3 offset_origin(const Vec3& p, const Vec3& ng, const Vec3& d, float epsilon) {
  return p + (dot(d, ng) >= 0.f ? ng : -ng) * epsilon;
}

PS_INLINE Ray spawn_ray(const Vec3& p, const Vec3& ng, const Vec3& d, float epsilon) {
  return {offset_origin(p, ng, d, epsilon), d, 0.f, kInfinity};
}

// Shadow ray from surface point p (geometric normal ng) along unit direction d to a point at
// distance dist (infinite for lights at infinity); the last epsilon is excluded so the light's own
// surface does not occlude.
PS_INLINE Ray spawn_shadow_ray(const Vec3& p, const Vec3& ng, const Vec3& d, float dist, float epsilon) {
  return {offset_origin(p, ng, d, epsilon), d, 0.f, isinf(dist) ? kInfinity : dist - 2.f * epsilon};
}

}  // namespace pathspace
