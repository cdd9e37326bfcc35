// Isotropic GGX (Trowbridge–Reitz) microfacet distribution shared by the rough conductor and the
// rough dielectric: normal distribution D, Smith masking G1 and height-correlated masking-shadowing
// G2 (Heitz 2014, "Understanding the Masking-Shadowing Function", eqs. 72, 86, 99), and sampling of
// the distribution of visible normals (Heitz 2018, "Sampling the GGX Distribution of Visible
// Normals", JCGT 7(4), listing 1 and eq. 3). Microfacet normals m always have m.z > 0.
#pragma once

#include "pathspace/math/vec3.h"
#include "pathspace/sampling/warps.h"

namespace pathspace::microfacet {

// Smaller roughness is clamped: below it D overflows float precision near the peak and the lobe is
// indistinguishable from a delta lobe anyway (use the standard material's mirror/glass for those).
inline constexpr float kMinAlpha = 1e-3f;
PS_INLINE float clamp_alpha(float alpha) { return fmaxf(alpha, kMinAlpha); }

// D(m) = alpha^2 / (pi (m.z^2 (alpha^2 - 1) + 1)^2), the GGX normal distribution (Walter 2007 eq. 33).
PS_INLINE float ggx_d(const Vec3& m, float alpha) {
  if (m.z <= 0.f) return 0.f;
  const float a2 = alpha * alpha;
  const float t = m.z * m.z * (a2 - 1.f) + 1.f;
  return a2 / (kPi * t * t);
}

// Smith Lambda(w) = (sqrt(1 + alpha^2 tan^2 theta) - 1) / 2 (Heitz 2014 eq. 86); depends on |w.z| only.
PS_INLINE float ggx_lambda(const Vec3& w, float alpha) {
  const float z2 = w.z * w.z;
  if (z2 <= 0.f) return kInfinity;
  const float a2_tan2 = alpha * alpha * fmaxf(0.f, 1.f - z2) / z2;
  return 0.5f * (sqrtf(1.f + a2_tan2) - 1.f);
}

// Smith masking G1(w) = 1 / (1 + Lambda(w)) (Heitz 2014 eq. 43), ignoring the sidedness test, which
// the callers do against the microfacet normal.
PS_INLINE float ggx_g1(const Vec3& w, float alpha) { return 1.f / (1.f + ggx_lambda(w, alpha)); }

// Height-correlated masking-shadowing G2 = 1 / (1 + Lambda(wo) + Lambda(wi)) (Heitz 2014 eq. 99).
// Used for reflection and for transmission (wo and wi on opposite sides) alike.
PS_INLINE float ggx_g2(const Vec3& wo, const Vec3& wi, float alpha) {
  return 1.f / (1.f + ggx_lambda(wo, alpha) + ggx_lambda(wi, alpha));
}

// Sample a normal m visible from w with density D_w(m) (Heitz 2018 §2 and listing 1). w below the
// surface (w.z < 0, a view from inside a dielectric) is treated as -w: the returned normal then
// faces w from below, i.e. dot(w, m) < 0.
PS_INLINE Vec3 ggx_sample_visible_normal(Vec3 w, float alpha, Point2 u) {
  if (w.z < 0.f) w = -w;
  // Stretch the view into the hemisphere configuration (alpha = 1).
  const Vec3 vh = normalize(Vec3(alpha * w.x, alpha * w.y, w.z));
  // Orthonormal basis around vh (listing 1, section 4.1).
  const float len2 = vh.x * vh.x + vh.y * vh.y;
  const Vec3 t1 = len2 > 0.f ? Vec3(-vh.y, vh.x, 0.f) / sqrtf(len2) : Vec3(1.f, 0.f, 0.f);
  const Vec3 t2 = cross(vh, t1);
  // Uniform point on the disk, then warp its upper half to the projected visible hemisphere (4.2).
  const float r = sqrtf(u.x), phi = kTwoPi * u.y;
  const float p1 = r * cosf(phi);
  float p2 = r * sinf(phi);
  const float s = 0.5f * (1.f + vh.z);
  p2 = (1.f - s) * safe_sqrt(1.f - p1 * p1) + s * p2;
  // Reproject onto the hemisphere (4.3) and unstretch (4.4).
  const Vec3 nh = t1 * p1 + t2 * p2 + vh * safe_sqrt(1.f - p1 * p1 - p2 * p2);
  return normalize(Vec3(alpha * nh.x, alpha * nh.y, fmaxf(1e-7f, nh.z)));
}

// D_w(m) = G1(w) max(0, w.m) D(m) / w.z (Heitz 2018 eq. 3), with w mirrored to w.z > 0 as above.
PS_INLINE float ggx_visible_normal_pdf(Vec3 w, const Vec3& m, float alpha) {
  if (w.z < 0.f) w = -w;
  const float wm = dot(w, m);
  if (wm <= 0.f || w.z <= 0.f) return 0.f;
  return ggx_g1(w, alpha) * wm * ggx_d(m, alpha) / w.z;
}

}  // namespace pathspace::microfacet
