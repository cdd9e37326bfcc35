// Ray with a parametric interval [tmin, tmax]. Directions are unit length unless stated.
#pragma once

#include "pathspace/math/vec3.h"

namespace pathspace {

struct Ray {
  Vec3 o;
  Vec3 d;
  float tmin = 0.f;
  float tmax = kInfinity;
  // The ray's instant in the shutter interval [0, 1) of a scene that moves (motion blur,
  // scene/motion.h): every ray of a path has its path's time. Always 0 in still scenes.
  float time = 0.f;

  PS_HD Vec3 at(float t) const { return o + d * t; }
};

// Rays leaving a surface start at the point pushed off the surface along the geometric normal, to
// the side the ray travels to (for refraction: the far side). Offsetting along the normal rather than
// along the ray (SmallVCM's tmin = 1e-3, docs/scenes.md §6) keeps origins near an edge inside
// a closed room: an along-ray offset can jump over the adjacent wall and leak light.
PS_INLINE Vec3 offset_origin(const Vec3& p, const Vec3& ng, const Vec3& d, float epsilon) {
  return p + (dot(d, ng) >= 0.f ? ng : -ng) * epsilon;
}

PS_INLINE Ray spawn_ray(const Vec3& p, const Vec3& ng, const Vec3& d, float epsilon, float time) {
  return {offset_origin(p, ng, d, epsilon), d, 0.f, kInfinity, time};
}

// Shadow ray from surface point p (geometric normal ng) along unit direction d to the point at
// distance dist (infinite for lights at infinity). The origin is pushed off the surface as for
// spawn_ray, and the ray is re-aimed from there at the target: the push shortens the way to the
// target by up to epsilon / |cos| (parallel surfaces, e.g. a ceiling and an upward-facing lamp seen
// at a grazing angle), so a fixed `dist - 2 epsilon` overshot into the target's own surface and
// the target occluded itself (veach-bidir's ceiling lost 3/4 of its direct light). The last epsilon
// before the target is excluded.
PS_INLINE Ray spawn_shadow_ray(const Vec3& p, const Vec3& ng, const Vec3& d, float dist, float epsilon, float time) {
  const Vec3 o = offset_origin(p, ng, d, epsilon);
  if (isinf(dist)) return {o, d, 0.f, kInfinity, time};
  const Vec3 to_target = p + d * dist - o;
  const float len = length(to_target);
  if (!(len > epsilon)) return {o, d, 0.f, 0.f, time};  // target within epsilon: nothing can occlude
  return {o, to_target / len, 0.f, len - epsilon, time};
}

}  // namespace pathspace
