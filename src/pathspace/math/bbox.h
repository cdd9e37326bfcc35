// Axis-aligned bounding box and bounding sphere.
#pragma once

#include "pathspace/math/vec3.h"

namespace pathspace {

struct Bounds3 {
  Vec3 lo{kInfinity, kInfinity, kInfinity};
  Vec3 hi{-kInfinity, -kInfinity, -kInfinity};

  PS_HD void expand(const Vec3& p) { lo = min_vec(lo, p); hi = max_vec(hi, p); }
  PS_HD void expand(const Bounds3& b) { lo = min_vec(lo, b.lo); hi = max_vec(hi, b.hi); }
  PS_HD bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  PS_HD Vec3 center() const { return (lo + hi) * 0.5f; }
  PS_HD Vec3 diagonal() const { return hi - lo; }
};

struct BoundingSphere {
  Vec3 center;
  float radius = 0.f;
};

PS_INLINE BoundingSphere bounding_sphere(const Bounds3& b) {
  return {b.center(), 0.5f * length(b.diagonal())};
}

}  // namespace pathspace
