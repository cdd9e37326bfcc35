// Orthonormal shading frame with z = normal (docs/conventions.md, "Shading frame").
// Basis construction: Duff et al., "Building an Orthonormal Basis, Revisited" (JCGT 2017).
#pragma once

#include "pathspace/math/vec3.h"

namespace pathspace {

struct Frame {
  Vec3 s, t, n;

  PS_HD Frame() : s(1, 0, 0), t(0, 1, 0), n(0, 0, 1) {}
  // The normal's components are read once into scalars: computing from the member n made GCC copy
  // the normal through the stack in 8 + 4 byte stores and read it back with an 8-byte load across
  // both, a failed store-to-load forward (18% of pt_on_hit's samples; 1-1.5% of PT and BPT).
  PS_HD explicit Frame(const Vec3& normal) {
    const float x = normal.x, y = normal.y, z = normal.z;
    const float sign = copysignf(1.f, z);
    const float a = -1.f / (sign + z);
    const float b = x * y * a;
    s = Vec3(1.f + sign * x * x * a, sign * b, -sign * x);
    t = Vec3(b, sign + y * y * a, -y);
    n = Vec3(x, y, z);
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
