// Orthonormal shading frame with z = normal (docs/conventions.md: "Shading frame: z = normal").
// Basis construction: Duff et al., "Building an Orthonormal Basis, Revisited" (JCGT 2017).
#pragma once

#include "pathspace/math/vec3.h"

namespace pathspace {

struct Frame {
  Vec3 s, t, n;

  PS_HD Frame() : s(1, 0, 0), t(0, 1, 0), n(0, 0, 1) {}
  PS_HD explicit Frame(const Vec3& normal) : n(normal) {
    const float sign = copysignf(1.f, n.z);
    const float a = -1.f / (sign + n.z);
    const float b = n.x * n.y * a;
    s = Vec3(1.f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    t = Vec3(b, sign + n.y * n.y * a, -n.y);
  }
  PS_HD Frame(const Vec3& s_, const Vec3& t_, const Vec3& n_) : s(s_), t(t_), n(n_) {}

  PS_HD Vec3 to_local(const Vec3& v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
  PS_HD Vec3 to_world(const Vec3& v) const { return s * v.x + t * v.y + n * v.z; }
};

// Local-frame trigonometry (z = normal).
PS_INLINE float cos_theta(const Vec3& w) { return w.z; }
PS_INLINE float abs_cos_theta(const Vec3& w) { return fabsf(w.z); }
PS_INLINE bool same_hemisphere(const Vec3& a, const Vec3& b) { return a.z * b.z > 0.f; }

}  // namespace pathspace
