// Isotropic Beckmann microfacet distribution (Walter et al. 2007 eqs. 25-27; Mitsuba's default for
// roughconductor and roughdielectric): normal distribution D, the exact Smith Lambda, and sampling of
// the distribution of visible normals (Heitz & d'Eon 2014, "Importance Sampling Microfacet-Based
// BSDFs using the Distribution of Visible Normals", sec. 4: stretch to alpha = 1, sample the visible
// slopes, unstretch). The visible-slope CDF is inverted by safeguarded Newton iterations on erf, so
// the code is the same on the CPU and the GPU. Microfacet normals m always have m.z > 0.
#pragma once

#include "pathspace/math/vec3.h"
#include "pathspace/sampling/warps.h"

namespace pathspace::microfacet {

inline constexpr float kInvSqrtPi = 0.56418958354775628f;

// D(m) = exp(-tan^2 theta / alpha^2) / (pi alpha^2 cos^4 theta) (Walter 2007 eq. 25).
PS_INLINE float beckmann_d(const Vec3& m, float alpha) {
  if (m.z <= 0.f) return 0.f;
  const float z2 = m.z * m.z;
  const float tan2 = fmaxf(0.f, 1.f - z2) / z2;
  const float a2 = alpha * alpha;
  return expf(-tan2 / a2) / (kPi * a2 * z2 * z2);
}

// Smith Lambda(w) = (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)), a = 1 / (alpha tan theta)
// (Heitz 2014 eq. 72 for Beckmann); depends on |w.z| only.
PS_INLINE float beckmann_lambda(const Vec3& w, float alpha) {
  const float z2 = w.z * w.z;
  if (z2 <= 0.f) return kInfinity;
  const float tan_theta = sqrtf(fmaxf(0.f, 1.f - z2) / z2);
  if (!(tan_theta > 0.f)) return 0.f;
  const float a = 1.f / (alpha * tan_theta);
  if (a > 9.f) return 0.f;  // erf(a) = 1 and exp(-a^2) < 1e-35: below float precision
  return 0.5f * (erff(a) - 1.f) + expf(-a * a) * (0.5f * kInvSqrtPi) / a;
}

namespace detail {

// x with erf(x) = y for y in (-1, 1): Newton's method on erf, kept inside a shrinking bracket.
PS_INLINE float erf_inverse(float y) {
  float lo = -4.f, hi = 4.f, x = 0.f;
  for (int i = 0; i < 40; ++i) {
    const float f = erff(x) - y;
    if (f > 0.f) hi = x;
    else lo = x;
    const float step = f / (2.f * kInvSqrtPi * expf(-x * x));
    float next = x - step;
    if (!(next > lo && next < hi)) next = 0.5f * (lo + hi);  // Newton left the bracket: bisect
    if (fabsf(next - x) <= 1e-6f * fmaxf(1.f, fabsf(x))) return next;
    x = next;
  }
  return x;
}

// A slope x~ along the view's azimuth, for the stretched view at angle theta (alpha = 1), with
// density proportional to max(0, cos theta - x sin theta) exp(-x^2): the visible slopes' marginal.
// Its CDF is C(x) = (cos theta (1 + erf x) + sin theta exp(-x^2) / sqrt(pi)) / 2, increasing up to
// x = cot theta, where it equals cos theta (1 + Lambda) (the normalisation).
PS_INLINE float sample_visible_slope(float cos_theta, float sin_theta, float u) {
  auto cdf = [&](float x) { return 0.5f * (cos_theta * (1.f + erff(x)) + sin_theta * expf(-x * x) * kInvSqrtPi); };
  const float top = sin_theta > 0.f ? fminf(cos_theta / sin_theta, 9.f) : 9.f;
  const float target = u * cdf(top);
  float lo = -9.f, hi = top, x = fminf(0.f, top);
  for (int i = 0; i < 60; ++i) {
    const float f = cdf(x) - target;
    if (f > 0.f) hi = x;
    else lo = x;
    const float slope = fmaxf(0.f, cos_theta - x * sin_theta) * expf(-x * x) * kInvSqrtPi;
    float next = slope > 0.f ? x - f / slope : 0.5f * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5f * (lo + hi);
    if (fabsf(next - x) <= 1e-6f * fmaxf(1.f, fabsf(x))) return next;
    x = next;
  }
  return x;
}

}  // namespace detail

// Sample a normal m visible from w with density D_w(m) = G1(w) max(0, w.m) D(m) / w.z. w below the
// surface (w.z < 0) is treated as -w, as for GGX (microfacet.h).
PS_INLINE Vec3 beckmann_sample_visible_normal(Vec3 w, float alpha, Point2 u) {
  if (w.z < 0.f) w = -w;
  // Stretch the view into the configuration alpha = 1.
  const Vec3 ws = normalize(Vec3(alpha * w.x, alpha * w.y, w.z));
  const float sin_theta = sqrtf(fmaxf(0.f, 1.f - ws.z * ws.z));
  const float cos_phi = sin_theta > 0.f ? ws.x / sin_theta : 1.f, sin_phi = sin_theta > 0.f ? ws.y / sin_theta : 0.f;
  // Visible slopes: x~ from the marginal above, y~ independent with density exp(-y^2) / sqrt(pi).
  const float u1 = fminf(fmaxf(u.x, 1e-7f), 1.f - 1e-7f), u2 = fminf(fmaxf(u.y, 1e-7f), 1.f - 1e-7f);
  const float sx = detail::sample_visible_slope(ws.z, sin_theta, u1);
  const float sy = detail::erf_inverse(2.f * u2 - 1.f);
  // Rotate back to the view's azimuth, unstretch, and turn slopes into a normal.
  const float x = alpha * (cos_phi * sx - sin_phi * sy), y = alpha * (sin_phi * sx + cos_phi * sy);
  return normalize(Vec3(-x, -y, 1.f));
}

}  // namespace pathspace::microfacet
