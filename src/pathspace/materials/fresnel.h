// Exact unpolarised Fresnel reflectance for dielectrics and conductors.
#pragma once

#include "pathspace/math/rgb.h"
#include "pathspace/math/vec3.h"

namespace pathspace {

// Dielectric Fresnel F = (r_par^2 + r_perp^2) / 2. cos_i is the cosine on the incident side
// (sign tells the side: > 0 outside), eta = n_inside / n_outside. Writes cos_t (>= 0) and returns
// 1 for total internal reflection.
PS_INLINE float fresnel_dielectric(float cos_i, float eta, float* cos_t_out = nullptr) {
  if (cos_i < 0.f) {
    eta = 1.f / eta;
    cos_i = -cos_i;
  }
  const float sin2_t = (1.f - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.f) {
    if (cos_t_out) *cos_t_out = 0.f;
    return 1.f;
  }
  const float cos_t = sqrtf(1.f - sin2_t);
  const float r_par = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  const float r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  if (cos_t_out) *cos_t_out = cos_t;
  return 0.5f * (r_par * r_par + r_perp * r_perp);
}

// Conductor Fresnel for complex IOR eta + i k (per channel), exact unpolarised form.
PS_INLINE float fresnel_conductor_channel(float cos_i, float eta, float k) {
  cos_i = clamp_to(cos_i, 0.f, 1.f);
  const float cos2 = cos_i * cos_i, sin2 = 1.f - cos2;
  const float t0 = eta * eta - k * k - sin2;
  const float a2b2 = sqrtf(fmaxf(t0 * t0 + 4.f * eta * eta * k * k, 0.f));
  const float a = sqrtf(fmaxf(0.5f * (a2b2 + t0), 0.f));
  const float t1 = a2b2 + cos2;
  const float t2 = 2.f * cos_i * a;
  const float rs = (t1 - t2) / (t1 + t2);
  const float t3 = cos2 * a2b2 + sin2 * sin2;
  const float t4 = t2 * sin2;
  const float rp = rs * (t3 - t4) / (t3 + t4);
  return 0.5f * (rp + rs);
}
PS_INLINE Rgb fresnel_conductor(float cos_i, const Rgb& eta, const Rgb& k) {
  return {fresnel_conductor_channel(cos_i, eta.r, k.r), fresnel_conductor_channel(cos_i, eta.g, k.g),
          fresnel_conductor_channel(cos_i, eta.b, k.b)};
}

// The cosine-weighted hemispherical average of the Fresnel reflectance seen from inside a medium of
// relative index eta, total internal reflection included (Mitsuba's fresnel_diffuse_reflectance(1 /
// eta)), by the midpoint rule in mu = cos theta. Host code: scene loading and tests.
inline double internal_diffuse_fresnel(float eta, int steps = 4096) {
  double sum = 0;
  for (int i = 0; i < steps; ++i) {
    const double mu = (i + 0.5) / steps;
    sum += double(fresnel_dielectric(-float(mu), eta)) * 2.0 * mu / steps;
  }
  return sum;
}

// Refract wi (local, pointing away from the surface) through the interface with normal +z.
// eta = n_inside / n_outside. Returns false on total internal reflection.
PS_INLINE bool refract_local(const Vec3& wi, float eta, Vec3* wt) {
  float cos_i = wi.z;
  float e = eta;
  float sign = 1.f;
  if (cos_i < 0.f) {
    e = 1.f / eta;
    cos_i = -cos_i;
    sign = -1.f;
  }
  const float sin2_t = (1.f - cos_i * cos_i) / (e * e);
  if (sin2_t >= 1.f) return false;
  const float cos_t = sqrtf(1.f - sin2_t);
  *wt = Vec3(-wi.x / e, -wi.y / e, -sign * cos_t);
  return true;
}

}  // namespace pathspace
