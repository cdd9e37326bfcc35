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

// Ray leaving a surface point. pathspace offsets along the ray by tmin = epsilon (the Cornell
// scenes' convention, cornell-variants.md §6); epsilon scales with the scene (Scene::ray_epsilon).
PS_INLINE Ray spawn_ray(const Vec3& p, const Vec3& d, float epsilon) { return {p, d, epsilon, kInfinity}; }

// Shadow ray from p to q, excluding epsilon at both ends.
PS_INLINE Ray spawn_ray_to(const Vec3& p, const Vec3& q, float epsilon, float* dist) {
  const Vec3 v = q - p;
  const float d = length(v);
  *dist = d;
  return {p, v / d, epsilon, d - epsilon};
}

}  // namespace pathspace
