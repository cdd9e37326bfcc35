// Warps from the unit square to common domains, their densities and their inverses.
// Inverses let tests check round trips and let later integrators (BPT) reuse random numbers.
#pragma once

#include "pathspace/math/vec3.h"

namespace pathspace {

struct Point2 {
  float x = 0.f, y = 0.f;
};

// Shirley–Chiu concentric map, square [0,1)^2 -> unit disk (area preserving).
PS_INLINE Point2 square_to_disk_concentric(Point2 u) {
  const float a = 2.f * u.x - 1.f, b = 2.f * u.y - 1.f;
  if (a == 0.f && b == 0.f) return {0.f, 0.f};
  float r, phi;
  if (fabsf(a) > fabsf(b)) {
    r = a;
    phi = (kPi / 4.f) * (b / a);
  } else {
    r = b;
    phi = (kPi / 2.f) - (kPi / 4.f) * (a / b);
  }
  return {r * cosf(phi), r * sinf(phi)};
}
PS_INLINE Point2 disk_concentric_to_square(Point2 p) {
  const float r = sqrtf(p.x * p.x + p.y * p.y);
  float phi = atan2f(p.y, p.x);
  if (phi < -kPi / 4.f) phi += kTwoPi;  // into [-pi/4, 7pi/4)
  float a, b;
  if (phi < kPi / 4.f) {
    a = r;
    b = phi * a / (kPi / 4.f);
  } else if (phi < 3.f * kPi / 4.f) {
    b = r;
    a = -(phi - kPi / 2.f) * b / (kPi / 4.f);
  } else if (phi < 5.f * kPi / 4.f) {
    a = -r;
    b = (phi - kPi) * a / (kPi / 4.f);
  } else {
    b = -r;
    a = -(phi - 3.f * kPi / 2.f) * b / (kPi / 4.f);
  }
  return {0.5f * (a + 1.f), 0.5f * (b + 1.f)};
}

// Cosine-weighted hemisphere around +z (Malley's method). pdf = cos(theta) / pi.
PS_INLINE Vec3 square_to_cosine_hemisphere(Point2 u) {
  const Point2 d = square_to_disk_concentric(u);
  const float z = safe_sqrt(1.f - d.x * d.x - d.y * d.y);
  return {d.x, d.y, z};
}
PS_INLINE float cosine_hemisphere_pdf(const Vec3& w) { return w.z > 0.f ? w.z * kInvPi : 0.f; }
PS_INLINE Point2 cosine_hemisphere_to_square(const Vec3& w) { return disk_concentric_to_square({w.x, w.y}); }

// Uniform sphere. pdf = 1 / (4 pi).
PS_INLINE Vec3 square_to_uniform_sphere(Point2 u) {
  const float z = 1.f - 2.f * u.x;
  const float r = safe_sqrt(1.f - z * z);
  const float phi = kTwoPi * u.y;
  return {r * cosf(phi), r * sinf(phi), z};
}
PS_INLINE float uniform_sphere_pdf() { return kInvFourPi; }
PS_INLINE Point2 uniform_sphere_to_square(const Vec3& w) {
  float phi = atan2f(w.y, w.x);
  if (phi < 0.f) phi += kTwoPi;
  return {(1.f - w.z) * 0.5f, phi * kInvTwoPi};
}

// Uniform hemisphere around +z. pdf = 1 / (2 pi).
PS_INLINE Vec3 square_to_uniform_hemisphere(Point2 u) {
  const float z = u.x;
  const float r = safe_sqrt(1.f - z * z);
  const float phi = kTwoPi * u.y;
  return {r * cosf(phi), r * sinf(phi), z};
}
PS_INLINE float uniform_hemisphere_pdf() { return kInvTwoPi; }
PS_INLINE Point2 uniform_hemisphere_to_square(const Vec3& w) {
  float phi = atan2f(w.y, w.x);
  if (phi < 0.f) phi += kTwoPi;
  return {w.z, phi * kInvTwoPi};
}

// Uniform cone around +z with cos(theta) >= cos_max. pdf = 1 / (2 pi (1 - cos_max)).
PS_INLINE Vec3 square_to_uniform_cone(Point2 u, float cos_max) {
  const float z = 1.f - u.x * (1.f - cos_max);
  const float r = safe_sqrt(1.f - z * z);
  const float phi = kTwoPi * u.y;
  return {r * cosf(phi), r * sinf(phi), z};
}
PS_INLINE float uniform_cone_pdf(float cos_max) { return 1.f / (kTwoPi * (1.f - cos_max)); }
PS_INLINE Point2 uniform_cone_to_square(const Vec3& w, float cos_max) {
  float phi = atan2f(w.y, w.x);
  if (phi < 0.f) phi += kTwoPi;
  return {(1.f - w.z) / (1.f - cos_max), phi * kInvTwoPi};
}

// Power-cosine lobe around +z: pdf = (n + 1) / (2 pi) cos^n(theta) (Phong sampling).
PS_INLINE Vec3 square_to_power_cosine(Point2 u, float n) {
  const float z = powf(u.x, 1.f / (n + 1.f));
  const float r = safe_sqrt(1.f - z * z);
  const float phi = kTwoPi * u.y;
  return {r * cosf(phi), r * sinf(phi), z};
}
PS_INLINE float power_cosine_pdf(const Vec3& w, float n) {
  return w.z > 0.f ? (n + 1.f) * kInvTwoPi * powf(w.z, n) : 0.f;
}
PS_INLINE Point2 power_cosine_to_square(const Vec3& w, float n) {
  float phi = atan2f(w.y, w.x);
  if (phi < 0.f) phi += kTwoPi;
  return {powf(w.z, n + 1.f), phi * kInvTwoPi};
}

// Uniform barycentrics on a triangle (b0, b1); b2 = 1 - b0 - b1. pdf = 1 / area.
// Square-root parametrisation (Osada et al. 2002), invertible.
PS_INLINE Point2 square_to_triangle_barycentric(Point2 u) {
  const float su = sqrtf(u.x);
  return {1.f - su, u.y * su};
}
PS_INLINE Point2 triangle_barycentric_to_square(Point2 b) {
  const float su = 1.f - b.x;
  return {su * su, su > 0.f ? b.y / su : 0.f};
}

}  // namespace pathspace
