// 3-vectors of float for points, directions and normals (world units; see docs/conventions.md).
#pragma once

#include "pathspace/math/scalar.h"

namespace pathspace {

struct Vec3 {
  float x = 0.f, y = 0.f, z = 0.f;

  constexpr Vec3() = default;
  PS_HD constexpr Vec3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
  PS_HD constexpr explicit Vec3(float s) : x(s), y(s), z(s) {}

  PS_HD float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  PS_HD float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

  PS_HD Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
  PS_HD Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
  PS_HD Vec3& operator*=(float s) { x *= s; y *= s; z *= s; return *this; }
  PS_HD Vec3& operator/=(float s) { return *this *= 1.f / s; }
};

PS_INLINE Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
PS_INLINE Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
PS_INLINE Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
PS_INLINE Vec3 operator*(const Vec3& a, float s) { return {a.x * s, a.y * s, a.z * s}; }
PS_INLINE Vec3 operator*(float s, const Vec3& a) { return a * s; }
PS_INLINE Vec3 operator/(const Vec3& a, float s) { return a * (1.f / s); }
PS_INLINE Vec3 mul(const Vec3& a, const Vec3& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
PS_INLINE bool operator==(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

PS_INLINE float dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
PS_INLINE float abs_dot(const Vec3& a, const Vec3& b) { return fabsf(dot(a, b)); }
PS_INLINE Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
PS_INLINE float length_squared(const Vec3& a) { return dot(a, a); }
PS_INLINE float length(const Vec3& a) { return sqrtf(dot(a, a)); }
PS_INLINE Vec3 normalize(const Vec3& a) { return a / length(a); }
PS_INLINE float distance(const Vec3& a, const Vec3& b) { return length(a - b); }
PS_INLINE float distance_squared(const Vec3& a, const Vec3& b) { return length_squared(a - b); }
PS_INLINE Vec3 min_vec(const Vec3& a, const Vec3& b) { return {fminf(a.x, b.x), fminf(a.y, b.y), fminf(a.z, b.z)}; }
PS_INLINE Vec3 max_vec(const Vec3& a, const Vec3& b) { return {fmaxf(a.x, b.x), fmaxf(a.y, b.y), fmaxf(a.z, b.z)}; }
PS_INLINE float max_component(const Vec3& a) { return fmaxf(a.x, fmaxf(a.y, a.z)); }
PS_INLINE bool all_finite(const Vec3& a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }
// Mirror direction w about normal n (both point away from the surface).
PS_INLINE Vec3 reflect(const Vec3& w, const Vec3& n) { return 2.f * dot(w, n) * n - w; }
// Flip n into the hemisphere of v.
PS_INLINE Vec3 face_forward(const Vec3& n, const Vec3& v) { return dot(n, v) < 0.f ? -n : n; }

}  // namespace pathspace
